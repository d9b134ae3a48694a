#pragma once
// One orientation for every connected piece of a surface mesh: elements (polygons of 3 or 4
// nodes) that share an edge agree when they run it in opposite directions. Used by the mesh
// reader for parts (meshing/part_extraction.cpp) and by the tools' orient_surface.
#include <optional>
#include <span>
#include <vector>

namespace sf {

/// An edge that more than two elements share (nodes lo < hi).
struct NonManifoldEdge {
  int lo = 0, hi = 0;
  int elements = 0;  ///< how many share it
};

/// Where a piece's orientation meets itself reversed (a Moebius-like band): elements a and b
/// share the edge (lo, hi) and cannot both agree with the rest.
struct OrientationConflict {
  int element_a = 0, element_b = 0;
  int lo = 0, hi = 0;
};

struct ConsistentOrientation {
  std::vector<char> flip;  ///< per element: 1 = reverse it to agree with its piece
  std::vector<int> piece;  ///< per element: its connected piece (over shared edges), from 0
  int num_pieces = 0;
  /// Every edge of more than two elements, by (lo, hi); when any, flip and piece are empty.
  std::vector<NonManifoldEdge> non_manifold;
  std::optional<OrientationConflict> conflict;  ///< when set, flip and piece are empty
};

/// Element e has the nodes nodes[offsets[e] .. offsets[e + 1]), in its order. Breadth-first over
/// shared edges from each piece's first element; of a piece's two orientations, the one most of
/// its elements already have is kept (a tie: its first element's).
ConsistentOrientation orient_consistently(std::span<const int> offsets, std::span<const int> nodes);

}  // namespace sf
