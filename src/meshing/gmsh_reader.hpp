#pragma once
// Meshes from gmsh: a .geo file meshed through the gmsh API (2-D), a ready .msh file, or a CAD
// (STEP, IGES, BREP) or STL file (meshing/mesh_import.hpp), read into plain data (GmshModel), from
// which part meshes and node groups are taken by physical group name.
// gmsh is used only here, serially, before the time loop.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/errors.hpp"
#include "core/types.hpp"
#include "mesh/mesh_data.hpp"
#include "meshing/geo_parameter.hpp"
#include "meshing/mesh_import.hpp"

namespace sf {

/// Elements of one gmsh element type within a physical group.
struct GmshElementBlock {
  int type = 0;               ///< gmsh element type (2 = 3-node triangle, 3 = 4-node quad)
  std::string type_name;      ///< gmsh's name for the type, e.g. "Triangle 6"
  int nodes_per_element = 0;  ///< nodes per element of this type
  std::vector<std::size_t> element_tags;  ///< gmsh element tags
  std::vector<std::size_t> node_tags;     ///< gmsh node tags, nodes_per_element per element
};

/// One physical group of a gmsh model.
struct GmshPhysicalGroup {
  std::string name;                        ///< "" when the file gives it no name
  int dim = 0;                             ///< 0 points, 1 curves, 2 surfaces, 3 volumes
  int tag = 0;                             ///< gmsh's physical tag
  std::vector<GmshElementBlock> elements;  ///< one block per element type, in gmsh's order
  std::vector<std::size_t> node_tags;      ///< every node of the group's entities, sorted, unique
};

/// Everything read from one gmsh model: all nodes, and each physical group by name.
struct GmshModel {
  std::filesystem::path file;          ///< the .geo or .msh file it came from
  std::vector<std::size_t> node_tags;  ///< gmsh tag of each node (column of node_coords)
  Matrix3X node_coords;                ///< mm (the file's units), column per node
  std::unordered_map<std::size_t, int> node_index;  ///< gmsh node tag -> column of node_coords
  std::vector<GmshPhysicalGroup> groups;            ///< sorted by (dim, tag)

  /// The group with this name and dimension (dim < 0: any dimension, lowest first), or nullptr.
  const GmshPhysicalGroup* find_group(const std::string& name, int dim = -1) const;
  /// The groups as text for messages: "blank (2-D), sym_x (1-D), ..." or "none".
  std::string list_groups() const;
};

/// A parameter a .geo file cannot take (it does not define it, or assigns it itself); index() is
/// its position in the parameters given.
class GeoParameterError : public InputError {
 public:
  GeoParameterError(std::size_t index, const std::string& message)
      : InputError(message), index_(index) {}
  std::size_t index() const { return index_; }

 private:
  std::size_t index_;
};

/// Meshes a .geo file with gmsh (OpenCASCADE or built-in kernel, 2-D mesh) or reads a .msh file.
///
/// element_size (mm) > 0, for a .geo file only: sets gmsh's option Mesh.MeshSizeMax to it and
/// Mesh.MeshSizeFromPoints to 0, both before the file is read (so a .geo can use the value, e.g.
/// `If (Mesh.MeshSizeMax < 1e21) h = Mesh.MeshSizeMax; EndIf` for transfinite counts) and again
/// after (so it overrides sizes the file sets). Curvature refinement and size fields the file asks
/// for still refine below it. 0 keeps the file's own sizes. Ignored for a .msh file.
/// recombine = true (for a .geo) sets Mesh.RecombineAll = 1 and Mesh.Algorithm = 8
/// (Frontal-Delaunay for quads) after the file is read: quadrilaterals wherever gmsh can make them.
///
/// parameters (a .geo only): numbers set before the file is parsed. Each must be a variable the
/// file declares with DefineConstant[ name = default ] (DefineConstant keeps a value set before
/// it; a plain assignment `name = ...;` would override it). gmsh 4.8's API cannot set or list
/// parser variables, so the file is parsed twice: once as it is, to check with Exists() that it
/// defines every parameter, then through a wrapper .geo (in a temporary folder) that assigns the
/// parameters and Includes the file, reading each value back afterwards. GeoParameterError for a
/// parameter the file does not define or overrides.
///
/// Throws InputError naming the file for: a missing file, an unknown extension, a negative size,
/// gmsh parse/meshing errors (with gmsh's message), an empty mesh, a model without physical groups,
/// parameters for a .msh file.
/// Runs its own gmsh session (initialize ... finalize; not re-entrant, do not call while another
/// gmsh session is open) and restores the OpenMP thread count that gmsh resets. gmsh's terminal
/// output is shown only at Verbosity::verbose.
/// What gmsh may spend on one part (the case's [limits]): a .geo whose element_size asks for
/// more elements than max_elements (estimated from its surfaces' bounding boxes before meshing)
/// is refused with InputError; reading and meshing that take longer than `seconds` end the
/// process with exit code 2 and a message naming the file (gmsh cannot be interrupted).
struct MeshBudget {
  double seconds = 600.0;
  double max_elements = 5e6;
};
/// The budget of the meshing in this process (set from the case before its parts are meshed).
MeshBudget& mesh_budget();

/// CAD and STL files (meshing/mesh_import.hpp): a CAD file is read by OpenCASCADE (a STEP file's
/// unit converted to mm, IGES faces sewn), scaled by import.scale and meshed like a .geo
/// (element_size > 0 required; import.curvature_elements and import.chord_error refine curved
/// faces); an STL file's triangles are
/// taken as they are. Either has no physical groups: its surfaces (import.surfaces, or all)
/// become the group import.group. A .msh or STL file's coordinates are multiplied by import.scale.
GmshModel load_gmsh_model(const std::filesystem::path& file, double element_size, bool recombine,
                          std::span<const GeoParameter> parameters = {},
                          const MeshImportOptions& import = {});

/// The 2-D physical group `group` as a part mesh named `part_name`: compact local node numbering
/// (ascending gmsh node tag), gmsh tags kept, quads and/or 3-node triangles; any other element type
/// (e.g. second order) is an InputError naming it. All elements of each connected piece are
/// oriented consistently (orientation propagated over shared edges); of the two orientations the
/// one most elements already had is kept (ties: that of the piece's first element). InputError for
/// a non-orientable surface, an edge shared by more than two elements, a degenerate element, or a
/// missing group (naming the file, the group and listing the groups that exist).
PartMesh extract_part_mesh(const GmshModel& model, const std::string& group,
                           const std::string& part_name);

/// Nodes of physical group `group` (any dimension: points, curves, surfaces; a name used at several
/// dimensions gives the union) mapped to the part's local node indices, sorted and unique.
/// InputError if the group is missing (listing the existing ones) or one of its nodes is not a node
/// of the part.
NodeGroup extract_node_group(const GmshModel& model, const PartMesh& part,
                             const std::string& group);

/// Meshes `geo_file` exactly as load_gmsh_model does (a .msh file is read as it is) and writes the
/// mesh to `msh_out` in gmsh's ASCII format 4.1, so a case folder can keep the mesh its .geo made.
/// Only elements of physical groups are written. InputError as load_gmsh_model, or if the output
/// cannot be written.
void write_msh(const std::filesystem::path& geo_file, double element_size, bool recombine,
               const std::filesystem::path& msh_out, std::span<const GeoParameter> parameters = {});

}  // namespace sf
