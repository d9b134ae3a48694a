#include "contact/tool_distance_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/box_grid.hpp"
#include "contact/triangle_projection.hpp"

namespace sf {

ToolDistanceBound::ToolDistanceBound(const TriangleSurface& surface) : exact_(surface) {
  if (surface.num_nodes() > 0) {
    const Matrix3X& x = surface.nodes();
    lo_ = x.rowwise().minCoeff();
    hi_ = x.rowwise().maxCoeff();
    size_ = std::max((hi_ - lo_).norm(), x.cwiseAbs().maxCoeff());
  }
  const int nt = surface.num_triangles();
  agrees_.assign(static_cast<std::size_t>(nt), 0);
  for (int t = 0; t < nt; ++t) {
    const Vec3 n = surface.triangle_normals().col(t);
    bool agrees = true;
    for (int a = 0; a < 3; ++a) {
      agrees =
          agrees && surface.node_normals().col(surface.triangles()(a, t)).dot(n) > normal_agreement;
    }
    agrees_[static_cast<std::size_t>(t)] = agrees ? 1 : 0;
  }
}

double ToolDistanceBound::lower_bound(const Vec3& p, double reach) const {
  // Every point of the surface lies in its nodes' bounding box (triangles are convex hulls).
  const double box = std::sqrt(detail::squared_distance_to_box(p, lo_, hi_));
  if (!(box < reach)) {
    return box;
  }
  // The least distance within reach, nearest cells first; the bound shrinks to the best so far,
  // so the skipped triangles are all farther than the result.
  const std::vector<detail::TriangleProjector>& projectors = exact_.projectors();
  double best = reach;
  exact_.grid().visit(p, reach, [&](int t) {
    best = std::min(best, std::sqrt(detail::squared_distance(projectors[t], p)));
    return best;
  });
  return best;
}

FrontClearance ToolDistanceBound::front_clearance(const Vec3& p, double reach) const {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  FrontClearance out;
  out.nearest = infinity;
  out.least_side = infinity;
  out.sided = true;
  const double box = std::sqrt(detail::squared_distance_to_box(p, lo_, hi_));
  if (!(box < reach)) {
    out.distance = box;
    return out;
  }
  const std::vector<detail::TriangleProjector>& projectors = exact_.projectors();
  const Matrix3X& normals = exact_.surface().triangle_normals();
  int reference = -1;      // the face normal the cone is measured from
  double least_cos = 1.0;  // the least cosine between a face normal and the reference
  const double reach2 = reach * reach;
  exact_.grid().visit(p, reach, [&](int t) {
    const detail::TriangleProjector& tp = projectors[static_cast<std::size_t>(t)];
    const double d2 = detail::squared_distance(tp, p);
    if (d2 <= reach2) {
      out.nearest = std::min(out.nearest, std::sqrt(d2));
      // The third row of the kernel's inverse is the unit face normal: the plane's distance.
      out.least_side = std::min(out.least_side, tp.inverse.row(2).dot(p - tp.x[0]));
      out.sided = out.sided && agrees_[static_cast<std::size_t>(t)] != 0;
      if (reference < 0) {
        reference = t;
      }
      least_cos = std::min(least_cos, normals.col(t).dot(normals.col(reference)));
    }
    return reach;  // every triangle within reach, not only the nearest
  });
  out.distance = std::min(out.nearest, reach);
  // Each face normal lies within angle a/2 of the reference (cos(a/2) >= least_cos), so two lie
  // within a; a < 90 degrees needs cos(a/2) > cos(45 degrees). The cosine is rounded down a little
  // so that the sine is rounded up.
  const double c = least_cos - 1e-12;
  out.sided = out.sided && c > std::sqrt(0.5);
  out.cone_sine = out.sided ? 2.0 * c * std::sqrt(std::max(0.0, 1.0 - c * c)) : 1.0;
  return out;
}

}  // namespace sf
