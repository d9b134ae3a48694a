#include "contact/box_grid.hpp"

#include <utility>

namespace sf::detail {

BoxGrid::BoxGrid(std::vector<Vec3> lo, std::vector<Vec3> hi, double cell_hint)
    : box_lo_(std::move(lo)), box_hi_(std::move(hi)) {
  const int n = num_items();
  if (n == 0) {
    cell_offsets_.assign(2, 0);
    return;
  }
  Vec3 grid_hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
  lo_ = Vec3::Constant(std::numeric_limits<double>::infinity());
  for (int i = 0; i < n; ++i) {
    lo_ = lo_.cwiseMin(box_lo_[i]);
    grid_hi = grid_hi.cwiseMax(box_hi_[i]);
  }
  const Vec3 extent = grid_hi - lo_;
  h_ = std::max(cell_hint, 1e-9 * std::max(extent.norm(), 1.0));
  const double max_cells = 8.0 * n + 64.0;
  for (;;) {
    double total = 1;
    for (int a = 0; a < 3; ++a) {
      cells_[a] = std::max(1, static_cast<int>(std::ceil(extent[a] / h_)));
      total *= cells_[a];
    }
    if (total <= max_cells) {
      break;
    }
    h_ *= std::max(1.01, std::cbrt(total / max_cells));
  }
  auto range = [&](int item, int a, int& first, int& last) {
    first = std::clamp(static_cast<int>(std::floor((box_lo_[item][a] - lo_[a]) / h_)), 0,
                       cells_[a] - 1);
    last = std::clamp(static_cast<int>(std::floor((box_hi_[item][a] - lo_[a]) / h_)), 0,
                      cells_[a] - 1);
  };
  const int ncell = cells_.prod();
  cell_offsets_.assign(ncell + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<int> fill;
    if (pass == 1) {
      for (int c = 0; c < ncell; ++c) {
        cell_offsets_[c + 1] += cell_offsets_[c];
      }
      cell_items_.resize(cell_offsets_[ncell]);
      fill.assign(cell_offsets_.begin(), cell_offsets_.end() - 1);
    }
    for (int item = 0; item < n; ++item) {
      int i0, i1, j0, j1, k0, k1;
      range(item, 0, i0, i1);
      range(item, 1, j0, j1);
      range(item, 2, k0, k1);
      for (int k = k0; k <= k1; ++k) {
        for (int j = j0; j <= j1; ++j) {
          for (int i = i0; i <= i1; ++i) {
            if (pass == 0) {
              ++cell_offsets_[cell_index(i, j, k) + 1];
            } else {
              cell_items_[fill[cell_index(i, j, k)]++] = item;
            }
          }
        }
      }
    }
  }
}

}  // namespace sf::detail
