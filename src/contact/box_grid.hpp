#pragma once
// A uniform grid of axis-aligned boxes (triangle bounding boxes, or tool nodes as zero-size
// boxes) with an exact nearest-first traversal: the one acceleration structure of the contact
// searches ("modified", "standard", "cached"). Internal to sf_contact.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include "core/types.hpp"

namespace sf::detail {

/// Squared distance from p to the box [lo, hi] (0 inside). For a zero-size box lo = hi = x it is
/// |p - x|^2, summed over the axes in order.
inline double squared_distance_to_box(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  double d2 = 0;
  for (int a = 0; a < 3; ++a) {
    const double e = std::max({lo[a] - p[a], 0.0, p[a] - hi[a]});
    d2 += e * e;
  }
  return d2;
}

/// Uniform grid over the bounding box of a set of items, each with its box. Each cell lists
/// every item whose box overlaps it (CSR).
class BoxGrid {
 public:
  BoxGrid() = default;
  /// Items i = 0 .. lo.size()-1 with boxes [lo[i], hi[i]] (mm). Cells are cubes of about
  /// `cell_hint` mm, enlarged until there are at most 8 cells per item (+64).
  BoxGrid(std::vector<Vec3> lo, std::vector<Vec3> hi, double cell_hint);

  int num_items() const { return static_cast<int>(box_lo_.size()); }
  const Vec3& box_lo(int i) const { return box_lo_[i]; }
  const Vec3& box_hi(int i) const { return box_hi_[i]; }
  const Eigen::Vector3i& cells() const { return cells_; }
  double cell_size() const { return h_; }

  /// Calls `test(i)` for every item i whose box is within `bound` (mm, may be +infinity) of p,
  /// nearest cells first, and for no item whose box is farther. `test` returns the bound to use
  /// from then on (it may only shrink, e.g. to the best distance so far plus a tie window): cells
  /// and items whose boxes lie farther than the current bound are skipped, and the traversal
  /// stops when every cell not yet visited is farther. An item overlapping several cells may be
  /// tested more than once. Does not allocate. Nothing is visited for a non-finite p.
  ///
  /// The cells are visited in shells of growing Chebyshev distance r around p's cell (p clamped
  /// into the grid). Every cell of shell r lies outside the box of the shells < r along some axis,
  /// so its distance from p is at least the least distance from p to a face of that box beyond
  /// which cells remain: once that exceeds the bound, nothing farther can be within it.
  template <class Test>
  void visit(const Vec3& p, double bound, Test&& test) const {
    visit(p, bound, test, NoCounter{});
  }

  /// The same, reporting its work to `counter` (for operation counts): counter.shell() for each
  /// shell bound checked, counter.cell() for each cell box checked, counter.item() for each item
  /// box checked.
  template <class Test, class Counter>
  void visit(const Vec3& p, double bound, Test&& test, Counter&& counter) const;

  /// A counter that counts nothing (the default).
  struct NoCounter {
    void shell() const {}
    void cell() const {}
    void item() const {}
  };

 private:
  int cell_index(int i, int j, int k) const { return (k * cells_[1] + j) * cells_[0] + i; }

  std::vector<Vec3> box_lo_, box_hi_;  ///< item boxes, mm
  Vec3 lo_ = Vec3::Zero();             ///< grid origin, mm
  double h_ = 1;                       ///< cell size, mm
  Eigen::Vector3i cells_ = Eigen::Vector3i::Ones();
  std::vector<int> cell_offsets_;  ///< CSR: items of cell c in
  std::vector<int> cell_items_;    ///< cell_items_[cell_offsets_[c] .. cell_offsets_[c+1])
};

template <class Test, class Counter>
void BoxGrid::visit(const Vec3& p, double bound, Test&& test, Counter&& counter) const {
  if (box_lo_.empty() || !p.allFinite()) {
    return;
  }
  Eigen::Vector3i c;
  for (int a = 0; a < 3; ++a) {
    const double f = std::floor((p[a] - lo_[a]) / h_);
    c[a] = static_cast<int>(std::clamp(f, 0.0, static_cast<double>(cells_[a] - 1)));
  }
  double bound2 = bound * bound;

  auto visit_cell = [&](int i, int j, int k) {
    counter.cell();
    const Vec3 cell_lo = lo_ + h_ * Vec3(i, j, k);
    const Vec3 cell_hi = cell_lo + Vec3::Constant(h_);
    // The last cell of each axis reaches the grid's end, which lies inside [cell_lo, cell_hi].
    if (squared_distance_to_box(p, cell_lo, cell_hi) > bound2) {
      return;
    }
    const int cell = cell_index(i, j, k);
    for (int q = cell_offsets_[cell]; q < cell_offsets_[cell + 1]; ++q) {
      const int item = cell_items_[q];
      counter.item();
      if (squared_distance_to_box(p, box_lo_[item], box_hi_[item]) > bound2) {
        continue;
      }
      bound = test(item);
      bound2 = bound * bound;
    }
  };

  for (int r = 0;; ++r) {
    if (r > 0) {
      counter.shell();
      double lower = std::numeric_limits<double>::infinity();
      bool cells_left = false;
      for (int a = 0; a < 3; ++a) {
        if (c[a] - r >= 0) {
          cells_left = true;
          lower = std::min(lower, std::max(0.0, p[a] - (lo_[a] + (c[a] - r + 1) * h_)));
        }
        if (c[a] + r <= cells_[a] - 1) {
          cells_left = true;
          lower = std::min(lower, std::max(0.0, lo_[a] + (c[a] + r) * h_ - p[a]));
        }
      }
      if (!cells_left || !(lower <= bound)) {
        return;  // no cells left, or all of them too far
      }
    }
    const int i0 = std::max(0, c[0] - r), i1 = std::min(cells_[0] - 1, c[0] + r);
    const int j0 = std::max(0, c[1] - r), j1 = std::min(cells_[1] - 1, c[1] + r);
    const int k0 = std::max(0, c[2] - r), k1 = std::min(cells_[2] - 1, c[2] + r);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        if (std::abs(i - c[0]) == r || std::abs(j - c[1]) == r) {
          for (int k = k0; k <= k1; ++k) {
            visit_cell(i, j, k);
          }
        } else {
          if (c[2] - r >= 0) {
            visit_cell(i, j, c[2] - r);
          }
          if (c[2] + r <= cells_[2] - 1) {
            visit_cell(i, j, c[2] + r);
          }
        }
      }
    }
  }
}

}  // namespace sf::detail
