// One orientation per connected piece (mesh/consistent_orientation.hpp), on hand-made meshes.
#include "mesh/consistent_orientation.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace sf {
namespace {

/// A strip of n quads (nodes 0..n bottom, n+1..2n+1 top), element e reversed when flipped[e].
struct Strip {
  std::vector<int> offsets{0}, nodes;
  Strip(int n, const std::vector<bool>& flipped) {
    for (int e = 0; e < n; ++e) {
      std::vector<int> q = {e, e + 1, n + 2 + e, n + 1 + e};
      if (flipped[e]) {
        std::swap(q[1], q[3]);
      }
      nodes.insert(nodes.end(), q.begin(), q.end());
      offsets.push_back(static_cast<int>(nodes.size()));
    }
  }
};

TEST(ConsistentOrientation, TheMajorityOrientationIsKept) {
  const Strip a(5, {false, true, false, true, false});
  const ConsistentOrientation o = orient_consistently(a.offsets, a.nodes);
  EXPECT_EQ(o.flip, (std::vector<char>{0, 1, 0, 1, 0}));
  EXPECT_EQ(o.num_pieces, 1);
  const Strip b(5, {true, true, false, true, false});
  EXPECT_EQ(orient_consistently(b.offsets, b.nodes).flip, (std::vector<char>{0, 0, 1, 0, 1}));
}

TEST(ConsistentOrientation, ATieKeepsTheFirstElements) {
  const Strip s(4, {true, false, true, false});
  EXPECT_EQ(orient_consistently(s.offsets, s.nodes).flip, (std::vector<char>{0, 1, 0, 1}));
}

TEST(ConsistentOrientation, PiecesAreOrientedOnTheirOwn) {
  // Two triangles apart (no shared edge), and a quad and a triangle sharing edge 10-11.
  const std::vector<int> offsets = {0, 3, 6, 10, 13};
  const std::vector<int> nodes = {0, 1, 2, 3, 4, 5, 10, 11, 12, 13, 10, 11, 14};
  const ConsistentOrientation o = orient_consistently(offsets, nodes);
  EXPECT_EQ(o.num_pieces, 3);
  EXPECT_EQ(o.piece, (std::vector<int>{0, 1, 2, 2}));
  // The triangle runs 10 -> 11 as the quad does: one of them turns (a tie: the quad is first).
  EXPECT_EQ(o.flip, (std::vector<char>{0, 0, 0, 1}));
}

TEST(ConsistentOrientation, AMoebiusBandIsAConflict) {
  // Four quads round a band whose last joins the first with its edge turned over.
  const std::vector<int> offsets = {0, 4, 8, 12, 16};
  const std::vector<int> nodes = {0, 1, 6, 5, 1, 2, 7, 6, 2, 3, 8, 7, 3, 5, 0, 8};
  const ConsistentOrientation o = orient_consistently(offsets, nodes);
  ASSERT_TRUE(o.conflict.has_value());
  EXPECT_TRUE(o.flip.empty());
}

TEST(ConsistentOrientation, EveryNonManifoldEdgeIsListed) {
  const std::vector<int> offsets = {0, 3, 6, 9, 12, 15};
  // Edge 0-1 in three triangles, edge 5-6 in two (fine).
  const std::vector<int> nodes = {0, 1, 2, 1, 0, 3, 0, 1, 4, 5, 6, 7, 6, 5, 8};
  const ConsistentOrientation o = orient_consistently(offsets, nodes);
  ASSERT_EQ(o.non_manifold.size(), 1u);
  EXPECT_EQ(o.non_manifold[0].lo, 0);
  EXPECT_EQ(o.non_manifold[0].hi, 1);
  EXPECT_EQ(o.non_manifold[0].elements, 3);
}

}  // namespace
}  // namespace sf
