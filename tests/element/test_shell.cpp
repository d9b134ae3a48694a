// Belytschko-Lin-Tsay shell: rigid-body motion, patch tests, work conjugacy, equilibrium,
// hourglass control, thickness update and failure detection.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "core/errors.hpp"
#include "element/shell_geometry.hpp"
#include "element/shell_output.hpp"
#include "element/shell_test_support.hpp"

namespace sf {
namespace {

using test::kE;
using test::kNu;
using test::run_step;

const J2PlaneStress kSteel{kE, kNu, SwiftHardening{565.32, 0.007117, 0.2589}};

QuadConn single_quad() {
  QuadConn q(4, 1);
  q << 0, 1, 2, 3;
  return q;
}

// A distorted flat quad (corner angles far from 90 deg) in the plane through `origin` spanned by
// the columns of `plane` (3 x 2, orthonormal).
Matrix3X distorted_quad(const Mat3& frame, const Vec3& origin) {
  Eigen::Matrix<double, 2, 4> p;
  p << 0.0, 11.0, 9.0, -1.5,  //
      0.0, 1.0, 8.0, 6.0;
  Matrix3X x(3, 4);
  for (int i = 0; i < 4; ++i) {
    x.col(i) = origin + frame.col(0) * p(0, i) + frame.col(1) * p(1, i);
  }
  return x;
}

TEST(ShellSection, GaussLegendreIsExact) {
  // Gauss-Legendre with n points integrates zeta^j exactly for j <= 2n - 1 (A&S 25.4.29);
  // tolerance 1e-14. Points ascend from bottom (zeta < 0) to top.
  for (int n = 1; n <= 9; ++n) {
    const ShellSection s = make_gauss_section(n);
    for (int j = 0; j <= 2 * n - 1; ++j) {
      double sum = 0.0;
      for (int k = 0; k < n; ++k) {
        sum += s.weight[k] * std::pow(s.zeta[k], j);
      }
      const double exact = j % 2 == 1 ? 0.0 : 2.0 / (j + 1);
      EXPECT_NEAR(sum, exact, 1e-14) << "n=" << n << " j=" << j;
    }
    for (int k = 1; k < n; ++k) {
      EXPECT_LT(s.zeta[k - 1], s.zeta[k]);
    }
  }
  EXPECT_NEAR(make_gauss_section(2).zeta[1], 1.0 / std::sqrt(3.0), 1e-15);
  EXPECT_THROW(make_gauss_section(0), InputError);
  EXPECT_THROW(make_gauss_section(10), InputError);
}

TEST(ShellRigidBody, TranslationGivesNoStrainAndNoForce) {
  // A rigid translation: strain increments are exactly zero by sum_I B_I = 0 and gamma . 1 = 0.
  // A prestressed state must be unchanged to 1e-12 relative; from a stress-free state every force
  // and moment must be below 1e-9 N (N mm) (a 1e-3 strain would give ~2e3 N here).
  const Mat3 frame = test::rotation(Vec3(1, 2, 3), 0.7);
  const Matrix3X x0 = distorted_quad(frame, Vec3(5, -3, 2));
  const ShellPart part = test::make_part(single_quad(), kSteel);
  const double dt = 1e-6;
  const Matrix3X v = Vec3(1200.0, -700.0, 3000.0).replicate(1, 4);
  const Matrix3X w = Matrix3X::Zero(3, 4);
  ShellState st = make_shell_state(1, 5, 1.0);
  auto o = run_step(part, x0 + dt * v, v, w, dt, st);
  EXPECT_LT(o.f.cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT(o.m.cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT(o.r.hourglass_work, 1e-27);
  for (int k = 0; k < 5; ++k) {
    st.eps_p[k] = 0.2;  // yield stress 376 MPa: the prestress stays elastic
    st.sxx[k] = 100.0 + 10 * k;
    st.syy[k] = -50.0;
    st.sxy[k] = 30.0;
  }
  const ShellState before = st;
  run_step(part, x0 + 2 * dt * v, v, w, dt, st);
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(st.sxx[k], before.sxx[k], 1e-12 * 140);
    EXPECT_NEAR(st.syy[k], before.syy[k], 1e-12 * 140);
    EXPECT_NEAR(st.sxy[k], before.sxy[k], 1e-12 * 140);
  }
  EXPECT_NEAR(st.thickness[0], 1.0, 1e-15);
}

// One rigid rotation step x_{n+1} = p + R (x_n - p), with the central-difference velocity and the
// angular velocity axial((2/dt)(R - I)(R + I)^-1) = (2/dt) tan(theta/2) n (Cayley), for which the
// velocity field is exactly skew on the mid-step configuration.
struct RigidStep {
  Matrix3X x_end, v, w;
};
RigidStep rigid_rotation_step(const Matrix3X& x, const Vec3& p, const Vec3& axis, double angle,
                              double dt) {
  const Mat3 r = test::rotation(axis, angle);
  RigidStep s;
  s.x_end = (r * (x.colwise() - p)).colwise() + p;
  s.v = (s.x_end - x) / dt;
  s.w = ((2.0 / dt) * std::tan(0.5 * angle) * axis.normalized()).replicate(1, x.cols());
  return s;
}

TEST(ShellRigidBody, LargeRotationGivesNoStrainAndObjectiveStress) {
  // 30 deg about a skew axis (1, -2, 0.5) through (3, 1, -2), in 60 steps, on the 5-element patch.
  // From a stress-free state: |stress| < 1e-9 MPa and |forces| < 1e-8 N at every step (round-off;
  // 1e-3 strain gives ~2e2 MPa). Prestressed: the corotational stresses stay (1e-10 relative), so
  // the global output equals R sigma0 R^T (1e-10 relative) and the thickness stays 1 (1e-14).
  const Vec3 axis(1.0, -2.0, 0.5);
  const Vec3 p(3.0, 1.0, -2.0);
  const double total = M_PI / 6.0;
  const int n_steps = 60;
  const double dt = 1e-6;
  const ShellPart part = test::make_part(test::patch_quads(), kSteel);
  for (bool prestress : {false, true}) {
    Matrix3X x = test::patch_nodes();
    ShellState st = make_shell_state(5, 5, 1.0);
    if (prestress) {
      for (std::size_t i = 0; i < st.sxx.size(); ++i) {
        st.sxx[i] = 120.0;  // in every element frame: same global tensor only if the frames agree,
        st.syy[i] = -40.0;  // so compare each element against its own initial output below
        st.sxy[i] = 25.0;
      }
      st.sxz.assign(5, 3.0);
    }
    ShellStressOutput out0;
    compute_element_stress_output(part, x, st, out0);
    double max_f = 0.0;
    double max_s = 0.0;
    for (int n = 0; n < n_steps; ++n) {
      const RigidStep s = rigid_rotation_step(x, p, axis, total / n_steps, dt);
      auto o = run_step(part, s.x_end, s.v, s.w, dt, st);
      x = s.x_end;
      if (!prestress) {
        max_f = std::max({max_f, o.f.cwiseAbs().maxCoeff(), o.m.cwiseAbs().maxCoeff()});
        for (std::size_t i = 0; i < st.sxx.size(); ++i) {
          max_s = std::max({max_s, std::abs(st.sxx[i]), std::abs(st.syy[i]), std::abs(st.sxy[i])});
        }
        max_s = std::max({max_s, std::abs(st.sxz[0]), std::abs(st.syz[0])});
      }
    }
    if (!prestress) {
      EXPECT_LT(max_s, 1e-9);
      EXPECT_LT(max_f, 1e-8);
      std::printf("rigid rotation: max |stress| %.2e MPa, max |f|,|m| %.2e\n", max_s, max_f);
      continue;
    }
    for (std::size_t i = 0; i < st.sxx.size(); ++i) {
      EXPECT_NEAR(st.sxx[i], 120.0, 1e-10 * 120);
      EXPECT_NEAR(st.syy[i], -40.0, 1e-10 * 120);
      EXPECT_NEAR(st.sxy[i], 25.0, 1e-10 * 120);
    }
    const Mat3 r = test::rotation(axis, total);
    ShellStressOutput out1;
    compute_element_stress_output(part, x, st, out1);
    double err = 0.0;
    for (int e = 0; e < 5; ++e) {
      Mat3 s0;
      const auto& c = out0.mid.col(e);
      s0 << c(0), c(3), c(5), c(3), c(1), c(4), c(5), c(4), c(2);
      const Mat3 s1 = r * s0 * r.transpose();
      Stress6 expect;
      expect << s1(0, 0), s1(1, 1), s1(2, 2), s1(0, 1), s1(1, 2), s1(0, 2);
      err = std::max(err, (out1.mid.col(e) - expect).norm() / expect.norm());
      EXPECT_NEAR(von_mises(out1.top.col(e)), von_mises_plane_stress(Vec3(120, -40, 25)), 1e-9);
      EXPECT_NEAR(st.thickness[e], 1.0, 1e-14);
    }
    EXPECT_LT(err, 1e-10);
    std::printf("rigid rotation, prestressed: objectivity error %.2e\n", err);
  }
}

TEST(ShellPatch, MembraneLinearFieldGivesUniformStress) {
  // Patch test (MacNeal & Harder 1985, 5 distorted elements) in a skew plane, displacement u = G x
  // in one step. The mid-step strain increment is sym(G (I + G/2)^-1) in every element; stress
  // = C eps (plane stress). With |G| = 1e-7 the corotational frame mismatch between mid-step and
  // end of step is O(|G|): tolerance 1e-6 relative on each element's global stress, and on the
  // interior nodes' forces relative to the boundary forces (they must vanish).
  const Mat3 q = test::rotation(Vec3(0.3, 1.0, -0.6), 1.1);
  const Matrix3X x0 = q * test::patch_nodes();
  Mat2 g2;
  g2 << 1.0e-7, 0.4e-7, -0.2e-7, -0.5e-7;
  Mat3 g = Mat3::Zero();
  g.topLeftCorner<2, 2>() = g2;
  const Mat3 g_global = q * g * q.transpose();
  const double dt = 1e-6;
  const Matrix3X u = g_global * x0;
  for (int np : {1, 5}) {
    const ShellPart part = test::make_part(test::patch_quads(), ElasticPlaneStress{kE, kNu}, np);
    ShellState st = make_shell_state(5, np, 0.8);
    auto o = run_step(part, x0 + u, u / dt, Matrix3X::Zero(3, 8), dt, st);
    const Mat2 eps_t = g2 * (Mat2::Identity() + 0.5 * g2).inverse();
    const Vec3 eps(eps_t(0, 0), eps_t(1, 1), eps_t(0, 1) + eps_t(1, 0));
    const Vec3 s = plane_stress_stiffness(kE, kNu) * eps;
    Mat3 s_loc = Mat3::Zero();
    s_loc << s(0), s(2), 0, s(2), s(1), 0, 0, 0, 0;
    const Mat3 s_glob = q * s_loc * q.transpose();
    Stress6 expect;
    expect << s_glob(0, 0), s_glob(1, 1), s_glob(2, 2), s_glob(0, 1), s_glob(1, 2), s_glob(0, 2);
    ShellStressOutput out;
    compute_element_stress_output(part, x0 + u, st, out);
    double err = 0.0;
    for (int e = 0; e < 5; ++e) {
      err = std::max({err, (out.mid.col(e) - expect).norm() / expect.norm(),
                      (out.top.col(e) - expect).norm() / expect.norm()});
    }
    const double f_boundary = o.f.leftCols<4>().norm();
    const double f_interior = o.f.rightCols<4>().norm() + o.m.rightCols<4>().norm();
    EXPECT_LT(err, 1e-6) << np;
    EXPECT_LT(f_interior / f_boundary, 1e-6) << np;
    EXPECT_LT(o.r.hourglass_work, 1e-12 * o.r.internal_work) << np;
    std::printf("membrane patch np=%d: stress error %.2e, interior/boundary force %.2e\n", np, err,
                f_interior / f_boundary);
  }
}

TEST(ShellPatch, ConstantCurvatureGivesPlateMoment) {
  // Cylindrical bending of a strip of 4 rectangular 10 x 2 mm elements: theta_y = c x and
  // w = -c x^2 / 2 (zero transverse shear), eps_yy = 0, so the moments per unit width are
  // M_xx = D c, M_yy = nu D c with D = E t^3 / (12 (1 - nu^2)) (plate theory). The end nodes carry
  // -/+ M_xx b as m_y, the interior nodes no m_y; the long free edges carry +/- M_yy per tributary
  // length as m_x. c = 1e-9 /mm keeps the geometrically nonlinear terms (membrane strain w'^2 / 2,
  // rotation of the frames) below 1e-8 relative: tolerance 1e-7 relative. 2 and 5 Gauss points
  // integrate z^2 exactly.
  const int n_el = 4;
  const double len = 10.0;
  const double b = 2.0;
  const double t = 1.5;
  const double c = 1e-9;
  const double dt = 1e-6;
  const test::BentStrip strip = test::make_bent_strip(n_el, len, b, c);
  const Matrix3X& x0 = strip.x0;
  const QuadConn& q = strip.quads;
  const Matrix3X& u = strip.u;
  const Matrix3X& phi = strip.phi;
  const double d_plate = kE * t * t * t / (12.0 * (1 - kNu * kNu));
  const double m_exact = d_plate * c * b;
  for (int np : {2, 5}) {
    const ShellPart part = test::make_part(q, ElasticPlaneStress{kE, kNu}, np);
    ShellState st = make_shell_state(n_el, np, t);
    auto o = run_step(part, x0 + u, u / dt, phi / dt, dt, st);
    const double m_end = o.m(1, 2 * n_el) + o.m(1, 2 * n_el + 1);
    const double m_start = o.m(1, 0) + o.m(1, 1);
    EXPECT_NEAR(m_end / m_exact, 1.0, 1e-7) << np;
    EXPECT_NEAR(m_start / m_exact, -1.0, 1e-7) << np;
    double interior = 0.0;
    double edge = 0.0;
    for (int i = 2; i < 2 * n_el; ++i) {
      interior = std::max(interior, std::abs(o.m(1, i)));
      // Node on y = 0 (even) or y = b (odd): m_x = -/+ nu D c len (two half elements).
      const double expect_mx = (i % 2 == 0 ? 1.0 : -1.0) * kNu * d_plate * c * len;
      edge = std::max(edge, std::abs(o.m(0, i) / expect_mx - 1.0));
    }
    EXPECT_LT(interior / m_exact, 1e-7) << np;
    EXPECT_LT(edge, 1e-7) << np;
    // Nodal forces come only from the (physical) membrane strain w'^2 / 2 ~ (c x)^2 / 2: relative
    // to M / len they are ~ 6 (1 - nu^2) c x_max^2 len / t^2 = 4e-5 here; bound at 3x that.
    const double x_max = n_el * len;
    const double geometric = 6 * (1 - kNu * kNu) * c * x_max * x_max * len / (t * t);
    EXPECT_LT(o.f.norm() / (m_exact / len), 3 * geometric) << np;
    // Top fibre (zeta = +1 side, +z here) in tension for c > 0: sxx = E/(1-nu^2) z_top c.
    const double z_top = 0.5 * t * part.section.zeta[np - 1];
    EXPECT_NEAR(st.sxx[np - 1] / (kE / (1 - kNu * kNu) * z_top * c), 1.0, 1e-7);
    std::printf(
        "bending np=%d: end moment error %.2e, interior m_y %.2e, edge m_x error %.2e, "
        "forces %.2e\n",
        np, std::abs(m_end / m_exact - 1), interior / m_exact, edge, o.f.norm() / (m_exact / len));
  }
}

// Internal work of one step with displacement u and rotation increment phi (dt = 1) from a
// stress-free elastic state, and the forces of that step.
test::StepOut step_from_rest(const ShellPart& part, const Matrix3X& x0, const Matrix3X& u,
                             const Matrix3X& phi) {
  ShellState st = make_shell_state(1, part.section.n_points, 0.9);
  return run_step(part, x0 + u, u, phi, 1.0, st);
}

TEST(ShellWork, InternalForceIsTheGradientOfTheStrainEnergy) {
  // For an elastic step from rest, the stress work is the strain energy W(u, phi) (exact for the
  // trapezoidal rule on a linear law), and f_int = dW/du, m_int = dW/dphi up to geometric terms
  // O(|u|/L) ~ 1e-6. Central differences with h = 1e-3 |u|; tolerance 1e-4 on the relative norm of
  // the 24-vector. Distorted quad in a skew plane, 3 thickness points, no hourglass (viscous).
  const Mat3 frame = test::rotation(Vec3(-1, 2, 1), 0.9);
  const Matrix3X x0 = distorted_quad(frame, Vec3(1, 2, 3));
  const ShellPart part = test::make_part(single_quad(), ElasticPlaneStress{kE, kNu}, 3, 0.0);
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  Matrix3X u(3, 4);
  Matrix3X phi(3, 4);
  for (int i = 0; i < 12; ++i) {
    u(i) = 1e-5 * uni(rng);
    phi(i) = 1e-6 * uni(rng);
  }
  const test::StepOut o = step_from_rest(part, x0, u, phi);
  Eigen::Matrix<double, 24, 1> f;
  Eigen::Matrix<double, 24, 1> fd;
  for (int j = 0; j < 12; ++j) {
    f(j) = o.f(j);
    f(12 + j) = o.m(j);
    const double hu = 1e-8;
    const double hr = 1e-9;
    Matrix3X up = u, um = u, pp = phi, pm = phi;
    up(j) += hu;
    um(j) -= hu;
    pp(j) += hr;
    pm(j) -= hr;
    fd(j) = (step_from_rest(part, x0, up, phi).r.internal_work -
             step_from_rest(part, x0, um, phi).r.internal_work) /
            (2 * hu);
    fd(12 + j) = (step_from_rest(part, x0, u, pp).r.internal_work -
                  step_from_rest(part, x0, u, pm).r.internal_work) /
                 (2 * hr);
  }
  const double err = (f - fd).norm() / f.norm();
  EXPECT_LT(err, 1e-4);
  // Moments alone (bending + transverse shear coupling) must agree too.
  const double err_m = (f.tail<12>() - fd.tail<12>()).norm() / f.tail<12>().norm();
  EXPECT_LT(err_m, 1e-4);
  std::printf("energy gradient: relative error %.2e (moments %.2e)\n", err, err_m);
}

TEST(ShellEquilibrium, ForcesAndMomentsSumToZero) {
  // Element forces are self-equilibrated: sum f = 0 and sum (x x f + m) = 0 about the origin, for a
  // plastic, prestressed, hourglassing step with random velocities (flat end-of-step geometry).
  // Tolerance 1e-12 relative to sum |f| |x|. For a warped element, sum f = 0 still holds and the
  // moment balance is exact without hourglass forces (Sum h_I B_I = 0); the viscous hourglass
  // forces of a warped element carry a small moment (documented limit, not tested).
  const Mat3 frame = test::rotation(Vec3(2, -1, 1), 0.4);
  const Matrix3X x_end = distorted_quad(frame, Vec3(-4, 7, 1));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  Matrix3X v(3, 4), w(3, 4);
  for (int i = 0; i < 12; ++i) {
    v(i) = 2e4 * uni(rng);
    w(i) = 5e3 * uni(rng);
  }
  const ShellPart part = test::make_part(single_quad(), kSteel, 5, 0.1);
  ShellState st = make_shell_state(1, 5, 1.0);
  for (int k = 0; k < 5; ++k) {
    st.sxx[k] = 200 - 30 * k;
    st.syy[k] = 50;
    st.sxy[k] = -20;
    st.eps_p[k] = 0.01;
  }
  const double dt = 1e-6;
  auto o = run_step(part, x_end, v, w, dt, st);
  EXPECT_GT(o.r.hourglass_work, 0.0);
  double scale = 0.0;
  Vec3 moment = Vec3::Zero();
  for (int i = 0; i < 4; ++i) {
    scale += o.f.col(i).norm() * x_end.col(i).norm() + o.m.col(i).norm();
    moment += x_end.col(i).cross(o.f.col(i)) + o.m.col(i);
  }
  EXPECT_LT(o.f.rowwise().sum().norm() / scale, 1e-12);
  EXPECT_LT(moment.norm() / scale, 1e-12);
  std::printf("equilibrium: |sum f| %.2e, |sum M| %.2e (relative)\n",
              o.f.rowwise().sum().norm() / scale, moment.norm() / scale);
}

TEST(ShellHourglass, ViscousForcesDissipateExactlyTheReportedPower) {
  // A pure hourglass velocity (v = h V in-plane, out-of-plane, and rotations) on a square:
  // no strain (B h = 0), hourglass power = sum a q^2 > 0, and the reported power equals
  // f_int . v + m_int . omega (1e-12 relative). With coefficient 0 no force at all.
  Matrix3X x(3, 4);
  x << 0, 5, 5, 0, 0, 0, 5, 5, 0, 0, 0, 0;
  const Eigen::RowVector4d h(1, -1, 1, -1);
  Matrix3X v(3, 4), w(3, 4);
  v.row(0) = 300.0 * h;
  v.row(1) = -200.0 * h;
  v.row(2) = 500.0 * h;
  w.row(0) = 40.0 * h;
  w.row(1) = 70.0 * h;
  w.row(2).setZero();
  const double dt = 1e-7;
  for (double coef : {0.1, 0.0}) {
    const ShellPart part = test::make_part(single_quad(), kSteel, 5, coef);
    ShellState st = make_shell_state(1, 5, 1.0);
    // Two equal steps: the work of the second, on the trapezoidal rule with the first step's
    // resultants (as the driver takes every force's work), is the power f.v times dt.
    run_step(part, x, v, w, dt, st);
    auto o = run_step(part, x, v, w, dt, st);
    for (int k = 0; k < 5; ++k) {
      EXPECT_LT(std::abs(st.sxx[k]) + std::abs(st.syy[k]) + std::abs(st.sxy[k]), 1e-9);
    }
    const double power = (o.f.cwiseProduct(v)).sum() + (o.m.cwiseProduct(w)).sum();
    if (coef > 0) {
      EXPECT_GT(o.r.hourglass_work, 0.0);
      EXPECT_NEAR(power * dt / o.r.hourglass_work, 1.0, 1e-12);
      // Membrane part by hand: a_m = kappa/2 m_node 2c/sqrt(A), q = gamma . v = 4 V.
      const double c = plane_stress_wave_speed(kE, kNu, test::kRho);
      const double m_node = 0.25 * test::kRho * 1.0 * 25.0;
      const double a_m = 0.05 * m_node * 2 * c / 5.0;
      EXPECT_NEAR(o.f(0, 0), a_m * 4 * 300.0, 1e-12 * std::abs(a_m * 1200));
      std::printf("hourglass: power %.6e N mm/s, f.v %.6e\n", o.r.hourglass_work / dt, power);
    } else {
      EXPECT_EQ(o.r.hourglass_work, 0.0);
      EXPECT_LT(o.f.norm() + o.m.norm(), 1e-9);
    }
  }
}

TEST(ShellThickness, FollowsPlaneStressAndPlasticIncompressibility) {
  // Equibiaxial stretch of a square: elastic, d_t/t = d_ezz = -nu/(1-nu) (2 e) with e the mid-step
  // increment g/(1 + g/2); plastic (Swift, large step), d_ezz = -2 e + (1 - 2 nu)/E d(sxx + syy).
  // Tolerance 1e-12 relative.
  Matrix3X x(3, 4);
  x << 0, 4, 4, 0, 0, 0, 4, 4, 0, 0, 0, 0;
  for (double g : {1e-4, 2e-2}) {
    const ShellPart part = test::make_part(single_quad(), kSteel, 5, 0.1);
    ShellState st = make_shell_state(1, 5, 1.2);
    const double dt = 1e-6;
    const Matrix3X u = g * x;
    run_step(part, x + u, u / dt, Matrix3X::Zero(3, 4), dt, st);
    const double e = g / (1 + 0.5 * g);
    const double d_ezz = -2 * e + (1 - 2 * kNu) / kE * (st.sxx[0] + st.syy[0]);
    EXPECT_NEAR(st.thickness[0] / (1.2 * (1 + d_ezz)), 1.0, 1e-12) << g;
    if (g < 1e-3) {
      EXPECT_NEAR(d_ezz / (-kNu / (1 - kNu) * 2 * e), 1.0, 1e-12);
    } else {
      EXPECT_GT(st.eps_p[0], 0.0);
    }
  }
}

TEST(ShellFailure, InversionCollapseAndNaNNameTheElement) {
  // Element 1 of 2 is inverted (a bow-tie), collapsed, or gets a NaN velocity: InstabilityError
  // whose message names "shell element 1".
  Matrix3X x(3, 6);
  x << 0, 1, 2, 0, 1, 2, 0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0;
  QuadConn q(4, 2);
  q << 0, 1, 1, 2, 4, 5, 3, 4;
  const ShellPart part = test::make_part(q, kSteel);
  const Matrix3X zero = Matrix3X::Zero(3, 6);
  auto expect_names_element_1 = [&](const Matrix3X& xx, const Matrix3X& vv) {
    ShellState st = make_shell_state(2, 5, 1.0);
    try {
      run_step(part, xx, vv, zero, 1e-6, st);
      ADD_FAILURE() << "no exception";
    } catch (const InstabilityError& err) {
      EXPECT_NE(std::string(err.what()).find("shell element 1"), std::string::npos) << err.what();
    }
  };
  Matrix3X bow = x;
  bow.col(5).swap(bow.col(4));  // nodes 4 and 5 swap places: element 1 becomes a bow-tie
  expect_names_element_1(bow, zero);
  Matrix3X collapsed = x;
  collapsed.col(5) = collapsed.col(1);  // node 5 onto node 1: a diagonal of element 1 vanishes
  expect_names_element_1(collapsed, zero);
  Matrix3X nan_v = zero;
  nan_v(2, 5) = std::nan("");
  expect_names_element_1(x, nan_v);
}

}  // namespace
}  // namespace sf
