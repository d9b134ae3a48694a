#pragma once
// Small helpers shared by the shell element tests.
#include <cmath>

#include "element/shell_forces.hpp"
#include "element/shell_part.hpp"

namespace sf::test {

inline constexpr double kE = 210000.0;   // MPa, steel
inline constexpr double kNu = 0.3;       // -
inline constexpr double kRho = 7.85e-9;  // tonne/mm^3

inline ShellPart make_part(const QuadConn& quads, const Material& material, int n_points = 5,
                           double hourglass = 0.1) {
  ShellPart p;
  p.formulation = ShellFormulation::belytschko_tsay;  // the element of these tests
  p.quads = quads;
  p.section = make_gauss_section(n_points);
  p.materials[0].law = material;
  p.materials[0].density = kRho;
  p.hourglass_coefficient = hourglass;
  return p;
}

/// One internal-force pass with freshly zeroed force arrays.
struct StepOut {
  Matrix3X f, m;
  ShellForceResult r;
};
inline StepOut run_step(const ShellPart& part, const Matrix3X& x_end, const Matrix3X& v,
                        const Matrix3X& w, double dt, ShellState& st) {
  StepOut o{Matrix3X::Zero(3, x_end.cols()), Matrix3X::Zero(3, x_end.cols()), {}};
  o.r = compute_shell_internal_forces(part, x_end, v, w, dt, st, o.f, o.m);
  return o;
}

/// Rotation matrix by `angle` (rad) about the unit `axis`.
inline Mat3 rotation(const Vec3& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

/// The classic 5-element membrane patch (MacNeal & Harder 1985), 0.24 x 0.12 scaled by 100:
/// 24 x 12 mm, in the z = 0 plane. Nodes 4..7 are interior.
inline Matrix3X patch_nodes() {
  Matrix3X x(3, 8);
  x << 0.0, 24.0, 24.0, 0.0, 4.0, 18.0, 16.0, 8.0,  //
      0.0, 0.0, 12.0, 12.0, 2.0, 3.0, 8.0, 8.0,     //
      0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0;
  return x;
}
inline QuadConn patch_quads() {
  QuadConn q(4, 5);
  q << 0, 1, 2, 3, 4,  //
      1, 2, 3, 0, 5,   //
      5, 6, 7, 4, 6,   //
      4, 5, 6, 7, 7;
  return q;
}

/// A strip of n_el elements (len x b mm each) along x, bent cylindrically to curvature c (1/mm)
/// in one step: the displacement u and rotation phi of the exact constant-curvature field.
struct BentStrip {
  Matrix3X x0, u, phi;
  QuadConn quads;
};
inline BentStrip make_bent_strip(int n_el, double len, double b, double c) {
  BentStrip s;
  s.x0.resize(3, 2 * (n_el + 1));
  s.quads.resize(4, n_el);
  for (int i = 0; i <= n_el; ++i) {
    s.x0.col(2 * i) = Vec3(i * len, 0.0, 0.0);
    s.x0.col(2 * i + 1) = Vec3(i * len, b, 0.0);
  }
  for (int e = 0; e < n_el; ++e) {
    s.quads.col(e) << 2 * e, 2 * e + 2, 2 * e + 3, 2 * e + 1;
  }
  s.u = Matrix3X::Zero(3, s.x0.cols());
  s.phi = Matrix3X::Zero(3, s.x0.cols());
  for (int i = 0; i < s.x0.cols(); ++i) {
    s.u(2, i) = -0.5 * c * s.x0(0, i) * s.x0(0, i);
    s.phi(1, i) = c * s.x0(0, i);
  }
  return s;
}

}  // namespace sf::test
