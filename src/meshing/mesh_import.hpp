#pragma once
// The mesh file formats a part can come from, and what each needs around gmsh's reading: CAD
// surfaces (STEP, IGES, BREP: read by gmsh's OpenCASCADE kernel and meshed as triangles, or quads
// for a blank), STL triangles, and the meshes of other codes that gmsh 4.8 reads (Nastran bulk
// data, I-DEAS UNV, legacy VTK), taken as they are, besides the .geo and .msh of gmsh_reader.
// A file without part names has its surfaces (all of them, or those listed: a Nastran file's
// property ids, a UNV file's physical property numbers) made into one physical group named as
// the case asks; a UNV file's named groups (dataset 2477) are kept.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sf {

enum class MeshFormat {
  geo,      ///< gmsh script, meshed in 2-D
  msh,      ///< gmsh mesh, read as it is
  step,     ///< .step, .stp: CAD, meshed; length unit from the file (converted to mm)
  iges,     ///< .iges, .igs: CAD, meshed; faces sewn; the file's length unit is not converted
  brep,     ///< .brep: OpenCASCADE's own CAD format, meshed; no length unit (taken as mm)
  stl,      ///< .stl (ASCII or binary): triangles read as they are
  nastran,  ///< .bdf, .nas: Nastran bulk data (GRID, CTRIA3, CQUAD4); surfaces = property ids
  unv,      ///< .unv: I-DEAS universal file (2411, 2412, 2477 groups)
  vtk,      ///< .vtk: legacy VTK unstructured grid or polydata (one surface)
};

/// The format of `file` from its extension (case-insensitive); InputError naming the file and
/// listing the accepted extensions for any other.
MeshFormat mesh_format(const std::filesystem::path& file);

/// The format of `file` from its extension (case-insensitive), or nullopt for any other.
std::optional<MeshFormat> find_mesh_format(const std::filesystem::path& file);

/// The extensions mesh_format accepts, for messages: ".geo, .msh, .step, ... or .vtk".
std::string accepted_mesh_extensions();

/// True for the formats gmsh meshes (a .geo script and the CAD formats).
bool is_meshed(MeshFormat format);
/// True for the CAD formats (STEP, IGES, BREP).
bool is_cad(MeshFormat format);
/// True for the formats whose part is formed here (CAD, STL, Nastran, UNV, VTK); not .geo, .msh.
bool is_imported(MeshFormat format);

/// How a CAD or STL file becomes a part.
struct MeshImportOptions {
  /// -: lengths in the file are multiplied by it after any unit conversion (a STEP in metres is
  /// converted to mm by the reader; an IGES, BREP, STL or .msh is taken as it is written).
  double scale = 1.0;
  /// CAD only: refine by curvature to this many elements per 2 pi of curvature (gmsh's
  /// Mesh.MeshSizeFromCurvature: on a radius R the size is at most 2 pi R / N); 0 = off.
  int curvature_elements = 0;
  /// mm, CAD only: no element stands off the curved faces and edges by more than this
  /// (chord_error_size.hpp); 0 = off.
  double chord_error = 0.0;
  /// Imported formats: the surface tags that form the part (empty: every surface of the file).
  std::vector<int> surfaces;
  /// Imported formats: the name of the physical group the surfaces form (the case's group).
  std::string group;
  /// A part made of curves (a trim line): gmsh meshes the file in 1-D only, and a CAD file's
  /// curves `curves` (all when empty) become the 1-D physical group `group` (not its surfaces).
  bool curves_only = false;
  /// CAD, curves_only: the curve tags that form the part (empty: every curve of the file).
  std::vector<int> curves;
};

/// Sets gmsh's options for reading a CAD file of `format` (length unit, scaling, sewing of IGES
/// faces). Call in a gmsh session before the file is opened.
void set_cad_read_options(MeshFormat format, const MeshImportOptions& options);

/// After an imported file is read (and meshed): unless it names its own 2-D groups (a UNV file's
/// dataset 2477), the surfaces `options.surfaces` (all when empty) become the 2-D physical group
/// `options.group` (unnamed groups, a UNV file's material numbers, are dropped). InputError naming
/// the file for a surface list given for a file with named groups, a listed surface that does
/// not exist (listing those that do), or no surface at all.
void group_imported_surfaces(const std::filesystem::path& file, const MeshImportOptions& options);

/// After a CAD file is read and meshed in 1-D (options.curves_only): its curves `options.curves`
/// (all when empty) become the 1-D physical group `options.group`. InputError naming the file for
/// a listed curve that does not exist (listing those that do), or no curve at all.
void group_imported_curves(const std::filesystem::path& file, const MeshImportOptions& options);

}  // namespace sf
