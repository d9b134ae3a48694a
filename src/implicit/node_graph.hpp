#pragma once
// The blank's node graph (nodes that share an element) and a distance-2 colouring of it: nodes of
// one colour share no neighbour, so perturbing all of them at once changes each node's internal
// force through one perturbed node only. This is what lets the tangent stiffness be built column
// by column from a few internal-force evaluations (Curtis, Powell & Reid 1974).
#include <vector>

#include "element/shell_part.hpp"

namespace sf {

/// Neighbours of every node (itself included), sorted: compressed rows.
struct NodeGraph {
  std::vector<int> start;      ///< node_count + 1
  std::vector<int> neighbour;  ///< neighbours of node i: neighbour[start[i] .. start[i + 1])
  int node_count() const { return static_cast<int>(start.size()) - 1; }
};

/// The graph of the part's quads and triangles over node_count nodes.
NodeGraph make_node_graph(const ShellPart& part, int node_count);

/// A distance-2 colouring: colour[i] in 0..colour_count - 1, no two nodes of one colour within
/// two edges of each other. Greedy in node order (deterministic).
struct NodeColouring {
  std::vector<int> colour;
  int colour_count = 0;
  /// Nodes of colour c: members[member_start[c] .. member_start[c + 1]).
  std::vector<int> member_start;
  std::vector<int> members;
};

NodeColouring colour_distance_two(const NodeGraph& graph);

}  // namespace sf
