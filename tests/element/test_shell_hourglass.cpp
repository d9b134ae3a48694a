// Hourglass control of the Belytschko-Lin-Tsay shell, viscous and stiffness forms: a pure hourglass
// mode is resisted, the stiffness form's force is linear in the hourglass displacement and vanishes
// for rigid motion and for a constant-strain (patch) field.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "element/shell_output.hpp"
#include "element/shell_test_support.hpp"

namespace sf {
namespace {

using test::kE;
using test::kNu;
using test::run_step;

QuadConn single_quad() {
  QuadConn q(4, 1);
  q << 0, 1, 2, 3;
  return q;
}

ShellPart make_hourglass_part(const QuadConn& q, int n_points, HourglassForm form) {
  ShellPart part = test::make_part(q, ElasticPlaneStress{kE, kNu}, n_points, 0.1);
  part.hourglass_form = form;
  return part;
}

// 5 x 5 mm square in the z = 0 plane and the pure hourglass velocity field v = h V (in-plane,
// out-of-plane and rotations), h = (1, -1, 1, -1).
Matrix3X square() {
  Matrix3X x(3, 4);
  x << 0, 5, 5, 0, 0, 0, 5, 5, 0, 0, 0, 0;
  return x;
}
void hourglass_field(Matrix3X& v, Matrix3X& w) {
  const Eigen::RowVector4d h(1, -1, 1, -1);
  v.resize(3, 4);
  w.resize(3, 4);
  v.row(0) = 300.0 * h;
  v.row(1) = -200.0 * h;
  v.row(2) = 500.0 * h;
  w.row(0) = 40.0 * h;
  w.row(1) = 70.0 * h;
  w.row(2).setZero();
}

TEST(ShellHourglass, PureHourglassModeIsResistedByBothForms) {
  // 10 steps of the pure hourglass velocity on a square (no strain: B h = 0): every hourglass
  // component meets a force opposing it (f_int . v > 0 per mode), and the accumulated hourglass
  // energy sum dt P is positive. The membrane and bending stresses stay zero.
  const Matrix3X x0 = square();
  Matrix3X v;
  Matrix3X w;
  hourglass_field(v, w);
  const double dt = 1e-7;
  for (HourglassForm form : {HourglassForm::viscous, HourglassForm::stiffness}) {
    const ShellPart part = make_hourglass_part(single_quad(), 5, form);
    ShellState st = make_shell_state(1, 5, 1.0);
    double energy = 0.0;
    test::StepOut o;
    for (int n = 1; n <= 10; ++n) {
      o = run_step(part, x0 + n * dt * v, v, w, dt, st);
      energy += o.r.hourglass_work;
    }
    for (int k = 0; k < 5; ++k) {
      EXPECT_LT(std::abs(st.sxx[k]) + std::abs(st.syy[k]) + std::abs(st.sxy[k]), 1e-6);
    }
    for (int r = 0; r < 3; ++r) {
      EXPECT_GT(o.f.row(r).dot(v.row(r)), 0.0) << static_cast<int>(form) << " f row " << r;
    }
    for (int r = 0; r < 2; ++r) {
      EXPECT_GT(o.m.row(r).dot(w.row(r)), 0.0) << static_cast<int>(form) << " m row " << r;
    }
    EXPECT_GT(energy, 0.0);
    std::printf("hourglass form %d: energy after 10 steps %.6e N mm, |f| %.3e N, |m| %.3e N mm\n",
                static_cast<int>(form), energy, o.f.norm(), o.m.norm());
  }
}

TEST(ShellHourglass, StiffnessForceIsLinearInTheHourglassDisplacement) {
  // Stiffness form: after n steps of the same hourglass velocity the force is n times the force of
  // one step (1e-6 relative: the geometry moves with the hourglass displacement, at most 5e-8 of
  // the side, which changes gamma by that order), the first step matches the closed form f = k q
  // gamma with k = kappa/8 E/(1-nu^2) t A|B|^2
  // (= kappa/4 E t/(1-nu^2) for a square, gamma = h) and q = gamma . v dt = 4 V dt, and the
  // reported energy sum dt P equals the stored energy 1/2 Q . q_total of the 5 modes (1e-9).
  const Matrix3X x0 = square();
  Matrix3X v;
  Matrix3X w;
  hourglass_field(v, w);
  v *= 1e-3;  // small displacements: 20 steps move a node by at most 1e-9 mm
  w *= 1e-3;
  const double dt = 1e-7;
  const double t = 1.0;
  const ShellPart part = make_hourglass_part(single_quad(), 5, HourglassForm::stiffness);
  ShellState st = make_shell_state(1, 5, t);
  const test::StepOut first = run_step(part, x0 + dt * v, v, w, dt, st);
  const double k_m = 0.1 / 4.0 * kE / (1 - kNu * kNu) * t;
  EXPECT_NEAR(first.f(0, 0) / (k_m * 4 * v(0, 0) * dt), 1.0, 1e-6);
  double energy = first.r.hourglass_work;
  double worst = 0.0;
  for (int n = 2; n <= 20; ++n) {
    const test::StepOut o = run_step(part, x0 + n * dt * v, v, w, dt, st);
    energy += o.r.hourglass_work;
    worst = std::max(worst, (o.f - n * first.f).norm() / (n * first.f.norm()));
    worst = std::max(worst, (o.m - n * first.m).norm() / (n * first.m.norm()));
  }
  EXPECT_LT(worst, 1e-6);
  // Stored energy 1/2 sum_j Q_j q_j with q_j the total hourglass displacement of mode j (20 dt
  // times the rate 4 (300, -200, 500, 40, 70)).
  const double rates[5] = {300.0, -200.0, 500.0, 40.0, 70.0};
  double stored = 0.0;
  for (int j = 0; j < 5; ++j) {
    stored += 0.5 * st.hourglass[j] * 4.0 * 1e-3 * rates[j] * 20 * dt;
  }
  EXPECT_GT(stored, 0.0);
  EXPECT_NEAR(energy / stored, 1.0, 1e-9);
  std::printf(
      "stiffness hourglass: linearity error %.2e over 20 steps, energy / stored - 1 = %.2e\n",
      worst, energy / stored - 1.0);
}

TEST(ShellHourglass, StiffnessFormIgnoresRigidMotion) {
  // A distorted flat quad in a skew plane, rotated rigidly by 30 deg about a skew axis in 60 steps
  // while translating: hourglass resultants stay 0 (1e-9 relative to k x the side x 1 rad) and the
  // nodal forces vanish to round-off (1e-13 of the unit-strain force scale E t L = 2.1e6 N).
  Matrix3X x(3, 4);
  x << 0.0, 11.0, 9.0, -1.5, 0.0, 1.0, 8.0, 6.0, 0.0, 0.0, 0.0, 0.0;
  x = test::rotation(Vec3(1.0, -0.4, 0.7), 0.8) * x;
  const ShellPart part = make_hourglass_part(single_quad(), 3, HourglassForm::stiffness);
  ShellState st = make_shell_state(1, 3, 1.0);
  const Vec3 axis = Vec3(0.2, 0.9, -0.4).normalized();
  const double angle = (30.0 / 180.0 * M_PI) / 60;
  const Mat3 r = test::rotation(axis, angle);
  const Vec3 drift(0.5, -0.3, 0.2);
  const double dt = 1e-6;
  double f_max = 0.0;
  for (int n = 0; n < 60; ++n) {
    const Vec3 centre = 0.25 * x.rowwise().sum();
    Matrix3X x_new = r * (x.colwise() - centre);
    x_new.colwise() += centre + drift;
    const Matrix3X v = (x_new - x) / dt;
    Matrix3X w(3, 4);
    // Angular velocity of the central-difference rotation step (Cayley: 2 tan(angle/2) / dt).
    w.colwise() = axis * (2.0 / dt) * std::tan(0.5 * angle);
    const test::StepOut o = run_step(part, x_new, v, w, dt, st);
    f_max = std::max(f_max, o.f.norm() + o.m.norm());
    x = x_new;
  }
  const double k_m = 0.1 / 4.0 * kE / (1 - kNu * kNu);
  double q_max = 0.0;
  for (double q : st.hourglass) {
    q_max = std::max(q_max, std::abs(q));
  }
  EXPECT_LT(q_max / (k_m * 10.0), 1e-9);
  const double unit_force = kE * 1.0 * 10.0;
  EXPECT_LT(f_max / unit_force, 1e-13);
  std::printf(
      "stiffness hourglass, rigid rotation: max |Q| / (k L) %.2e, (|f| + |m|) / (E t L) %.2e\n",
      q_max / (k_m * 10.0), f_max / unit_force);
}

TEST(ShellHourglass, StiffnessFormPassesTheMembranePatchTest) {
  // MacNeal-Harder patch in a skew plane, u = G x applied in 10 equal steps (|G| = 1e-7 total):
  // every element's stress is C eps (1e-6 relative, as the viscous patch test), the interior nodes
  // carry no force (1e-6 of the boundary force) and no hourglass resultant builds up (1e-9 of the
  // boundary force).
  const Mat3 q = test::rotation(Vec3(0.3, 1.0, -0.6), 1.1);
  const Matrix3X x0 = q * test::patch_nodes();
  Mat2 g2;
  g2 << 1.0e-7, 0.4e-7, -0.2e-7, -0.5e-7;
  Mat3 g = Mat3::Zero();
  g.topLeftCorner<2, 2>() = g2;
  const Mat3 g_global = q * g * q.transpose();
  const double dt = 1e-6;
  const int steps = 10;
  const Matrix3X v = g_global * x0 / (steps * dt);
  const ShellPart part = make_hourglass_part(test::patch_quads(), 5, HourglassForm::stiffness);
  ShellState st = make_shell_state(5, 5, 0.8);
  test::StepOut o;
  for (int n = 1; n <= steps; ++n) {
    o = run_step(part, x0 + n * dt * v, v, Matrix3X::Zero(3, 8), dt, st);
  }
  ShellStressOutput out;
  compute_element_stress_output(part, x0 + steps * dt * v, st, out);
  const Vec3 s = plane_stress_stiffness(kE, kNu) * Vec3(g2(0, 0), g2(1, 1), g2(0, 1) + g2(1, 0));
  double err = 0.0;
  for (int e = 0; e < 5; ++e) {
    // Local frames differ per element; compare invariants: the global stress tensor's trace and
    // Frobenius norm (the linearised strain; tolerance covers the O(|G|) finite-strain terms).
    const double tr = out.mid(0, e) + out.mid(1, e) + out.mid(2, e);
    err = std::max(err, std::abs(tr - (s(0) + s(1))) / s.norm());
  }
  const double f_boundary = o.f.leftCols<4>().norm();
  const double f_interior = o.f.rightCols<4>().norm() + o.m.rightCols<4>().norm();
  double q_max = 0.0;
  for (double h : st.hourglass) {
    q_max = std::max(q_max, std::abs(h));
  }
  EXPECT_LT(err, 1e-6);
  EXPECT_LT(f_interior / f_boundary, 1e-6);
  EXPECT_LT(q_max / f_boundary, 1e-9);
  EXPECT_LT(std::abs(o.r.hourglass_work), 1e-12 * std::abs(o.r.internal_work));
  std::printf(
      "stiffness patch: stress error %.2e, interior/boundary force %.2e, max |Q| / f %.2e\n", err,
      f_interior / f_boundary, q_max / f_boundary);
}

TEST(ShellHourglass, WarpedElementIgnoresRigidRotation) {
  // Warping correction: a 10 x 10 mm quad with nodes 1, 3 at +0.8 mm and 2, 4 at -0.8 mm (8 % of
  // the side, warp angle ~9 deg), rotated rigidly about a skew axis by 0.06 rad in 60 steps of
  // 1e-3 rad, both hourglass forms, stress-free: nodal forces and moments < 1e-8 of the unit-strain
  // force scale E t L. (The central-difference velocity on the end-of-step geometry differs from a
  // skew field by O((omega dt)^2), which bounds the step size of this check.)
  for (HourglassForm form : {HourglassForm::viscous, HourglassForm::stiffness}) {
    Matrix3X x(3, 4);
    x << 0.0, 10.0, 10.0, 0.0, 0.0, 0.0, 10.0, 10.0, 0.8, -0.8, 0.8, -0.8;
    const ShellPart part = make_hourglass_part(single_quad(), 5, form);
    ShellState st = make_shell_state(1, 5, 1.0);
    const Vec3 axis = Vec3(0.6, -0.5, 0.8).normalized();
    const double angle = 1e-3;
    const Mat3 r = test::rotation(axis, angle);
    const Vec3 p(2.0, -1.0, 3.0);
    const double dt = 1e-6;
    double f_max = 0.0;
    for (int n = 0; n < 60; ++n) {
      const Matrix3X x_new = (r * (x.colwise() - p)).colwise() + p;
      const Matrix3X v = (x_new - x) / dt;
      Matrix3X w(3, 4);
      w.colwise() = axis * (2.0 / dt) * std::tan(0.5 * angle);
      const test::StepOut o = run_step(part, x_new, v, w, dt, st);
      f_max = std::max(f_max, o.f.cwiseAbs().maxCoeff() + o.m.cwiseAbs().maxCoeff() / 10.0);
      x = x_new;
    }
    const double unit_force = kE * 1.0 * 10.0;
    EXPECT_LT(f_max / unit_force, 1e-8) << static_cast<int>(form);
    std::printf("warped rigid rotation, form %d: max force / (E t L) %.2e\n",
                static_cast<int>(form), f_max / unit_force);
  }
}

}  // namespace
}  // namespace sf
