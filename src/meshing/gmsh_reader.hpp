#pragma once
// Meshes from a user's file: a .geo meshed by gmsh (2-D), a ready .msh, a CAD file (STEP, IGES,
// BREP) meshed by gmsh's OpenCASCADE kernel, an STL or another code's mesh
// (meshing/mesh_import.hpp), read into plain data (GmshModel), from which part meshes and node
// groups are taken by physical group name (meshing/part_extraction.hpp).
//
// gmsh never runs in this process: it reads and meshes the file in a sandboxed child
// (meshing/sandbox.hpp, meshing/gmsh_job.hpp) that cannot start programs, read outside the file's
// folder or write outside a scratch folder, under memory, CPU and wall-time limits; the child
// writes the mesh as MSH 4.1, which this process reads without gmsh (meshing/msh_file.hpp).
// docs/security.md.
#include <filesystem>
#include <span>

#include "meshing/geo_parameter.hpp"
#include "meshing/gmsh_model.hpp"
#include "meshing/mesh_import.hpp"
#include "meshing/mesh_limits.hpp"
#include "meshing/part_extraction.hpp"

namespace sf {

/// Meshes a .geo or CAD file, or reads a .msh, STL or other mesh file, with gmsh in the sandbox.
///
/// element_size (mm) > 0, for a .geo: sets gmsh's option Mesh.MeshSizeMax to it and
/// Mesh.MeshSizeFromPoints to 0, both before the file is read (so a .geo can use the value, e.g.
/// `If (Mesh.MeshSizeMax < 1e21) h = Mesh.MeshSizeMax; EndIf` for transfinite counts) and again
/// after (so it overrides sizes the file sets). Curvature refinement and size fields the file asks
/// for still refine below it. 0 keeps the file's own sizes. Ignored for a .msh file.
/// recombine = true (a .geo or CAD file) makes quadrilaterals wherever gmsh can.
///
/// parameters (a .geo only): numbers set before the file is parsed, each a variable the file
/// declares with DefineConstant[ name = default ] (meshing/geo_parameters.hpp); GeoParameterError
/// for a parameter the file does not define or overrides.
///
/// import (CAD, STL, other codes' meshes): a CAD file is read by OpenCASCADE (a STEP file's unit
/// converted to mm, IGES faces sewn), scaled by import.scale and meshed like a .geo (element_size
/// > 0 required; import.curvature_elements and import.chord_error refine curved faces); an STL
/// file's triangles are taken as they are. Either has no physical groups: its surfaces
/// (import.surfaces, or all) become the group import.group. A .msh or STL file's coordinates are
/// multiplied by import.scale.
///
/// limits: a .geo or CAD file whose element_size asks for more than limits.max_elements
/// (estimated before meshing) is refused; the time and memory gmsh may take (MeshLimits).
///
/// Throws InputError naming the file for: a missing file, an unknown extension, a negative size,
/// a .geo statement that runs a command (meshing/geo_safety.hpp), a CAD or STL file that is not
/// whole (meshing/file_completeness.hpp), gmsh's parse and meshing errors (with gmsh's message), a
/// crash of gmsh or OpenCASCADE, a call the sandbox refuses (starting a program), a limit
/// reached, an empty mesh, a model without physical groups, parameters for a file that is not a
/// .geo. gmsh's terminal output is shown only at Verbosity::verbose.
GmshModel load_gmsh_model(const std::filesystem::path& file, double element_size, bool recombine,
                          std::span<const GeoParameter> parameters = {},
                          const MeshImportOptions& import = {}, const MeshLimits& limits = {});

/// Meshes `geo_file` exactly as load_gmsh_model does (a .msh file is read as it is) and writes the
/// mesh to `msh_out` in gmsh's ASCII format 4.1, so a case folder can keep the mesh its .geo made.
/// Only elements of physical groups are written. InputError as load_gmsh_model, or if the output
/// cannot be written.
void write_msh(const std::filesystem::path& geo_file, double element_size, bool recombine,
               const std::filesystem::path& msh_out, std::span<const GeoParameter> parameters = {},
               const MeshLimits& limits = {});

}  // namespace sf
