#include "element/shell_material_axes.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "core/errors.hpp"
#include "element/element_block.hpp"
#include "element/shell_geometry.hpp"
#include "element/shell_triangle_geometry.hpp"

namespace sf {

namespace {

std::string format_point(const Vec3& p) {
  char buf[96];
  // + 0.0 turns -0 into 0 for the message.
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", p(0) + 0.0, p(1) + 0.0, p(2) + 0.0);
  return buf;
}

}  // namespace

namespace {

// The angle of the unit direction d in the plane of `frame` (columns e1, e2, e3), or an InputError
// naming the element when d is (nearly) normal to it.
double angle_in_frame(const Vec3& d, const Mat3& frame, const std::string& name) {
  const double d1 = d.dot(frame.col(0));
  const double d2 = d.dot(frame.col(1));
  const double in_plane = std::hypot(d1, d2);
  if (!(in_plane >= kMinRollingDirectionInPlane)) {
    char part[64];
    std::snprintf(part, sizeof part, "%.3g < %.3g", in_plane, kMinRollingDirectionInPlane);
    throw InputError(name + ": the rolling direction " + format_point(d) +
                     " is (nearly) normal to the element (its in-plane part is " + part +
                     " of its length; element normal " + format_point(frame.col(2)) +
                     "); give a direction in the sheet's plane");
  }
  return std::atan2(d2, d1);
}

Vec3 unit_direction(const Vec3& rolling_direction) {
  const double length = rolling_direction.norm();
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw InputError("rolling direction " + format_point(rolling_direction) +
                     ": expected a finite, non-zero vector");
  }
  return rolling_direction / length;
}

}  // namespace

std::vector<double> compute_material_angles(const Matrix3X& x, const QuadConn& quads,
                                            const Vec3& rolling_direction) {
  return compute_material_angles(x, quads, TriConn(3, 0), rolling_direction);
}

std::vector<double> compute_material_angles(const Matrix3X& x, const QuadConn& quads,
                                            const TriConn& triangles,
                                            const Vec3& rolling_direction) {
  const Vec3 d = unit_direction(rolling_direction);
  std::vector<double> angle(static_cast<std::size_t>(quads.cols() + triangles.cols()));
  for (const ElementBlock& block : element_blocks(quads, triangles)) {
    for (int e = block.first; e < block.end(); ++e) {
      const int k = block.local(e);
      const auto at = static_cast<std::size_t>(e);
      if (block.shape == ElementShape::quad) {
        const Quad3 xe = gather_quad(x, quads, k);
        const std::string name = "blank element " + std::to_string(e) + " (centroid " +
                                 format_point(0.25 * xe.rowwise().sum()) + " mm)";
        ShellGeometry g;
        if (!compute_shell_geometry(xe, g)) {
          throw InputError(name + ": inverted, collapsed or non-finite geometry");
        }
        angle[at] = angle_in_frame(d, g.frame, name);
        continue;
      }
      const Tri3 xe = gather_triangle(x, triangles, k);
      const std::string name = "blank element " + std::to_string(e) + " (triangle " +
                               std::to_string(k) + ", centroid " +
                               format_point(xe.rowwise().sum() / 3.0) + " mm)";
      TriangleGeometry g;
      if (!compute_triangle_geometry(xe, g)) {
        throw InputError(name + ": inverted, collapsed or non-finite geometry");
      }
      angle[at] = angle_in_frame(d, g.frame, name);
    }
  }
  return angle;
}

}  // namespace sf
