#pragma once
// The "interpolated projection" of Wawrzyk & Kowalczyk ("Modified contact search algorithm for
// sheet metal forming"): after the search has picked the closest triangle (or tie set) of a tool
// surface, the point is projected onto the triangle ALONG the normal interpolated from the
// averaged nodal normals, which smooths the contact normal and gap as the point moves.
//
// On triangle (x1, x2, x3) with averaged nodal normals (N1, N2, N3), find (T1, T2, D) with
//   p = x(T) + D n(T),
//   x(T) = T3 x1 + T1 x2 + T2 x3,                     T3 = 1 - T1 - T2,
//   n(T) = m(T) / |m(T)|,  m(T) = T3 N1 + T1 N2 + T2 N3,
// by Newton's method from the orthogonal projection onto the triangle's plane.
#include <vector>

#include "contact/contact_search.hpp"
#include "contact/triangle_projection.hpp"
#include "core/types.hpp"
#include "mesh/triangle_surface.hpp"

namespace sf {

/// The interpolated projection of one point.
struct InterpolatedProjection {
  int triangle = -1;  ///< the triangle holding the solution (-1: no input triangle)
  /// (T1, T2, T3) of `point` in `triangle`, as ClosestPoint::barycentric (point = T3 x1 + T1 x2 +
  /// T2 x3); each >= -inside_tolerance unless `fallback`.
  Vec3 barycentric = Vec3::Zero();
  double distance = 0;          ///< signed D along `normal` (positive on the normal's side), mm
  Vec3 point = Vec3::Zero();    ///< x(T), the contact point on the surface, mm
  Vec3 normal = Vec3::UnitZ();  ///< n(T), the interpolated unit normal
  int iterations = 0;           ///< Newton iterations, summed over every triangle tried
  int triangles_tried = 0;      ///< triangles on which Newton was run
  /// No triangle of the set (nor of the walk) held a converged solution: the fields above are
  /// the ORTHOGONAL answer (ClosestPoint's triangle, barycentric, signed distance, point and
  /// normal).
  bool fallback = false;
};

/// Interpolated projection onto a rigid tool surface in its reference frame.
///
/// Treatment of tie sets and of solutions outside the triangle:
///  1. the triangles of ClosestPoint::set are tried in ASCENDING index order; the first whose
///     converged solution lies inside (every T >= -inside_tolerance) is accepted (so the answer
///     does not depend on the order of the set; at a shared edge or vertex the point, normal and
///     distance are the same on every triangle there, to round-off);
///  2. otherwise a walk starts from the set triangle whose solution was least outside (largest
///     smallest coordinate; Newton failures count as farthest outside; ties to the lower index):
///     it moves to the neighbour across the edge opposite the most negative coordinate
///     (TriangleSurface::triangle_neighbours) and solves there, at most `max_walk_steps` times,
///     never revisiting a triangle; it stops at a boundary edge, at a visited triangle (a cycle)
///     or when Newton fails;
///  3. then the triangles around the vertex nearest the walk's last solution (its largest
///     coordinate) not yet tried, ascending: near a vertex the solution may lie in a triangle of
///     the fan that the walk cannot reach (it steps back into a visited triangle);
///  4. if nothing is found (a point beyond the surface's boundary, a knife edge where the
///     interpolated normal vanishes, Newton not converging), the result is the orthogonal answer
///     with `fallback` set.
/// A flat region (all three nodal normals equal to the face normal) gives the orthogonal
/// projection to round-off, in zero Newton iterations.
class InterpolatedProjector {
 public:
  /// Residual tolerance factor: |x(T) + D n(T) - p| <= residual_relative * (tool size), the size
  /// as for the search's tie tolerance (the larger of the bounding-box diagonal and the largest
  /// coordinate). 1e-12 of the size is 1e-10 mm on a 100 mm tool: far below any physical length
  /// and below the penalty force's sensitivity (k * 1e-10 mm), yet some 4000 times above the
  /// round-off of the residual (~2.2e-16 times the coordinates), so Newton can always reach it.
  static constexpr double residual_relative = 1e-12;
  /// A solution lies inside a triangle when every barycentric coordinate is >= -1e-9. Newton
  /// stops with the coordinates accurate to ~ (residual tolerance) / (triangle height), i.e.
  /// better than 1e-10 for triangles down to 1 % of the tool size; 1e-9 of a triangle is an
  /// immaterial extrapolation of the smooth normal field, and it makes points exactly on an edge
  /// or vertex (coordinates ~ -1e-16) inside every triangle there.
  static constexpr double inside_tolerance = 1e-9;
  static constexpr int max_iterations = 16;  ///< Newton cap per triangle (quadratic: ~3 needed)
  static constexpr int max_walk_steps = 4;   ///< neighbour steps after the tie set

  /// `surface` must outlive the projector (and keep its geometry). Allocates the per-triangle
  /// data once.
  explicit InterpolatedProjector(const TriangleSurface& surface);

  /// Projects p (reference frame, mm) along the interpolated normal, starting from the
  /// search's answer `closest` (which must have closest.triangle >= 0). Does not allocate.
  void project(const Vec3& p, const ClosestPoint& closest, InterpolatedProjection& out) const;

  /// Newton on triangle t alone. On entry `solution` is ignored; on return (T1, T2, D) and
  /// whether the residual reached the tolerance. `iterations` is incremented per Newton update.
  bool solve_on_triangle(int t, const Vec3& p, Vec3& solution, int& iterations) const;

  /// The residual tolerance, mm.
  double tolerance() const { return tolerance_; }
  const TriangleSurface& surface() const { return *surface_; }

 private:
  const TriangleSurface* surface_;
  std::vector<detail::TriangleProjector> projectors_;
  double tolerance_ = 0;
};

}  // namespace sf
