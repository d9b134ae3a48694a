#include "element/shell_material_axes.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "core/errors.hpp"
#include "element/shell_geometry.hpp"

namespace sf {

namespace {

std::string format_point(const Vec3& p) {
  char buf[96];
  // + 0.0 turns -0 into 0 for the message.
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", p(0) + 0.0, p(1) + 0.0, p(2) + 0.0);
  return buf;
}

}  // namespace

std::vector<double> compute_material_angles(const Matrix3X& x, const QuadConn& quads,
                                            const Vec3& rolling_direction) {
  const double length = rolling_direction.norm();
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw InputError("rolling direction " + format_point(rolling_direction) +
                     ": expected a finite, non-zero vector");
  }
  const Vec3 d = rolling_direction / length;
  std::vector<double> angle(static_cast<std::size_t>(quads.cols()));
  for (Eigen::Index e = 0; e < quads.cols(); ++e) {
    const Quad3 xe = gather_quad(x, quads, static_cast<int>(e));
    const std::string name = "blank element " + std::to_string(e) + " (centroid " +
                             format_point(0.25 * xe.rowwise().sum()) + " mm)";
    ShellGeometry g;
    if (!compute_shell_geometry(xe, g)) {
      throw InputError(name + ": inverted, collapsed or non-finite geometry");
    }
    const double d1 = d.dot(g.frame.col(0));
    const double d2 = d.dot(g.frame.col(1));
    const double in_plane = std::hypot(d1, d2);
    if (!(in_plane >= kMinRollingDirectionInPlane)) {
      char part[64];
      std::snprintf(part, sizeof part, "%.3g < %.3g", in_plane, kMinRollingDirectionInPlane);
      throw InputError(name + ": the rolling direction " + format_point(d) +
                       " is (nearly) normal to the element (its in-plane part is " + part +
                       " of its length; element normal " + format_point(g.frame.col(2)) +
                       "); give a direction in the sheet's plane");
    }
    angle[static_cast<std::size_t>(e)] = std::atan2(d2, d1);
  }
  return angle;
}

}  // namespace sf
