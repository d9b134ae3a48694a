#pragma once
// A bounding-volume hierarchy over axis-aligned boxes (mm), for the pre-run tool checks
// (mesh/tool_diagnosis.hpp, mesh/surface_approach.hpp): every box near a query box, or the
// nearest, at a cost that grows with log n whether the query is near the boxes or far from them
// (a uniform grid, contact/box_grid.hpp, walks its empty cells when the query is far).
#include <algorithm>
#include <array>
#include <vector>

#include "core/types.hpp"

namespace sf {

/// Squared distance between boxes [lo1, hi1] and [lo2, hi2] (0 when they overlap).
inline double box_distance2(const Vec3& lo1, const Vec3& hi1, const Vec3& lo2, const Vec3& hi2) {
  return (lo2 - hi1).cwiseMax(lo1 - hi2).cwiseMax(0.0).squaredNorm();
}

class BoxTree {
 public:
  /// Items i = 0 .. lo.size()-1 with boxes [lo[i], hi[i]] (mm).
  BoxTree(std::vector<Vec3> lo, std::vector<Vec3> hi);

  const Vec3& box_lo(int i) const { return box_lo_[i]; }
  const Vec3& box_hi(int i) const { return box_hi_[i]; }

  /// Calls test(i) for every item i whose box lies within `bound` (mm, may be +infinity) of the
  /// box [lo, hi], nearer subtrees first, and for no item farther. `test` returns the bound to use
  /// from then on (it may only shrink, e.g. to the best distance so far; below 0 ends the visit).
  /// Does not allocate.
  template <class Test>
  void visit(const Vec3& lo, const Vec3& hi, double bound, Test&& test) const;

 private:
  struct Node {
    Vec3 lo, hi;    ///< the box of every item below
    int first = 0;  ///< leaf: items_[first .. first + count); inner node: its first child
    int count = 0;  ///< items of a leaf; 0 for an inner node (children first and first + 1)
  };
  void build(int node, int begin, int end);

  std::vector<Vec3> box_lo_, box_hi_;
  std::vector<int> items_;
  std::vector<Node> nodes_;
};

template <class Test>
void BoxTree::visit(const Vec3& lo, const Vec3& hi, double bound, Test&& test) const {
  if (nodes_.empty() || bound < 0.0) {
    return;
  }
  double bound2 = bound * bound;
  const auto distance2 = [&](const Node& n) { return box_distance2(lo, hi, n.lo, n.hi); };
  std::array<int, 128> stack;  // holds depth + 1 nodes at most; depth <= log2(n) + 1
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (distance2(node) > bound2) {
      continue;
    }
    if (node.count > 0) {
      for (int k = node.first; k < node.first + node.count; ++k) {
        const int item = items_[k];
        if (box_distance2(lo, hi, box_lo(item), box_hi(item)) <= bound2) {
          bound = test(item);
          if (bound < 0.0) {
            return;
          }
          bound2 = bound * bound;
        }
      }
      continue;
    }
    // The nearer child on top of the stack, visited first.
    const int a = node.first, b = node.first + 1;
    const bool a_nearer = distance2(nodes_[a]) <= distance2(nodes_[b]);
    stack[top++] = a_nearer ? b : a;
    stack[top++] = a_nearer ? a : b;
  }
}

}  // namespace sf
