#include "mesh/box_tree.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <utility>

namespace sf {

namespace {
constexpr int kLeafSize = 4;
}  // namespace

BoxTree::BoxTree(std::vector<Vec3> lo, std::vector<Vec3> hi)
    : box_lo_(std::move(lo)), box_hi_(std::move(hi)) {
  const int n = static_cast<int>(box_lo_.size());
  if (n == 0) {
    return;
  }
  items_.resize(n);
  std::iota(items_.begin(), items_.end(), 0);
  nodes_.reserve(n);  // about 2 n / kLeafSize are made: no reallocation
  nodes_.emplace_back();
  build(0, 0, n);
}

// Fills nodes_[node] for items_[begin, end): a leaf of at most kLeafSize items, or an inner node
// whose two children split the items at the median of their box centres along the widest axis.
void BoxTree::build(int node, int begin, int end) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  Vec3 centre_lo = lo, centre_hi = hi;
  for (int k = begin; k < end; ++k) {
    const int i = items_[k];
    lo = lo.cwiseMin(box_lo_[i]);
    hi = hi.cwiseMax(box_hi_[i]);
    const Vec3 centre = 0.5 * (box_lo_[i] + box_hi_[i]);
    centre_lo = centre_lo.cwiseMin(centre);
    centre_hi = centre_hi.cwiseMax(centre);
  }
  Node& self = nodes_[node];
  self.lo = lo;
  self.hi = hi;
  if (end - begin <= kLeafSize) {
    self.first = begin;
    self.count = end - begin;
    return;
  }
  int axis = 0;
  (centre_hi - centre_lo).maxCoeff(&axis);
  const int middle = begin + (end - begin) / 2;
  const auto centre_below = [&](int a, int b) {
    return box_lo_[a][axis] + box_hi_[a][axis] < box_lo_[b][axis] + box_hi_[b][axis];
  };
  std::nth_element(items_.begin() + begin, items_.begin() + middle, items_.begin() + end,
                   centre_below);
  const int children = static_cast<int>(nodes_.size());
  self.first = children;  // before the nodes grow (self may move)
  self.count = 0;
  nodes_.resize(nodes_.size() + 2);
  build(children, begin, middle);
  build(children + 1, middle, end);
}

}  // namespace sf
