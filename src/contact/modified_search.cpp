#include "contact/modified_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sf {

namespace {

/// Squared distance from p to the box [lo, hi].
inline double squared_distance_to_box(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  double d2 = 0;
  for (int a = 0; a < 3; ++a) {
    const double e = std::max({lo[a] - p[a], 0.0, p[a] - hi[a]});
    d2 += e * e;
  }
  return d2;
}

}  // namespace

ModifiedBruteForceSearch::ModifiedBruteForceSearch(const TriangleSurface& surface)
    : surface_(surface),
      projectors_(detail::make_projectors(surface)),
      tol_(detail::make_tie_tolerance(surface)) {}

void ModifiedBruteForceSearch::find_closest(const Vec3& p, double cutoff, ClosestPoint& out) const {
  detail::TieSet ties(tol_);
  if (p.allFinite()) {
    const int nt = static_cast<int>(projectors_.size());
    double bound = tol_.window(cutoff);
    double bound2 = bound * bound;
    for (int t = 0; t < nt; ++t) {
      const double d2 = detail::squared_distance(projectors_[t], p);
      if (d2 <= bound2) {
        ties.offer(t, std::sqrt(d2));
        bound = tol_.window(std::min(cutoff, ties.best()));
        bound2 = bound * bound;
      }
    }
  }
  ties.fill(projectors_, surface_, p, cutoff, out);
}

ModifiedSearch::ModifiedSearch(const TriangleSurface& surface)
    : surface_(surface),
      projectors_(detail::make_projectors(surface)),
      tol_(detail::make_tie_tolerance(surface)) {
  const int nt = surface.num_triangles();
  box_lo_.resize(nt);
  box_hi_.resize(nt);
  Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
  lo_ = Vec3::Constant(std::numeric_limits<double>::infinity());
  double mean_size = 0;
  for (int t = 0; t < nt; ++t) {
    const auto& x = projectors_[t].x;
    box_lo_[t] = x[0].cwiseMin(x[1]).cwiseMin(x[2]);
    box_hi_[t] = x[0].cwiseMax(x[1]).cwiseMax(x[2]);
    lo_ = lo_.cwiseMin(box_lo_[t]);
    hi = hi.cwiseMax(box_hi_[t]);
    mean_size += (box_hi_[t] - box_lo_[t]).maxCoeff();
  }
  if (nt == 0) {
    lo_.setZero();
    cell_offsets_.assign(2, 0);
    return;
  }
  // Cells about the mean triangle size (a few triangles per cell), at most ~8 per triangle.
  const Vec3 extent = hi - lo_;
  h_ = std::max(mean_size / nt, 1e-9 * std::max(extent.norm(), 1.0));
  const double max_cells = 8.0 * nt + 64.0;
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
  auto range = [&](int t, int a, int& first, int& last) {
    first =
        std::clamp(static_cast<int>(std::floor((box_lo_[t][a] - lo_[a]) / h_)), 0, cells_[a] - 1);
    last =
        std::clamp(static_cast<int>(std::floor((box_hi_[t][a] - lo_[a]) / h_)), 0, cells_[a] - 1);
  };
  const int ncell = cells_.prod();
  cell_offsets_.assign(ncell + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<int> fill;
    if (pass == 1) {
      for (int c = 0; c < ncell; ++c) {
        cell_offsets_[c + 1] += cell_offsets_[c];
      }
      cell_triangles_.resize(cell_offsets_[ncell]);
      fill.assign(cell_offsets_.begin(), cell_offsets_.end() - 1);
    }
    for (int t = 0; t < nt; ++t) {
      int i0, i1, j0, j1, k0, k1;
      range(t, 0, i0, i1);
      range(t, 1, j0, j1);
      range(t, 2, k0, k1);
      for (int k = k0; k <= k1; ++k) {
        for (int j = j0; j <= j1; ++j) {
          for (int i = i0; i <= i1; ++i) {
            if (pass == 0) {
              ++cell_offsets_[cell_index(i, j, k) + 1];
            } else {
              cell_triangles_[fill[cell_index(i, j, k)]++] = t;
            }
          }
        }
      }
    }
  }
}

void ModifiedSearch::find_closest(const Vec3& p, double cutoff, ClosestPoint& out) const {
  detail::TieSet ties(tol_);
  if (!p.allFinite() || projectors_.empty()) {
    ties.fill(projectors_, surface_, p, cutoff, out);
    return;
  }
  Eigen::Vector3i c;
  for (int a = 0; a < 3; ++a) {
    const double f = std::floor((p[a] - lo_[a]) / h_);
    c[a] = static_cast<int>(std::clamp(f, 0.0, static_cast<double>(cells_[a] - 1)));
  }
  double bound = tol_.window(cutoff);
  double bound2 = bound * bound;

  auto visit_cell = [&](int i, int j, int k) {
    const Vec3 cell_lo = lo_ + h_ * Vec3(i, j, k);
    const Vec3 cell_hi = cell_lo + Vec3::Constant(h_);
    // The last cell of each axis reaches the grid's end, which lies inside [cell_lo, cell_hi].
    if (squared_distance_to_box(p, cell_lo, cell_hi) > bound2) {
      return;
    }
    const int cell = cell_index(i, j, k);
    for (int q = cell_offsets_[cell]; q < cell_offsets_[cell + 1]; ++q) {
      const int t = cell_triangles_[q];
      if (squared_distance_to_box(p, box_lo_[t], box_hi_[t]) > bound2) {
        continue;
      }
      const double d2 = detail::squared_distance(projectors_[t], p);
      if (d2 <= bound2) {
        ties.offer(t, std::sqrt(d2));
        bound = tol_.window(std::min(cutoff, ties.best()));
        bound2 = bound * bound;
      }
    }
  };

  for (int r = 0;; ++r) {
    if (r > 0) {
      // Every cell of shell r lies outside the box of shells < r along some axis: its distance
      // is at least the least distance from p to that box's faces beyond which cells exist.
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
        break;  // no cells left, or all of them too far
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
  ties.fill(projectors_, surface_, p, cutoff, out);
}

}  // namespace sf
