#pragma once
// The per-triangle kernel of the modified contact search (Wawrzyk & Kowalczyk): orthogonal
// projection of a point onto a triangle by the 3x3 system
//   x_p = x1 + T1 (x2 - x1) + T2 (x3 - x1) + D n,   T3 = 1 - T1 - T2,
// and, when the projection falls outside (some T < 0), projection onto the edges (clamped to
// the vertices). Internal to sf_contact.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "contact/contact_search.hpp"
#include "core/types.hpp"
#include "mesh/triangle_surface.hpp"

namespace sf::detail {

/// What makes the 3x3 system cheap for a rigid tool in its reference frame: the inverse of the
/// constant matrix [x2 - x1, x3 - x1, n] (rows give T1, T2 and D), the vertices and the inverse
/// squared edge lengths.
struct TriangleProjector {
  std::array<Vec3, 3> x;           ///< vertices, mm
  Mat3 inverse;                    ///< [x2 - x1, x3 - x1, n]^-1
  std::array<double, 3> inv_len2;  ///< 1 / |edge|^2 for edges 1->2, 2->3, 3->1, 1/mm^2
};

/// Builds the projector of every triangle of `surface`.
std::vector<TriangleProjector> make_projectors(const TriangleSurface& surface);

/// Squared distance from p to the segment a -> a + e (clamped), parameter t in [0, 1].
inline double squared_distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& e,
                                          double inv_len2, double& t) {
  t = std::clamp((p - a).dot(e) * inv_len2, 0.0, 1.0);
  return (p - a - t * e).squaredNorm();
}

/// Squared distance from p to the triangle (mm^2), the paper's procedure. When the projection
/// leaves the triangle only the edges opposite a negative coordinate can hold the closest point
/// (at a point interior to another edge, p - point would be that edge's outward in-plane normal
/// plus a multiple of n, which makes that edge's opposite coordinate negative), so only those
/// are tested; vertices are the clamped ends of the edges.
inline double squared_distance(const TriangleProjector& tp, const Vec3& p) {
  const Vec3 r = p - tp.x[0];
  const Vec3 s = tp.inverse * r;  // (T1, T2, D)
  const double t3 = 1.0 - s[0] - s[1];
  if (s[0] >= 0 && s[1] >= 0 && t3 >= 0) {
    return s[2] * s[2];
  }
  double best = std::numeric_limits<double>::infinity();
  double t;
  if (t3 < 0) {  // weight of x1 negative: edge x2 -> x3
    best = std::min(best,
                    squared_distance_to_segment(p, tp.x[1], tp.x[2] - tp.x[1], tp.inv_len2[1], t));
  }
  if (s[0] < 0) {  // weight of x2 negative: edge x3 -> x1
    best = std::min(best,
                    squared_distance_to_segment(p, tp.x[2], tp.x[0] - tp.x[2], tp.inv_len2[2], t));
  }
  if (s[1] < 0) {  // weight of x3 negative: edge x1 -> x2
    best = std::min(best,
                    squared_distance_to_segment(p, tp.x[0], tp.x[1] - tp.x[0], tp.inv_len2[0], t));
  }
  return best;
}

/// The same as `squared_distance`, also giving the closest point and its (T1, T2, T3).
double project(const TriangleProjector& tp, const Vec3& p, Vec3& point, Vec3& barycentric);

/// Tie tolerance: two distances are the same when they differ by at most
/// tie_relative * d + tie_absolute.
struct TieTolerance {
  double relative = 1e-12;
  double absolute = 0;  ///< 1e-12 * (surface size), set by `make_tie_tolerance`
  double window(double d) const { return d + relative * d + absolute; }
};

/// 1e-12 relative, and 1e-12 of the surface's size (the larger of its bounding-box diagonal and
/// its largest coordinate) absolute: the rounding error of a distance is ~ 2.2e-16 times the
/// coordinates' magnitude, some 4000 times below this, and 1e-12 of a tool's size is far below
/// any physical length (1e-10 mm for a 100 mm tool). The absolute part makes points ON a shared
/// edge or vertex (D = 0) form their tie set too.
TieTolerance make_tie_tolerance(const TriangleSurface& surface);

/// The triangles at the least distance found so far, within the tie tolerance. No allocation.
class TieSet {
 public:
  explicit TieSet(const TieTolerance& tol) : tol_(tol) {}
  double best() const { return best_; }
  /// Distances above this cannot join the set.
  double window() const { return tol_.window(best_); }
  /// Offers triangle t at distance d (mm).
  void offer(int t, double d) {
    if (d > window()) {
      return;
    }
    if (d < best_) {
      best_ = d;
      const double w = window();
      int kept = 0;
      for (int i = 0; i < size_; ++i) {
        if (dist_[i] <= w) {
          tri_[kept] = tri_[i];
          dist_[kept++] = dist_[i];
        }
      }
      size_ = kept;
    }
    for (int i = 0; i < size_; ++i) {
      if (tri_[i] == t) {
        return;  // a triangle met again in another grid cell
      }
    }
    if (size_ < ClosestPoint::max_set_size) {
      tri_[size_] = t;
      dist_[size_++] = d;
      return;
    }
    int worst = 0;
    for (int i = 1; i < size_; ++i) {
      if (dist_[i] > dist_[worst]) {
        worst = i;
      }
    }
    if (d < dist_[worst]) {
      lost_ = std::min(lost_, dist_[worst]);
      tri_[worst] = t;
      dist_[worst] = d;
    } else {
      lost_ = std::min(lost_, d);
    }
  }
  /// Whether a triangle that belongs to the set (within the window of the least distance) was
  /// dropped for want of room. Exact whatever the order of the offers: a triangle dropped while
  /// the least distance was larger counts only if it is still within the final window.
  bool truncated() const { return lost_ <= window(); }
  /// Fills `out` from the set (nothing within `cutoff` -> out.triangle = -1).
  void fill(const std::vector<TriangleProjector>& projectors, const TriangleSurface& surface,
            const Vec3& p, double cutoff, ClosestPoint& out) const;

 private:
  TieTolerance tol_;
  double best_ = std::numeric_limits<double>::infinity();
  std::array<int, ClosestPoint::max_set_size> tri_{};
  std::array<double, ClosestPoint::max_set_size> dist_{};
  int size_ = 0;
  double lost_ = std::numeric_limits<double>::infinity();  ///< least distance dropped, mm
};

}  // namespace sf::detail
