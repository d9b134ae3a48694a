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
  // Scalar code on the fixed-size input (no temporaries): this kernel runs twice per element and
  // cycle. The formulas are those of the comment above.
  const double d1x = x(0, 2) - x(0, 0), d1y = x(1, 2) - x(1, 0), d1z = x(2, 2) - x(2, 0);
  const double d2x = x(0, 3) - x(0, 1), d2y = x(1, 3) - x(1, 1), d2z = x(2, 3) - x(2, 1);
  const double s3x = d1y * d2z - d1z * d2y;
  const double s3y = d1z * d2x - d1x * d2z;
  const double s3z = d1x * d2y - d1y * d2x;
  const double n3 = std::sqrt(s3x * s3x + s3y * s3y + s3z * s3z);
  const double scale = d1x * d1x + d1y * d1y + d1z * d1z + d2x * d2x + d2y * d2y + d2z * d2z;
  if (!(n3 > 1e-10 * scale) || !std::isfinite(n3)) {
    return false;
  }
  const double inv_n3 = 1.0 / n3;
  const double e3x = s3x * inv_n3, e3y = s3y * inv_n3, e3z = s3z * inv_n3;
  double min_corner = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i) {
    const int ip = (i + 1) & 3;
    const int im = (i + 3) & 3;
    const double ax = x(0, ip) - x(0, i), ay = x(1, ip) - x(1, i), az = x(2, ip) - x(2, i);
    const double cx = x(0, im) - x(0, i), cy = x(1, im) - x(1, i), cz = x(2, im) - x(2, i);
    const double jac =
        (ay * cz - az * cy) * e3x + (az * cx - ax * cz) * e3y + (ax * cy - ay * cx) * e3z;
    min_corner = std::min(min_corner, jac);
  }
  g.min_corner = min_corner;
  if (!(min_corner > 1e-10 * scale)) {
    return false;
  }
  double s1x = x(0, 1) - x(0, 0), s1y = x(1, 1) - x(1, 0), s1z = x(2, 1) - x(2, 0);
  const double s1e3 = s1x * e3x + s1y * e3y + s1z * e3z;
  s1x -= s1e3 * e3x;
  s1y -= s1e3 * e3y;
  s1z -= s1e3 * e3z;
  const double inv_s1 = 1.0 / std::sqrt(s1x * s1x + s1y * s1y + s1z * s1z);
  const double e1x = s1x * inv_s1, e1y = s1y * inv_s1, e1z = s1z * inv_s1;
  const double e2x = e3y * e1z - e3z * e1y;
  const double e2y = e3z * e1x - e3x * e1z;
  const double e2z = e3x * e1y - e3y * e1x;
  g.frame << e1x, e2x, e3x, e1y, e2y, e3y, e1z, e2z, e3z;
  const double cx = 0.25 * (x(0, 0) + x(0, 1) + x(0, 2) + x(0, 3));
  const double cy = 0.25 * (x(1, 0) + x(1, 1) + x(1, 2) + x(1, 3));
  const double cz = 0.25 * (x(2, 0) + x(2, 1) + x(2, 2) + x(2, 3));
  double xh[4];
  double yh[4];
  for (int i = 0; i < 4; ++i) {
    const double px = x(0, i) - cx, py = x(1, i) - cy, pz = x(2, i) - cz;
    xh[i] = e1x * px + e1y * py + e1z * pz;
    yh[i] = e2x * px + e2y * py + e2z * pz;
    g.xy(0, i) = xh[i];
    g.xy(1, i) = yh[i];
  }
  // Belytschko, Lin & Tsay (1984); Hallquist, LS-DYNA Theory Manual (BLT shell): one-point B.
  const double two_a = (xh[2] - xh[0]) * (yh[3] - yh[1]) - (xh[3] - xh[1]) * (yh[2] - yh[0]);
  g.area = 0.5 * two_a;
  const double inv = 1.0 / two_a;
  g.b(0, 0) = (yh[1] - yh[3]) * inv;
  g.b(0, 1) = (yh[2] - yh[0]) * inv;
  g.b(0, 2) = (yh[3] - yh[1]) * inv;
  g.b(0, 3) = (yh[0] - yh[2]) * inv;
  g.b(1, 0) = (xh[3] - xh[1]) * inv;
  g.b(1, 1) = (xh[0] - xh[2]) * inv;
  g.b(1, 2) = (xh[1] - xh[3]) * inv;
  g.b(1, 3) = (xh[2] - xh[0]) * inv;
  // Flanagan & Belytschko (1981), hourglass base vectors: gamma is orthogonal to the linear fields
  // 1, x^, y^. h = (1, -1, 1, -1).
  const double hx = xh[0] - xh[1] + xh[2] - xh[3];
  const double hy = yh[0] - yh[1] + yh[2] - yh[3];
  for (int i = 0; i < 4; ++i) {
    const double h = (i & 1) ? -1.0 : 1.0;
    g.gamma(i) = h - hx * g.b(0, i) - hy * g.b(1, i);
  }
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
