#pragma once
// Meshes as read from gmsh: nodes, elements and named groups, before any physics is attached.
#include <string>
#include <vector>

#include "core/types.hpp"

namespace sf {

/// One part's mesh: a blank (quads) or a tool surface (triangles). Node numbering is local and
/// compact (0..n-1); `gmsh_node_tags` keeps gmsh's tags for messages.
struct PartMesh {
  std::string name;                         ///< part name (blank, punch, ...)
  Matrix3X nodes;                           ///< mm, column per node
  std::vector<std::size_t> gmsh_node_tags;  ///< gmsh tag of each local node
  QuadConn quads;     ///< local node indices, counter-clockwise seen from +normal
  TriConn triangles;  ///< local node indices
  /// Elements reversed when read, to agree with their neighbours' orientation (the minority of
  /// each connected piece: extract_part_mesh).
  int reoriented = 0;
  /// gmsh tag of each element, quads first then triangles (as the ShellPart numbering); empty
  /// where the elements have none (a formed part's mesh).
  std::vector<std::size_t> gmsh_element_tags;
};

/// A named set of nodes of a part (boundary curves, points), from a gmsh physical group.
struct NodeGroup {
  std::string name;
  std::vector<int> nodes;  ///< local node indices of the part they belong to, sorted, unique
};

}  // namespace sf
