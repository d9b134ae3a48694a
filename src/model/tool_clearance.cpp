#include "model/tool_clearance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace sf {
namespace {

// The distance s >= 0 along unit d from p to the triangle (a, b, c) (Moller and Trumbore 1997),
// or +inf when the ray misses it.
double ray_to_triangle(const Vec3& p, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a;
  const Vec3 e2 = c - a;
  const Vec3 h = d.cross(e2);
  const double det = e1.dot(h);
  const double scale = e1.norm() * e2.norm();
  if (std::abs(det) <= 1e-12 * scale) {
    return std::numeric_limits<double>::infinity();  // the ray runs along the triangle's plane
  }
  const Vec3 q = p - a;
  const double u = q.dot(h) / det;
  const Vec3 r = q.cross(e1);
  const double v = d.dot(r) / det;
  constexpr double slack = 1e-9;  // a ray through an edge or a vertex counts
  if (u < -slack || v < -slack || u + v > 1.0 + slack) {
    return std::numeric_limits<double>::infinity();
  }
  const double s = e2.dot(r) / det;
  return s >= 0.0 ? s : std::numeric_limits<double>::infinity();
}

// The least distance along d from any node of `from` to any triangle of `to`; each triangle's
// bounding box in the plane across d screens it out first.
double least_ray_distance(const TriangleSurface& from, const TriangleSurface& to, const Vec3& d) {
  const Vec3 e1 = d.unitOrthogonal();
  const Vec3 e2 = d.cross(e1);
  const Matrix3X& x = to.nodes();
  const TriConn& tri = to.triangles();
  std::vector<std::array<double, 4>> boxes(static_cast<std::size_t>(tri.cols()));
  for (Eigen::Index t = 0; t < tri.cols(); ++t) {
    auto& box = boxes[static_cast<std::size_t>(t)];
    box = {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    for (int k = 0; k < 3; ++k) {
      const Vec3 y = x.col(tri(k, t));
      box[0] = std::min(box[0], y.dot(e1));
      box[1] = std::max(box[1], y.dot(e1));
      box[2] = std::min(box[2], y.dot(e2));
      box[3] = std::max(box[3], y.dot(e2));
    }
  }
  double least = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < from.nodes().cols(); ++i) {
    const Vec3 p = from.nodes().col(i);
    const double u = p.dot(e1);
    const double w = p.dot(e2);
    for (Eigen::Index t = 0; t < tri.cols(); ++t) {
      const auto& box = boxes[static_cast<std::size_t>(t)];
      const double pad = 1e-9 * (1.0 + std::abs(u) + std::abs(w));
      if (u < box[0] - pad || u > box[1] + pad || w < box[2] - pad || w > box[3] + pad) {
        continue;
      }
      least = std::min(least,
                       ray_to_triangle(p, d, x.col(tri(0, t)), x.col(tri(1, t)), x.col(tri(2, t))));
    }
  }
  return least;
}

}  // namespace

std::optional<double> clearance_along(const TriangleSurface& moving, const TriangleSurface& other,
                                      const Vec3& direction) {
  const Vec3 d = direction.normalized();
  const double least =
      std::min(least_ray_distance(moving, other, d), least_ray_distance(other, moving, -d));
  if (!std::isfinite(least)) {
    return std::nullopt;
  }
  return least;
}

}  // namespace sf
