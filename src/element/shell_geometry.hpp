#pragma once
// Corotational geometry of a 4-node Belytschko-Lin-Tsay shell: local frame, projected in-plane
// coordinates, one-point gradient operator and hourglass shape vector. Pure inline kernels.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include "core/errors.hpp"
#include "core/simd_block.hpp"
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

/// The geometry of one quad (T = double) or of a block of quads, one per lane (T = Block,
/// core/simd_block.hpp), as plain values: the same operations for both, so every lane of a block
/// gets the bits of the one-element computation.
template <class T>
struct GeometryLanes {
  T e1[3], e2[3], e3[3];  ///< frame
  T xh[4], yh[4];         ///< in-plane nodal coordinates about the centroid, mm
  T area;                 ///< mm^2
  T b[2][4];              ///< one-point gradient, 1/mm
  T gamma[4];             ///< hourglass shape vector
  T min_corner;           ///< mm^2
};

namespace detail {
inline bool lanes_isfinite(double v) {
  return std::isfinite(v);
}
inline double lanes_sqrt(double v) {
  return std::sqrt(v);
}
inline double lanes_min(double a, double b) {
  return std::min(a, b);
}
SF_BLOCK_INLINE BlockMask lanes_isfinite(const Block& v) {
  return block_isfinite(v);
}
SF_BLOCK_INLINE Block lanes_sqrt(const Block& v) {
  return block_sqrt(v);
}
SF_BLOCK_INLINE Block lanes_min(const Block& a, const Block& b) {
  return block_min(a, b);
}
}  // namespace detail

/// Frame (Hallquist, LS-DYNA Theory Manual, Belytschko-Lin-Tsay shell): e3 = x31 x x42 / |.|,
/// e1 = the side x21 with its e3 component removed, normalised; e2 = e3 x e1. Returns false (per
/// lane) for a collapsed or inverted element (a corner Jacobian <= 1e-10 (|x31|^2 + |x42|^2),
/// i.e. the bilinear map is not invertible) or non-finite coordinates; `g` is then unspecified.
/// x[c][i]: component c of node i.
template <class T>
SF_BLOCK_INLINE auto compute_geometry_lanes(const T (&x)[3][4], GeometryLanes<T>& g) {
  using detail::lanes_isfinite;
  using detail::lanes_min;
  using detail::lanes_sqrt;
  // Scalar code on the fixed-size input (no temporaries): this kernel runs twice per element and
  // cycle. The formulas are those of the comment above.
  const T d1x = x[0][2] - x[0][0], d1y = x[1][2] - x[1][0], d1z = x[2][2] - x[2][0];
  const T d2x = x[0][3] - x[0][1], d2y = x[1][3] - x[1][1], d2z = x[2][3] - x[2][1];
  const T s3x = d1y * d2z - d1z * d2y;
  const T s3y = d1z * d2x - d1x * d2z;
  const T s3z = d1x * d2y - d1y * d2x;
  const T n3 = lanes_sqrt(s3x * s3x + s3y * s3y + s3z * s3z);
  const T scale = d1x * d1x + d1y * d1y + d1z * d1z + d2x * d2x + d2y * d2y + d2z * d2z;
  const auto normal_ok = (n3 > 1e-10 * scale) & lanes_isfinite(n3);
  const T inv_n3 = 1.0 / n3;
  const T e3x = s3x * inv_n3, e3y = s3y * inv_n3, e3z = s3z * inv_n3;
  T min_corner = T{} + std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i) {
    const int ip = (i + 1) & 3;
    const int im = (i + 3) & 3;
    const T ax = x[0][ip] - x[0][i], ay = x[1][ip] - x[1][i], az = x[2][ip] - x[2][i];
    const T cx = x[0][im] - x[0][i], cy = x[1][im] - x[1][i], cz = x[2][im] - x[2][i];
    const T jac = (ay * cz - az * cy) * e3x + (az * cx - ax * cz) * e3y + (ax * cy - ay * cx) * e3z;
    min_corner = lanes_min(min_corner, jac);
  }
  g.min_corner = min_corner;
  const auto ok = normal_ok & (min_corner > 1e-10 * scale);
  T s1x = x[0][1] - x[0][0], s1y = x[1][1] - x[1][0], s1z = x[2][1] - x[2][0];
  const T s1e3 = s1x * e3x + s1y * e3y + s1z * e3z;
  s1x -= s1e3 * e3x;
  s1y -= s1e3 * e3y;
  s1z -= s1e3 * e3z;
  const T inv_s1 = 1.0 / lanes_sqrt(s1x * s1x + s1y * s1y + s1z * s1z);
  const T e1x = s1x * inv_s1, e1y = s1y * inv_s1, e1z = s1z * inv_s1;
  const T e2x = e3y * e1z - e3z * e1y;
  const T e2y = e3z * e1x - e3x * e1z;
  const T e2z = e3x * e1y - e3y * e1x;
  g.e1[0] = e1x, g.e1[1] = e1y, g.e1[2] = e1z;
  g.e2[0] = e2x, g.e2[1] = e2y, g.e2[2] = e2z;
  g.e3[0] = e3x, g.e3[1] = e3y, g.e3[2] = e3z;
  const T cx = 0.25 * (x[0][0] + x[0][1] + x[0][2] + x[0][3]);
  const T cy = 0.25 * (x[1][0] + x[1][1] + x[1][2] + x[1][3]);
  const T cz = 0.25 * (x[2][0] + x[2][1] + x[2][2] + x[2][3]);
  T* xh = g.xh;
  T* yh = g.yh;
  for (int i = 0; i < 4; ++i) {
    const T px = x[0][i] - cx, py = x[1][i] - cy, pz = x[2][i] - cz;
    xh[i] = e1x * px + e1y * py + e1z * pz;
    yh[i] = e2x * px + e2y * py + e2z * pz;
  }
  // Belytschko, Lin & Tsay (1984); Hallquist, LS-DYNA Theory Manual (BLT shell): one-point B.
  const T two_a = (xh[2] - xh[0]) * (yh[3] - yh[1]) - (xh[3] - xh[1]) * (yh[2] - yh[0]);
  g.area = 0.5 * two_a;
  const T inv = 1.0 / two_a;
  g.b[0][0] = (yh[1] - yh[3]) * inv;
  g.b[0][1] = (yh[2] - yh[0]) * inv;
  g.b[0][2] = (yh[3] - yh[1]) * inv;
  g.b[0][3] = (yh[0] - yh[2]) * inv;
  g.b[1][0] = (xh[3] - xh[1]) * inv;
  g.b[1][1] = (xh[0] - xh[2]) * inv;
  g.b[1][2] = (xh[1] - xh[3]) * inv;
  g.b[1][3] = (xh[2] - xh[0]) * inv;
  // Flanagan & Belytschko (1981), hourglass base vectors: gamma is orthogonal to the linear fields
  // 1, x^, y^. h = (1, -1, 1, -1).
  const T hx = xh[0] - xh[1] + xh[2] - xh[3];
  const T hy = yh[0] - yh[1] + yh[2] - yh[3];
  for (int i = 0; i < 4; ++i) {
    const double h = (i & 1) ? -1.0 : 1.0;
    g.gamma[i] = h - hx * g.b[0][i] - hy * g.b[1][i];
  }
  return ok;
}

