#include "contact/standard_search.hpp"

#include <cmath>
#include <limits>
#include <utility>

namespace sf {

StandardSearchBase::StandardSearchBase(const TriangleSurface& surface)
    : surface_(surface),
      projectors_(detail::make_projectors(surface)),
      tol_(detail::make_tie_tolerance(surface)) {
  for (const detail::TriangleProjector& tp : projectors_) {
    for (int a = 0; a < 3; ++a) {
      longest_edge_ = std::max(longest_edge_, (tp.x[(a + 1) % 3] - tp.x[a]).norm());
    }
  }
}

void StandardSearchBase::closest_on_node_triangles(int node, const Vec3& p, double cutoff,
                                                   ClosestPoint& out) const {
  detail::TieSet ties(tol_);
  if (node >= 0) {
    const std::vector<int>& offsets = surface_.node_triangle_offsets();
    const std::vector<int>& triangles = surface_.node_triangles();
    double bound = tol_.window(cutoff);
    for (int q = offsets[node]; q < offsets[node + 1]; ++q) {
      const int t = triangles[q];
      const double d2 = detail::squared_distance(projectors_[t], p);
      if (d2 <= bound * bound) {
        ties.offer(t, std::sqrt(d2));
        bound = tol_.window(std::min(cutoff, ties.best()));
      }
    }
  }
  ties.fill(projectors_, surface_, p, cutoff, out);
}

void StandardBruteForceSearch::find_closest(const Vec3& p, double cutoff, ClosestPoint& out) const {
  int best = -1;
  if (p.allFinite()) {
    double best_d2 = std::numeric_limits<double>::infinity();
    const int nn = surface_.num_nodes();
    for (int i = 0; i < nn; ++i) {
      const double d2 = node_distance2(i, p);
      if (d2 < best_d2 && has_triangles(i)) {  // strict: ties keep the lowest index
        best_d2 = d2;
        best = i;
      }
    }
  }
  closest_on_node_triangles(best, p, cutoff, out);
}

StandardSearch::StandardSearch(const TriangleSurface& surface) : StandardSearchBase(surface) {
  std::vector<Vec3> lo;
  double edge_sum = 0;
  int edge_count = 0;
  for (const detail::TriangleProjector& tp : projectors_) {
    for (int a = 0; a < 3; ++a) {
      edge_sum += (tp.x[(a + 1) % 3] - tp.x[a]).norm();
      ++edge_count;
    }
  }
  for (int i = 0; i < surface.num_nodes(); ++i) {
    if (has_triangles(i)) {
      grid_nodes_.push_back(i);
      lo.push_back(surface.nodes().col(i));
    }
  }
  std::vector<Vec3> hi = lo;
  grid_ = detail::BoxGrid(std::move(lo), std::move(hi), edge_count > 0 ? edge_sum / edge_count : 1);
}

int StandardSearch::closest_node(const Vec3& p, double radius) const {
  int best = -1;
  double best_d2 = std::numeric_limits<double>::infinity();
  double bound = radius;
  // The grid skips a cell or node only when its box is farther than the bound: widened by the
  // tie tolerance's absolute part (far above the rounding of a box or node distance) so that a
  // node at exactly the best distance, which may have a lower index, is still compared.
  grid_.visit(p, bound, [&](int item) {
    const int node = grid_nodes_[item];
    const double d2 = node_distance2(node, p);
    if (d2 < best_d2 || (d2 == best_d2 && node < best)) {
      best_d2 = d2;
      best = node;
      bound = std::min(bound, std::sqrt(best_d2) + tol_.absolute);
    }
    return bound;
  });
  return best;
}

void StandardSearch::find_closest(const Vec3& p, double cutoff, ClosestPoint& out) const {
  // Nodes farther than cutoff + longest edge carry no triangle within the cutoff (class comment).
  const double radius = tol_.window(cutoff + longest_edge_);
  closest_on_node_triangles(closest_node(p, radius), p, cutoff, out);
}

}  // namespace sf
