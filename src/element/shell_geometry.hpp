#pragma once
// Corotational geometry of a 4-node Belytschko-Lin-Tsay shell: local frame, projected in-plane
// coordinates, one-point gradient operator and hourglass shape vector. Pure inline kernels.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/errors.hpp"
#include "core/types.hpp"

namespace sf {

using Quad2 = Eigen::Matrix<double, 2, 4>;
using Row4 = Eigen::Matrix<double, 1, 4>;

/// Geometry of one quad at one configuration.
struct ShellGeometry {
  Mat3 frame;         ///< columns e1, e2, e3 in global components
  Quad2 xy;           ///< nodal in-plane coordinates in the frame, about the centroid, mm
  Quad2 b;            ///< rows: dN_I/dx^, dN_I/dy^ at the element centre, 1/mm
  Row4 gamma;         ///< hourglass shape vector h - (h.x^) b_x - (h.y^) b_y, h = (1,-1,1,-1)
  double area;        ///< mm^2, area projected on the mid-plane = |x31 x x42| / 2
  double min_corner;  ///< smallest corner Jacobian (x_{I+1}-x_I) x (x_{I-1}-x_I) . e3, mm^2
};

/// Frame (Hallquist, LS-DYNA Theory Manual, Belytschko-Lin-Tsay shell): e3 = x31 x x42 / |.|,
/// e1 = the side x21 with its e3 component removed, normalised; e2 = e3 x e1. Returns false for a
/// collapsed or inverted element (a corner Jacobian <= 1e-10 (|x31|^2 + |x42|^2), i.e. the
/// bilinear map is not invertible) or non-finite coordinates; `g` is then unspecified.
inline bool compute_shell_geometry(const Quad3& x, ShellGeometry& g) {
  const Vec3 d1 = x.col(2) - x.col(0);
  const Vec3 d2 = x.col(3) - x.col(1);
  const Vec3 s3 = d1.cross(d2);
  const double n3 = s3.norm();
  const double scale = d1.squaredNorm() + d2.squaredNorm();
  if (!(n3 > 1e-10 * scale) || !std::isfinite(n3)) {
    return false;
  }
  const Vec3 e3 = s3 / n3;
  g.min_corner = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i) {
    const Vec3 a = x.col((i + 1) % 4) - x.col(i);
    const Vec3 c = x.col((i + 3) % 4) - x.col(i);
    g.min_corner = std::min(g.min_corner, a.cross(c).dot(e3));
  }
  if (!(g.min_corner > 1e-10 * scale)) {
    return false;
  }
  Vec3 s1 = x.col(1) - x.col(0);
  s1 -= s1.dot(e3) * e3;
  const Vec3 e1 = s1.normalized();
  g.frame.col(0) = e1;
  g.frame.col(1) = e3.cross(e1);
  g.frame.col(2) = e3;
  const Vec3 centroid = 0.25 * x.rowwise().sum();
  g.xy = g.frame.leftCols<2>().transpose() * (x.colwise() - centroid);
  const Row4 xh = g.xy.row(0);
  const Row4 yh = g.xy.row(1);
  // Belytschko, Lin & Tsay (1984); Hallquist, LS-DYNA Theory Manual (BLT shell): one-point B.
  const double two_a = (xh(2) - xh(0)) * (yh(3) - yh(1)) - (xh(3) - xh(1)) * (yh(2) - yh(0));
  g.area = 0.5 * two_a;
  const double inv = 1.0 / two_a;
  g.b(0, 0) = (yh(1) - yh(3)) * inv;
  g.b(0, 1) = (yh(2) - yh(0)) * inv;
  g.b(0, 2) = (yh(3) - yh(1)) * inv;
  g.b(0, 3) = (yh(0) - yh(2)) * inv;
  g.b(1, 0) = (xh(3) - xh(1)) * inv;
  g.b(1, 1) = (xh(0) - xh(2)) * inv;
  g.b(1, 2) = (xh(1) - xh(3)) * inv;
  g.b(1, 3) = (xh(2) - xh(0)) * inv;
  // Flanagan & Belytschko (1981), hourglass base vectors: gamma is orthogonal to the linear fields
  // 1, x^, y^.
  const Row4 h(1.0, -1.0, 1.0, -1.0);
  g.gamma = h - h.dot(xh) * g.b.row(0) - h.dot(yh) * g.b.row(1);
  return true;
}

/// Throws InstabilityError naming the element unless the geometry is valid.
inline void compute_shell_geometry_or_throw(const Quad3& x, int element, const char* when,
                                            ShellGeometry& g) {
  if (!compute_shell_geometry(x, g)) {
    throw InstabilityError("shell element " + std::to_string(element) +
                           ": inverted, collapsed or non-finite geometry (" + when + ")");
  }
}

/// Gathers the 4 nodal columns of element e from a 3 x n_nodes array.
inline Quad3 gather_quad(const Matrix3X& a, const QuadConn& quads, int e) {
  Quad3 q;
  for (int i = 0; i < 4; ++i) {
    q.col(i) = a.col(quads(i, e));
  }
  return q;
}

/// Rotational inertia factor alpha (mm^2): nodal rotational inertia = alpha x nodal mass. See
/// docs/element-and-material.md: alpha = (A + t^2) / 4 keeps every rotational frequency of the
/// element below its highest membrane frequency, so rotations never limit the time step.
inline double rotational_inertia_factor(double area, double thickness) {
  return 0.25 * (area + thickness * thickness);
}

}  // namespace sf
