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

}  // namespace sf
