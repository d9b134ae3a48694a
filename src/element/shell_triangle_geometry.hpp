#pragma once
// Corotational geometry of the 3-node C0 shell triangle: local frame, constant (CST) gradients
// and the DSG3 transverse shear operator. Pure inline kernels. See docs/element-and-material.md.
#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "core/types.hpp"

namespace sf {

using Row3 = Eigen::Matrix<double, 1, 3>;
using Shear23 = Eigen::Matrix<double, 2, 3>;  ///< rows: gamma_xz, gamma_yz; column per node

/// Geometry of one triangle at one configuration.
struct TriangleGeometry {
  Mat3 frame;  ///< columns e1, e2, e3 in global components
  Row3 bx;     ///< dN_I/dx^ (constant over the element), 1/mm
  Row3 by;     ///< dN_I/dy^, 1/mm
  /// DSG3 transverse shear operator in the frame: gamma = sw w + sx theta_x + sy theta_y, with w
  /// the nodal e3 displacements (sw in 1/mm) and theta the nodal rotations about e1, e2 (-).
  Shear23 sw;
  Shear23 sx;
  Shear23 sy;
  double area;           ///< mm^2
  double longest_side2;  ///< mm^2, square of the longest side
};

/// Frame: e3 = x21 x x31 / |.| (nodes counter-clockwise seen from +e3), e1 = x21 / |x21|,
/// e2 = e3 x e1. Returns false for a collapsed triangle (|x21 x x31| <= 1e-10 (sum of the squared
/// sides)) or non-finite coordinates; `g` is then unspecified.
///
/// Transverse shear: the discrete shear gap triangle DSG3 (K.-U. Bletzinger, M. Bischoff, E. Ramm,
/// A unified approach for shear-locking-free triangular and rectangular shell finite elements,
/// Computers & Structures 75 (2000) 321-334). With Mindlin kinematics gamma = grad w + beta,
/// beta = (theta_y, -theta_x), the shear gap of a side I -> J is the integral of gamma along it,
/// g_IJ = w_J - w_I + (beta_I + beta_J)/2 . (x_J - x_I), exact for linear w and beta. Taking node s
/// as origin, the gaps of its two sides give the covariant shear strains, hence the constant
/// Cartesian gamma_s = [x_ps^T; x_qs^T]^-1 (g_sp, g_sq). DSG3 depends on which node is s; the
/// three cyclic choices are averaged, gamma = (gamma_1 + gamma_2 + gamma_3) / 3, which makes the
/// element independent of the node numbering. Each gamma_s vanishes for every Kirchhoff mode
/// (quadratic w, beta = -grad w), so pure bending gives no shear strain and the thin element does
/// not lock.
inline bool compute_triangle_geometry(const Tri3& x, TriangleGeometry& g) {
  const Vec3 x21 = x.col(1) - x.col(0);
  const Vec3 x31 = x.col(2) - x.col(0);
  const Vec3 x32 = x.col(2) - x.col(1);
  const Vec3 s3 = x21.cross(x31);
  const double n3 = s3.norm();
  const double l21 = x21.squaredNorm();
  const double l31 = x31.squaredNorm();
  const double l32 = x32.squaredNorm();
  if (!(n3 > 1e-10 * (l21 + l31 + l32)) || !std::isfinite(n3)) {
    return false;
  }
  const Vec3 e3 = s3 / n3;
  const Vec3 e1 = x21 / std::sqrt(l21);
  const Vec3 e2 = e3.cross(e1);
  g.frame.col(0) = e1;
  g.frame.col(1) = e2;
  g.frame.col(2) = e3;
  g.area = 0.5 * n3;
  g.longest_side2 = std::max({l21, l31, l32});
  // In-plane coordinates about node 1: (0, 0), (|x21|, 0), (x31.e1, x31.e2).
  const double xh[3] = {0.0, e1.dot(x21), e1.dot(x31)};
  const double yh[3] = {0.0, 0.0, e2.dot(x31)};
  const double inv_2a = 1.0 / n3;
  g.bx << (yh[1] - yh[2]) * inv_2a, (yh[2] - yh[0]) * inv_2a, (yh[0] - yh[1]) * inv_2a;
  g.by << (xh[2] - xh[1]) * inv_2a, (xh[0] - xh[2]) * inv_2a, (xh[1] - xh[0]) * inv_2a;
  // DSG3, averaged over the three cyclic choices of the origin node s (p, q the next two).
  g.sw.setZero();
  g.sx.setZero();
  g.sy.setZero();
  const double w_avg = inv_2a / 3.0;
  for (int s = 0; s < 3; ++s) {
    const int p = (s + 1) % 3;
    const int q = (s + 2) % 3;
    const double a = xh[p] - xh[s], b = yh[p] - yh[s];  // x_ps
    const double c = xh[q] - xh[s], d = yh[q] - yh[s];  // x_qs; a d - b c = 2A
    // gamma_s = ( d g_sp - b g_sq, -c g_sp + a g_sq ) / 2A. The gap g_sp has the coefficients
    // w_p: 1, w_s: -1, theta_x (s and p): -b/2, theta_y (s and p): a/2 (beta . x_ps); g_sq the
    // same with (c, d) and node q.
    const double cx_sp = d * w_avg, cy_sp = -c * w_avg;  // weights of g_sp in gamma_x, gamma_y
    const double cx_sq = -b * w_avg, cy_sq = a * w_avg;  // weights of g_sq
    g.sw(0, p) += cx_sp;
    g.sw(1, p) += cy_sp;
    g.sw(0, q) += cx_sq;
    g.sw(1, q) += cy_sq;
    g.sw(0, s) -= cx_sp + cx_sq;
    g.sw(1, s) -= cy_sp + cy_sq;
    for (int node : {s, p}) {
      g.sx(0, node) -= 0.5 * b * cx_sp;
      g.sx(1, node) -= 0.5 * b * cy_sp;
      g.sy(0, node) += 0.5 * a * cx_sp;
      g.sy(1, node) += 0.5 * a * cy_sp;
    }
    for (int node : {s, q}) {
      g.sx(0, node) -= 0.5 * d * cx_sq;
      g.sx(1, node) -= 0.5 * d * cy_sq;
      g.sy(0, node) += 0.5 * c * cx_sq;
      g.sy(1, node) += 0.5 * c * cy_sq;
    }
  }
  return true;
}

/// Throws InstabilityError naming the element (its index in the part's state, quads first, and
/// its triangle index) unless the geometry is valid.
inline void compute_triangle_geometry_or_throw(const Tri3& x, int element, int triangle,
                                               const char* when, TriangleGeometry& g) {
  if (!compute_triangle_geometry(x, g)) {
    throw InstabilityError("shell element " + std::to_string(element) + " (triangle " +
                           std::to_string(triangle) + "): collapsed or non-finite geometry (" +
                           when + ")");
  }
}

/// Gathers the 3 nodal columns of triangle k from a 3 x n_nodes array.
inline Tri3 gather_triangle(const Matrix3X& a, const TriConn& triangles, int k) {
  Tri3 t;
  for (int i = 0; i < 3; ++i) {
    t.col(i) = a.col(triangles(i, k));
  }
  return t;
}

/// Characteristic length of a triangle for the stable time step (mm): the smallest altitude,
/// 2 A / longest side (the LS-DYNA shell length (1 + beta) A / max side with beta = 1 for
/// triangles). See docs/element-and-material.md for the stability margin it leaves.
inline double triangle_characteristic_length(const TriangleGeometry& g) {
  return 2.0 * g.area / std::sqrt(g.longest_side2);
}

/// Lyly-Stenberg-Vihinen shear stabilisation constant alpha (-): the transverse shear modulus is
/// scaled by t^2 / (t^2 + alpha h^2), h the longest side (M. Lyly, R. Stenberg, T. Vihinen, A
/// stable bilinear element for the Reissner-Mindlin plate model, CMAME 110 (1993) 343-357).
inline constexpr double kTriangleShearStabilisation = 0.1;

/// The factor t^2 / (t^2 + alpha h^2) (-) for thickness t (mm) and squared longest side h2 (mm^2).
inline double triangle_shear_factor(double thickness, double longest_side2) {
  const double t2 = thickness * thickness;
  return t2 / (t2 + kTriangleShearStabilisation * longest_side2);
}

}  // namespace sf