/// Lane `j` of `lanes` (the value itself for T = double) as a ShellGeometry.
template <class T>
SF_BLOCK_INLINE void unpack_geometry(const GeometryLanes<T>& lanes, int j, ShellGeometry& g) {
  const auto at = [=](const T& v) {  // (j unused for T = double)
    if constexpr (std::is_same_v<T, double>) {
      return v;
    } else {
      return static_cast<double>(v[j]);
    }
  };
  g.frame << at(lanes.e1[0]), at(lanes.e2[0]), at(lanes.e3[0]), at(lanes.e1[1]), at(lanes.e2[1]),
      at(lanes.e3[1]), at(lanes.e1[2]), at(lanes.e2[2]), at(lanes.e3[2]);
  for (int i = 0; i < 4; ++i) {
    g.xy(0, i) = at(lanes.xh[i]);
    g.xy(1, i) = at(lanes.yh[i]);
    g.b(0, i) = at(lanes.b[0][i]);
    g.b(1, i) = at(lanes.b[1][i]);
    g.gamma(i) = at(lanes.gamma[i]);
  }
  g.area = at(lanes.area);
  g.min_corner = at(lanes.min_corner);
}

/// The geometry of one quad (see compute_geometry_lanes); false for an invalid element.
inline bool compute_shell_geometry(const Quad3& x, ShellGeometry& g) {
  double xs[3][4];
  for (int i = 0; i < 4; ++i) {
    for (int c = 0; c < 3; ++c) {
      xs[c][i] = x(c, i);
    }
  }
  GeometryLanes<double> lanes;
  const bool ok = compute_geometry_lanes(xs, lanes);
  unpack_geometry(lanes, 0, g);
  return ok;
}

[[noreturn]] inline void throw_invalid_geometry(int element, const char* when) {
  throw InstabilityError("shell element " + std::to_string(element) +
                         ": inverted, collapsed or non-finite geometry (" + when + ")");
}

/// Throws InstabilityError naming the element unless the geometry is valid.
inline void compute_shell_geometry_or_throw(const Quad3& x, int element, const char* when,
                                            ShellGeometry& g) {
  if (!compute_shell_geometry(x, g)) {
    throw_invalid_geometry(element, when);
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
