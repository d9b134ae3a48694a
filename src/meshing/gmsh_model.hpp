#pragma once
// A gmsh model as plain data: every node, and each physical group with its elements. Read from the
// MSH 4.1 file the sandboxed gmsh writes (meshing/msh_file.hpp); part meshes and node groups are
// taken from it by group name (meshing/part_extraction.hpp).
#include <cstddef>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/types.hpp"

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
  std::vector<std::size_t> node_tags;      ///< every node of the group's elements, sorted, unique
};

/// Everything read from one gmsh model: all nodes, and each physical group by name.
struct GmshModel {
  std::filesystem::path file;          ///< the .geo, CAD or mesh file it came from
  std::vector<std::size_t> node_tags;  ///< gmsh tag of each node (column of node_coords)
  Matrix3X node_coords;                ///< mm (the file's units), column per node
  std::unordered_map<std::size_t, int> node_index;  ///< gmsh node tag -> column of node_coords
  std::vector<GmshPhysicalGroup> groups;            ///< sorted by (dim, tag)

  /// The group with this name and dimension (dim < 0: any dimension, lowest first), or nullptr.
  const GmshPhysicalGroup* find_group(const std::string& name, int dim = -1) const;
  /// The groups as text for messages: "blank (2-D), sym_x (1-D), ..." or "none".
  std::string list_groups() const;
};

/// "blank (2-D)", or "(unnamed, tag 3) (1-D)".
std::string group_label(const GmshPhysicalGroup& group);

/// InputError naming model.file when the model has no nodes, no physical groups or no elements
/// in them (what a part needs before any group is taken from it).
void check_model_has_groups(const GmshModel& model);

}  // namespace sf
