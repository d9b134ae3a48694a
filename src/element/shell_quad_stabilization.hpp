#pragma once
// Physical stabilisation of the one-point quadrilateral shell (formulation assumed_strain): the
// strain fields that one-point quadrature misses, taken from assumed-strain elements and
// integrated exactly over the element with the Jacobian at its centre, at the material's elastic
// moduli. Pure inline kernels. Derivation and references: docs/element-and-material.md,
// "Formulation assumed_strain".
//
// Every nodal field u_I of a quad splits into a linear field and an hourglass part,
// u_I = u_0 + (B_x.u) x_I + (B_y.u) y_I + (gamma.u / 4) h_I, h = (1, -1, 1, -1), and h interpolates
// to xi eta (gamma: shell_geometry.hpp). So the hourglass part of a field is (q / 4) xi eta with
// q = gamma.u, and its gradient is (q / 4)(eta grad xi + xi grad eta).
#include <cmath>

#include "core/types.hpp"
#include "element/shell_geometry.hpp"
#include "element/shell_quad_directors.hpp"

namespace sf {

/// Stiffnesses of the stabilisation resultants of one element.
struct StabilizationStiffness {
  /// N/mm, on the membrane hourglass amplitudes q_m = (gamma.u_x, gamma.u_y) (mm): the
  /// quintessential-bending strain of the xi and eta fibres, (q_m . g_xi) eta / (4 |g_xi|^2) and
  /// likewise, integrated at Young's modulus (exact in-plane bending of a rectangle, no parasitic
  /// shear; Belytschko & Bindeman 1993): E t A / 48 sum g g^T / |g|^4.
  Mat2 membrane;
  /// N mm, on the rotation hourglass amplitudes q_b = (gamma.beta_x, gamma.beta_y) (rad), beta =
  /// (theta_y, -theta_x): the curvature of that field integrated with the plate modulus D (full
  /// integration of the bending, as the MITC4 shell).
  Mat2 bending;
  /// N/mm, on the differences of the MITC4 covariant transverse shears of opposite edges,
  /// (e_A - e_C, e_B - e_D) (mm): the linear part of the assumed shear, integrated at k G t.
  Vec2 shear;
};

/// Of the basis b in the frame (e1, e2) (its Cartesian map c); young (MPa), poisson (-),
/// thickness (mm), shear_modulus: k G with the shear correction factor (MPa).
inline StabilizationStiffness compute_stabilization_stiffness(const QuadBasis& b,
                                                              const CartesianMap& c,
                                                              const Mat3& frame, double young,
                                                              double poisson, double thickness,
                                                              double shear_modulus) {
  StabilizationStiffness k;
  const double area = b.area;
  const Vec2 g_xi(b.g_xi.dot(frame.col(0)), b.g_xi.dot(frame.col(1)));
  const Vec2 g_eta(b.g_eta.dot(frame.col(0)), b.g_eta.dot(frame.col(1)));
  const double g_xi2 = g_xi.squaredNorm();
  const double g_eta2 = g_eta.squaredNorm();
  k.membrane = (young * thickness * area / 48.0) * (g_xi * g_xi.transpose() / (g_xi2 * g_xi2) +
                                                    g_eta * g_eta.transpose() / (g_eta2 * g_eta2));
  // Curvature of beta = (q / 4) xi eta: kappa = eta K(grad xi) q + xi K(grad eta) q, with
  // K(p) q = -(p_x q_x, p_y q_y, p_y q_x + p_x q_y) / 4; int xi^2 = int eta^2 = A / 3, int xi eta =
  // 0.
  const double plate =
      young * thickness * thickness * thickness / (12.0 * (1.0 - poisson * poisson));
  const double twist = 0.5 * (1.0 - poisson);
  auto curvature_form = [&](const Vec2& p) {
    Mat2 f;
    f << p(0) * p(0) + twist * p(1) * p(1), (poisson + twist) * p(0) * p(1),  //
        (poisson + twist) * p(0) * p(1), p(1) * p(1) + twist * p(0) * p(0);
    return f;
  };
  k.bending = (plate * area / 48.0) * (curvature_form(c.p) + curvature_form(c.r));
  // Shear (e_xi, e_eta) = centre + (eta (e_A - e_C), xi (e_B - e_D)) / 2; gamma = grad xi e_xi +
  // grad eta e_eta: the linear part's energy is k G t A / 24 (|grad xi|^2 d_xi^2 + ...).
  k.shear = (shear_modulus * thickness * area / 12.0) *
            Vec2(b.grad_xi.squaredNorm(), b.grad_eta.squaredNorm());
  return k;
}

}  // namespace sf
