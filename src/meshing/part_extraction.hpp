#pragma once
// Part meshes and node groups taken from a gmsh model by physical group name.
#include <string>

#include "mesh/mesh_data.hpp"
#include "meshing/gmsh_model.hpp"

namespace sf {

/// The 2-D physical group `group` as a part mesh named `part_name`: compact local node numbering
/// (ascending gmsh node tag), gmsh tags kept, quads and/or 3-node triangles; any other element type
/// (e.g. second order) is an InputError naming it. All elements of each connected piece are
/// oriented consistently (mesh/consistent_orientation.hpp: the majority's orientation). InputError
/// for a non-orientable surface, an edge shared by more than two elements, a degenerate element, a
/// node beyond kMaxCoordinate, or a missing group (naming the file, the group and listing the
/// groups that exist).
PartMesh extract_part_mesh(const GmshModel& model, const std::string& group,
                           const std::string& part_name);

/// Nodes of physical group `group` (any dimension: points, curves, surfaces; a name used at several
/// dimensions gives the union) mapped to the part's local node indices, sorted and unique.
/// InputError if the group is missing (listing the existing ones) or one of its nodes is not a node
/// of the part.
NodeGroup extract_node_group(const GmshModel& model, const PartMesh& part,
                             const std::string& group);

/// The largest coordinate a part's node may have, in the file's length unit: 1e12 (a million km in
/// mm); beyond it no sheet or tool is meant, and areas would lose their digits or overflow.
inline constexpr double kMaxCoordinate = 1e12;

}  // namespace sf
