#include "contact/modified_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace sf {

namespace {

/// The grid of the triangles' bounding boxes; cells about the mean triangle size (a few
/// triangles per cell).
detail::BoxGrid make_triangle_grid(const std::vector<detail::TriangleProjector>& projectors) {
  const int nt = static_cast<int>(projectors.size());
  std::vector<Vec3> lo(nt), hi(nt);
  double mean_size = 0;
  for (int t = 0; t < nt; ++t) {
    const auto& x = projectors[t].x;
    lo[t] = x[0].cwiseMin(x[1]).cwiseMin(x[2]);
    hi[t] = x[0].cwiseMax(x[1]).cwiseMax(x[2]);
    mean_size += (hi[t] - lo[t]).maxCoeff();
  }
  return detail::BoxGrid(std::move(lo), std::move(hi), nt > 0 ? mean_size / nt : 1.0);
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
      tol_(detail::make_tie_tolerance(surface)),
      grid_(make_triangle_grid(projectors_)) {}

void ModifiedSearch::find_closest(const Vec3& p, double cutoff, ClosestPoint& out) const {
  detail::TieSet ties(tol_);
  double bound = tol_.window(cutoff);
  grid_.visit(p, bound, [&](int t) {
    const double d2 = detail::squared_distance(projectors_[t], p);
    if (d2 <= bound * bound) {
      ties.offer(t, std::sqrt(d2));
      bound = tol_.window(std::min(cutoff, ties.best()));
    }
    return bound;
  });
  ties.fill(projectors_, surface_, p, cutoff, out);
}

}  // namespace sf
