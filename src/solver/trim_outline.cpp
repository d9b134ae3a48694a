#include "solver/trim_outline.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "mesh/box_tree.hpp"

namespace sf {
namespace {

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// Distance from p to the triangle abc in the plane (0 inside); a triangle of no area (a tool's
// wall seen along the direction) is its edges.
double triangle_distance(const Vec2& p, const std::array<Vec2, 3>& t) {
  const double area = cross(t[1] - t[0], t[2] - t[0]);
  if (area != 0.0) {
    const double s = area > 0.0 ? 1.0 : -1.0;
    if (s * cross(t[1] - t[0], p - t[0]) >= 0.0 && s * cross(t[2] - t[1], p - t[1]) >= 0.0 &&
        s * cross(t[0] - t[2], p - t[2]) >= 0.0) {
      return 0.0;
    }
  }
  return std::min({segment_distance(p, t[0], t[1]), segment_distance(p, t[1], t[2]),
                   segment_distance(p, t[2], t[0])});
}

}  // namespace

TrimRegion::TrimRegion(const TrimOutline& outline, const std::string& source)
    : keep_inside_(outline.keep_inside), offset_(outline.offset) {
  const double length = outline.direction.norm();
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw InputError(source + ": a trim line needs a direction of projection of nonzero length");
  }
  const Vec3 d = outline.direction / length;
  e1_ = d.unitOrthogonal();
  e2_ = d.cross(e1_);
  if (outline.points.empty()) {
    if (outline.tool_triangles.empty() || !(outline.offset >= 0.0)) {
      throw InputError(fmt::format(
          "{}: a trim by a tool's outline needs the tool's triangles ({} given) and an offset >= "
          "0 mm ({:g} given)",
          source, outline.tool_triangles.size(), outline.offset));
    }
    std::vector<Vec3> lo, hi;
    for (const Tri3& t : outline.tool_triangles) {
      const std::array<Vec2, 3> p{project(t.col(0)), project(t.col(1)), project(t.col(2))};
      triangles_.push_back(p);
      const Vec2 low = p[0].cwiseMin(p[1]).cwiseMin(p[2]);
      const Vec2 high = p[0].cwiseMax(p[1]).cwiseMax(p[2]);
      lo.emplace_back(low.x(), low.y(), 0.0);
      hi.emplace_back(high.x(), high.y(), 0.0);
    }
    tree_ = std::make_unique<BoxTree>(std::move(lo), std::move(hi));
    return;
  }
  if (outline.points.size() < 3) {
    throw InputError(
        fmt::format("{}: a trim line needs a closed polyline of at least 3 points, got {}", source,
                    outline.points.size()));
  }
  double area = 0.0;  // shoelace, across the direction
  for (const Vec3& p : outline.points) {
    polyline_.push_back(project(p));
  }
  for (std::size_t i = 0, j = polyline_.size() - 1; i < polyline_.size(); j = i++) {
    area += cross(polyline_[j], polyline_[i]);
  }
  if (!(std::abs(area) > 0.0)) {
    throw InputError(fmt::format(
        "{}: the trim line encloses no area seen along the direction ({:g}, {:g}, {:g})", source,
        d.x(), d.y(), d.z()));
  }
}

TrimRegion::~TrimRegion() = default;

bool TrimRegion::inside(const Vec2& p) const {
  return polyline_.empty() ? near_tool(p) : inside_polyline(p);
}

// Even-odd rule: a ray along +e1 from p crosses the polyline an odd number of times.
bool TrimRegion::inside_polyline(const Vec2& p) const {
  bool inside = false;
  for (std::size_t i = 0, j = polyline_.size() - 1; i < polyline_.size(); j = i++) {
    const Vec2& a = polyline_[i];
    const Vec2& b = polyline_[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) {
        inside = !inside;
      }
    }
  }
  return inside;
}

// Within the offset of a projected triangle of the tool.
bool TrimRegion::near_tool(const Vec2& p) const {
  const Vec3 q(p.x(), p.y(), 0.0);
  bool near = false;
  tree_->visit(q, q, offset_, [&](int k) {
    near = triangle_distance(p, triangles_[static_cast<std::size_t>(k)]) <= offset_;
    return near ? -1.0 : offset_;
  });
  return near;
}

}  // namespace sf
