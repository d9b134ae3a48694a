#pragma once
// A formed part carried onto a new mesh made from its own (shared/DESIGN.md R8: a topology change
// is a function from formed part to formed part that maps the state): every new node is one of
// the part's nodes, possibly moved along one of its edges, or a point on an edge; every new
// element is one of its elements whole, or a piece of one. The state follows by each field's
// mapping (solver/state_fields.hpp):
// - node fields that interpolate (coordinates, velocities, rotations), the reference nodes:
//   linearly along the edge the node lies on;
// - element and point fields: the parent element's values. A piece's components in the element
//   frame (stresses, back stresses, transverse shear: mapping inherit_in_frame) are turned into
//   the piece's own corotational frame; its hourglass resultants start at zero (they belong to
//   the parent's shape) and its directors are the parent's at its corners, interpolated along an
//   edge where a corner lies on one;
// - fields made again from the mesh (forces, masses, contact offsets) and the contact pairs'
//   history are left out, for the next model to make; the run's and the tools' are kept.
// Node groups: a node that continues one of the part's keeps its groups; a node made on an edge
// belongs to the groups that hold both of the edge's ends.
#include <array>
#include <vector>

#include "solver/formed_part.hpp"

namespace sf {

/// Where a new node comes from: the point (1 - t) x_a + t x_b of the part's nodes a, b (a == b,
/// t = 0 for a node kept as it is), in the part's current and reference coordinates alike.
struct NodeSource {
  int a = 0;
  int b = 0;
  double t = 0.0;
  int origin = -1;  ///< the part's node it continues (its tag and groups), or -1: a new node
};

/// A new element: its nodes (new numbering; 3 for a triangle, the 4th then unused) and the part's
/// element it is, or is a piece of (quads first, then triangles).
struct ElementSource {
  std::array<int, 4> nodes{};
  int parent = 0;
  bool whole = true;  ///< the parent itself, its nodes unmoved: every value kept as it is
};

struct PartRemap {
  std::vector<NodeSource> nodes;
  std::vector<ElementSource> quads;
  std::vector<ElementSource> triangles;
};

/// The part on the new mesh, its state mapped as above. Throws std::logic_error for a map that
/// refers to nodes or elements the part does not have.
FormedPart remap_part(const FormedPart& part, const PartRemap& map);

/// The element's node indices in the part (quads first, then triangles).
std::vector<int> part_element_nodes(const FormedPart& part, int element);

/// The connected pieces of the part (elements joined through shared nodes), elements each,
/// largest first.
std::vector<int> part_piece_sizes(const FormedPart& part);

}  // namespace sf
