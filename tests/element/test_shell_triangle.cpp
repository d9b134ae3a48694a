// C0 shell triangle (CST membrane, constant curvature, DSG3 shear with LSV stabilisation):
// rigid-body motion, membrane and bending patch tests, work conjugacy, equilibrium, mass, time
// step, rotational inertia, a thin cantilever against beam theory, and failure detection.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "element/shell_geometry.hpp"
#include "element/shell_mass.hpp"
#include "element/shell_output.hpp"
#include "element/shell_test_support.hpp"
#include "element/shell_triangle_geometry.hpp"

namespace sf {
namespace {

using test::kE;
using test::kNu;
using test::kRho;
using test::run_step;

const J2PlaneStress kSteel{kE, kNu, SwiftHardening{565.32, 0.007117, 0.2589}};

ShellPart make_tri_part(const TriConn& triangles, const Material& material, int n_points = 5) {
  ShellPart p = test::make_part(QuadConn(4, 0), material, n_points, 0.1);
  p.triangles = triangles;
  return p;
}

TriConn single_triangle() {
  TriConn t(3, 1);
  t << 0, 1, 2;
  return t;
}

// An irregular flat triangle (angles 25, 47, 108 deg approx.) in the plane through `origin`
// spanned by the first two columns of `frame`.
Matrix3X skew_triangle(const Mat3& frame, const Vec3& origin) {
  Eigen::Matrix<double, 2, 3> p;
  p << 0.0, 9.0, 2.5,  //
      0.0, 1.5, 5.0;
  Matrix3X x(3, 3);
  for (int i = 0; i < 3; ++i) {
    x.col(i) = origin + frame.col(0) * p(0, i) + frame.col(1) * p(1, i);
  }
  return x;
}

// The MacNeal-Harder patch (test::patch_nodes, 24 x 12 mm, nodes 4..7 interior) cut into 10
// triangles with mixed diagonal directions: an irregular triangle mesh.
TriConn patch_triangles() {
  TriConn t(3, 10);
  t << 0, 0, 1, 2, 2, 2, 3, 3, 4, 4,  //
      1, 5, 2, 6, 3, 7, 0, 4, 5, 6,   //
      5, 4, 5, 5, 7, 6, 4, 7, 6, 7;
  return t;
}

struct RigidStep {
  Matrix3X x_end, v, w;
};
// One rigid rotation step with the central-difference velocity and the Cayley angular velocity
// (2/dt) tan(theta/2) n, as in test_shell.cpp.
RigidStep rigid_rotation_step(const Matrix3X& x, const Vec3& p, const Vec3& axis, double angle,
                              double dt) {
  const Mat3 r = test::rotation(axis, angle);
  RigidStep s;
  s.x_end = (r * (x.colwise() - p)).colwise() + p;
  s.v = (s.x_end - x) / dt;
  s.w = ((2.0 / dt) * std::tan(0.5 * angle) * axis.normalized()).replicate(1, x.cols());
  return s;
}

TEST(TriangleGeometry, GradientsAndShearOperatorAreExactForLinearFields) {
  // CST: sum_I N_I,x = 0 and sum_I x_I N_I,x = 1 (exact for linear fields); DSG3: a linear w and
  // uniform rotations give gamma = grad w + (theta_y, -theta_x) exactly. Tolerance 1e-14
  // (round-off on O(1) quantities, lengths ~ 10 mm).
  const Matrix3X x = skew_triangle(test::rotation(Vec3(1, -1, 2), 0.8), Vec3(3, 4, 5));
  TriangleGeometry g;
  ASSERT_TRUE(compute_triangle_geometry(x, g));
  const Matrix3X xl = g.frame.transpose() * x;
  EXPECT_NEAR(g.bx.sum(), 0.0, 1e-15);
  EXPECT_NEAR(g.by.sum(), 0.0, 1e-15);
  EXPECT_NEAR(g.bx.dot(xl.row(0)), 1.0, 1e-14);
  EXPECT_NEAR(g.by.dot(xl.row(1)), 1.0, 1e-14);
  EXPECT_NEAR(g.bx.dot(xl.row(1)), 0.0, 1e-14);
  EXPECT_NEAR(g.area, 0.5 * (9.0 * 5.0 - 2.5 * 1.5), 1e-13);
  const Vec2 grad_w(0.3, -0.7);
  const double thx = 0.11, thy = -0.23;
  const Eigen::RowVector3d w = grad_w(0) * xl.row(0) + grad_w(1) * xl.row(1);
  const Vec2 gamma = g.sw * w.transpose() + g.sx * Vec3::Constant(thx) + g.sy * Vec3::Constant(thy);
  EXPECT_NEAR(gamma(0), grad_w(0) + thy, 1e-14);
  EXPECT_NEAR(gamma(1), grad_w(1) - thx, 1e-14);
}

TEST(TriangleRigidBody, TranslationGivesNoStrainAndNoForce) {
  // Rigid translation: every strain operator sums to zero over the nodes, so strain increments
  // vanish to round-off. Stress-free: forces and moments < 1e-9 N (N mm) (a 1e-3 strain gives
  // ~1e3 N here); prestressed: stresses unchanged to 1e-12 relative, thickness exactly kept.
  const Matrix3X x0 = skew_triangle(test::rotation(Vec3(1, 2, 3), 0.7), Vec3(5, -3, 2));
  const ShellPart part = make_tri_part(single_triangle(), kSteel);
  const double dt = 1e-6;
  const Matrix3X v = Vec3(1200.0, -700.0, 3000.0).replicate(1, 3);
  const Matrix3X w = Matrix3X::Zero(3, 3);
  ShellState st = make_shell_state(1, 5, 1.0);
  auto o = run_step(part, x0 + dt * v, v, w, dt, st);
  EXPECT_LT(o.f.cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT(o.m.cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_EQ(o.r.hourglass_work, 0.0);
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

TEST(TriangleRigidBody, LargeRotationGivesNoStrainAndObjectiveStress) {
  // 30 deg in 60 steps and 90 deg in 180 steps about a skew axis (1, -2, 0.5) through (3, 1, -2),
  // on the 10-triangle patch. Stress-free: only round-off, which accumulates step by step (each
  // velocity (x_{n+1} - x_n)/dt carries ~eps |x| / dt): |stress| < 2e-11 MPa and |f|, |m|
  // < 2.5e-10 N (N mm) per step taken, the per-step bounds of the quad test's 1e-9 MPa / 1e-8 N
  // over 60 steps rounded up (1.7e-11, 1.7e-10). A strain measure that is not exact for rigid
  // rotation would give ~(omega dt)^2 E = 1.6e1 MPa per step here. Prestressed: the
  // corotational stresses stay (1e-10 relative), the global output is R sigma0 R^T (1e-10
  // relative) and the thickness stays 1 (1e-14).
  const Vec3 axis(1.0, -2.0, 0.5);
  const Vec3 p(3.0, 1.0, -2.0);
  const double dt = 1e-6;
  const ShellPart part = make_tri_part(patch_triangles(), kSteel);
  for (const auto& [total, n_steps] : {std::pair{M_PI / 6.0, 60}, std::pair{M_PI / 2.0, 180}}) {
    for (bool prestress : {false, true}) {
      Matrix3X x = test::patch_nodes();
      ShellState st = make_shell_state(10, 5, 1.0);
      if (prestress) {
        std::fill(st.sxx.begin(), st.sxx.end(), 120.0);
        std::fill(st.syy.begin(), st.syy.end(), -40.0);
        std::fill(st.sxy.begin(), st.sxy.end(), 25.0);
        st.sxz.assign(10, 3.0);
      }
      ShellStressOutput out0;
      compute_element_stress_output(part, x, st, out0);
      double max_f = 0.0;
      double max_s = 0.0;
      for (int n = 0; n < n_steps; ++n) {
        const RigidStep s = rigid_rotation_step(x, p, axis, total / n_steps, dt);
        auto o = run_step(part, s.x_end, s.v, s.w, dt, st);
        x = s.x_end;
        max_f = std::max({max_f, o.f.cwiseAbs().maxCoeff(), o.m.cwiseAbs().maxCoeff()});
        for (std::size_t i = 0; i < st.sxx.size(); ++i) {
          max_s = std::max({max_s, std::abs(st.sxx[i]), std::abs(st.syy[i]), std::abs(st.sxy[i])});
        }
        for (int e = 0; e < 10; ++e) {
          max_s = std::max({max_s, std::abs(st.syz[e]), std::abs(st.sxz[e] - st.sxz[0])});
        }
      }
      if (!prestress) {
        EXPECT_LT(max_s, 2e-11 * n_steps) << total;
        EXPECT_LT(max_f, 2.5e-10 * n_steps) << total;
        std::printf("triangle rigid rotation %.0f deg: max |stress| %.2e MPa, max |f|,|m| %.2e\n",
                    total * 180 / M_PI, max_s, max_f);
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
      for (int e = 0; e < 10; ++e) {
        Mat3 s0;
        const auto& c = out0.mid.col(e);
        s0 << c(0), c(3), c(5), c(3), c(1), c(4), c(5), c(4), c(2);
        const Mat3 s1 = r * s0 * r.transpose();
        Stress6 expect;
        expect << s1(0, 0), s1(1, 1), s1(2, 2), s1(0, 1), s1(1, 2), s1(0, 2);
        err = std::max(err, (out1.mid.col(e) - expect).norm() / expect.norm());
        EXPECT_NEAR(st.thickness[e], 1.0, 1e-14);
      }
      EXPECT_LT(err, 1e-10);
      std::printf("triangle rigid rotation %.0f deg, prestressed: objectivity error %.2e\n",
                  total * 180 / M_PI, err);
    }
  }
}

TEST(TrianglePatch, MembraneLinearFieldGivesUniformStress) {
  // Membrane patch test on the irregular 10-triangle patch in a skew plane, u = G x in one step:
  // the mid-step strain increment is sym(G (I + G/2)^-1) in every element, stress = C eps. With
  // |G| = 1e-7 the frame mismatch between mid-step and end of step is O(|G|): tolerance 1e-6
  // relative on each element's global stress, and on the interior nodes' forces and moments
  // relative to the boundary forces (they must vanish).
  const Mat3 q = test::rotation(Vec3(0.3, 1.0, -0.6), 1.1);
  const Matrix3X x0 = q * test::patch_nodes();
  Mat2 g2;
  g2 << 1.0e-7, 0.4e-7, -0.2e-7, -0.5e-7;
  Mat3 g = Mat3::Zero();
  g.topLeftCorner<2, 2>() = g2;
  const Matrix3X u = (q * g * q.transpose()) * x0;
  const double dt = 1e-6;
  for (int np : {1, 5}) {
    const ShellPart part = make_tri_part(patch_triangles(), ElasticPlaneStress{kE, kNu}, np);
    ShellState st = make_shell_state(10, np, 0.8);
    auto o = run_step(part, x0 + u, u / dt, Matrix3X::Zero(3, 8), dt, st);
    const Mat2 eps_t = g2 * (Mat2::Identity() + 0.5 * g2).inverse();
    const Vec3 eps(eps_t(0, 0), eps_t(1, 1), eps_t(0, 1) + eps_t(1, 0));
    const Vec3 s = plane_stress_stiffness(kE, kNu) * eps;
    Mat3 s_loc;
    s_loc << s(0), s(2), 0, s(2), s(1), 0, 0, 0, 0;
    const Mat3 s_glob = q * s_loc * q.transpose();
    Stress6 expect;
    expect << s_glob(0, 0), s_glob(1, 1), s_glob(2, 2), s_glob(0, 1), s_glob(1, 2), s_glob(0, 2);
    ShellStressOutput out;
    compute_element_stress_output(part, x0 + u, st, out);
    double err = 0.0;
    for (int e = 0; e < 10; ++e) {
      err = std::max({err, (out.mid.col(e) - expect).norm() / expect.norm(),
                      (out.top.col(e) - expect).norm() / expect.norm()});
    }
    const double f_boundary = o.f.leftCols<4>().norm();
    const double f_interior = o.f.rightCols<4>().norm() + o.m.rightCols<4>().norm();
    EXPECT_LT(err, 1e-6) << np;
    EXPECT_LT(f_interior / f_boundary, 1e-6) << np;
    std::printf("triangle membrane patch np=%d: stress error %.2e, interior/boundary force %.2e\n",
                np, err, f_interior / f_boundary);
  }
}

TEST(TrianglePatch, ConstantCurvatureGivesPlateMoment) {
  // Bending patch test on the irregular 10-triangle patch (z = 0 plane): the Kirchhoff field
  // w = (a x^2 + b y^2 + 2 c x y) / 2, theta_x = w_,y, theta_y = -w_,x has constant curvature
  // k = (a, b, 2c) in this element's convention (d(z) = d_m - z k), so every point must carry
  // sigma = -z C k (plate theory: M = -int z sigma dz = D k, D = t^3/12 C) and the DSG3 shear
  // gaps vanish (gamma = 0 for Kirchhoff modes). The one physical extra is the membrane strain
  // w'^2 / 2: relative to the surface bending strain t |k| / 2 it is about |k| x_max^2 / t
  // = 3e-11 x 27^2 / 1.2 = 1.8e-8 here. Tolerances: 1e-7 on every point's stress relative to the
  // surface bending stress; 1e-7 on the interior nodes' moments relative to the boundary ones
  // (constant M: sum_e A_e grad N_I = 0 at an interior node); interior in-plane forces below
  // 3 x 1.8e-8 of sigma_surface t L (L = 24 mm); shear stress below 1e-12 of the bending stress
  // (round-off).
  const double a = 3.0e-11, b = -1.8e-11, c = 1.05e-11;
  const double t = 1.2;
  const double dt = 1e-6;
  const Matrix3X x0 = test::patch_nodes();
  Matrix3X u = Matrix3X::Zero(3, 8);
  Matrix3X phi = Matrix3X::Zero(3, 8);
  for (int i = 0; i < 8; ++i) {
    const double x = x0(0, i), y = x0(1, i);
    u(2, i) = 0.5 * (a * x * x + b * y * y + 2 * c * x * y);
    phi(0, i) = b * y + c * x;     // w_,y
    phi(1, i) = -(a * x + c * y);  // -w_,x
  }
  const Vec3 k(a, b, 2 * c);
  const Vec3 ck = plane_stress_stiffness(kE, kNu) * k;
  for (int np : {2, 5}) {
    const ShellPart part = make_tri_part(patch_triangles(), ElasticPlaneStress{kE, kNu}, np);
    ShellState st = make_shell_state(10, np, t);
    auto o = run_step(part, x0 + u, u / dt, phi / dt, dt, st);
    double err = 0.0;
    double shear = 0.0;
    for (int e = 0; e < 10; ++e) {
      // Each element's frame: e1 along its side 1-2 in the z = 0 plane, e3 = +z.
      TriangleGeometry g;
      ASSERT_TRUE(compute_triangle_geometry(gather_triangle(x0, part.triangles, e), g));
      const Mat2 r = g.frame.topLeftCorner<2, 2>();
      for (int j = 0; j < np; ++j) {
        const double z = 0.5 * t * part.section.zeta[j];
        Mat2 s_glob;
        s_glob << -z * ck(0), -z * ck(2), -z * ck(2), -z * ck(1);
        const Mat2 s_loc = r.transpose() * s_glob * r;
        const std::size_t i = static_cast<std::size_t>(e * np + j);
        const double scale = 0.5 * t * ck.norm();
        err = std::max({err, std::abs(st.sxx[i] - s_loc(0, 0)) / scale,
                        std::abs(st.syy[i] - s_loc(1, 1)) / scale,
                        std::abs(st.sxy[i] - s_loc(0, 1)) / scale});
      }
      shear = std::max({shear, std::abs(st.sxz[e]), std::abs(st.syz[e])});
    }
    const double m_boundary = o.m.leftCols<4>().norm();
    const double interior = o.m.rightCols<4>().norm();
    const double sigma_bending = 0.5 * t * ck.norm();
    const double forces = o.f.rightCols<4>().norm() / (sigma_bending * t * 24.0);
    EXPECT_LT(err, 1e-7) << np;
    EXPECT_LT(interior / m_boundary, 1e-7) << np;
    EXPECT_LT(forces, 3 * 1.8e-8) << np;
    EXPECT_LT(shear / sigma_bending, 1e-12) << np;
    std::printf(
        "triangle bending patch np=%d: stress error %.2e, interior/boundary moment %.2e, interior "
        "forces %.2e, shear/bending %.2e\n",
        np, err, interior / m_boundary, forces, shear / sigma_bending);
  }
}

// One elastic step from rest with displacement u and rotation increment phi (dt = 1).
test::StepOut step_from_rest(const ShellPart& part, const Matrix3X& x0, const Matrix3X& u,
                             const Matrix3X& phi, double t) {
  ShellState st = make_shell_state(element_count(part), part.section.n_points, t);
  return run_step(part, x0 + u, u, phi, 1.0, st);
}

TEST(TriangleWork, InternalForceIsTheGradientOfTheStrainEnergy) {
  // For an elastic step from rest the stress work is the strain energy W(u, phi) (exact for the
  // trapezoidal rule on a linear law) and f_int = dW/du, m_int = dW/dphi up to geometric terms
  // O(|u|/L) ~ 1e-6. Central differences; tolerance 1e-4 on the relative norm of the 18-vector
  // and of the moments alone. Irregular triangle in a skew plane, 3 thickness points, t = 0.9 mm
  // (the LSV factor is active: t^2 / (t^2 + 0.1 h^2) = 0.09).
  const Matrix3X x0 = skew_triangle(test::rotation(Vec3(-1, 2, 1), 0.9), Vec3(1, 2, 3));
  const ShellPart part = make_tri_part(single_triangle(), ElasticPlaneStress{kE, kNu}, 3);
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  Matrix3X u(3, 3);
  Matrix3X phi(3, 3);
  for (int i = 0; i < 9; ++i) {
    u(i) = 1e-5 * uni(rng);
    phi(i) = 1e-6 * uni(rng);
  }
  const double t = 0.9;
  const test::StepOut o = step_from_rest(part, x0, u, phi, t);
  Eigen::Matrix<double, 18, 1> f;
  Eigen::Matrix<double, 18, 1> fd;
  for (int j = 0; j < 9; ++j) {
    f(j) = o.f(j);
    f(9 + j) = o.m(j);
    const double hu = 1e-8;
    const double hr = 1e-9;
    Matrix3X up = u, um = u, pp = phi, pm = phi;
    up(j) += hu;
    um(j) -= hu;
    pp(j) += hr;
    pm(j) -= hr;
    fd(j) = (step_from_rest(part, x0, up, phi, t).r.internal_work -
             step_from_rest(part, x0, um, phi, t).r.internal_work) /
            (2 * hu);
    fd(9 + j) = (step_from_rest(part, x0, u, pp, t).r.internal_work -
                 step_from_rest(part, x0, u, pm, t).r.internal_work) /
                (2 * hr);
  }
  const double err = (f - fd).norm() / f.norm();
  const double err_m = (f.tail<9>() - fd.tail<9>()).norm() / f.tail<9>().norm();
  EXPECT_LT(err, 1e-4);
  EXPECT_LT(err_m, 1e-4);
  std::printf("triangle energy gradient: relative error %.2e (moments %.2e)\n", err, err_m);
}

TEST(TriangleEquilibrium, ForcesAndMomentsSumToZero) {
  // sum f = 0 and sum (x x f + m) = 0 about the origin for a plastic, prestressed step with random
  // velocities (the triangle is flat, so this is exact): tolerance 1e-12 relative to
  // sum |f| |x| + |m|.
  const Matrix3X x_end = skew_triangle(test::rotation(Vec3(2, -1, 1), 0.4), Vec3(-4, 7, 1));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  Matrix3X v(3, 3), w(3, 3);
  for (int i = 0; i < 9; ++i) {
    v(i) = 2e4 * uni(rng);
    w(i) = 5e3 * uni(rng);
  }
  const ShellPart part = make_tri_part(single_triangle(), kSteel);
  ShellState st = make_shell_state(1, 5, 1.0);
  for (int k = 0; k < 5; ++k) {
    st.sxx[k] = 200 - 30 * k;
    st.syy[k] = 50;
    st.sxy[k] = -20;
    st.eps_p[k] = 0.01;
  }
  auto o = run_step(part, x_end, v, w, 1e-6, st);
  double scale = 0.0;
  Vec3 moment = Vec3::Zero();
  for (int i = 0; i < 3; ++i) {
    scale += o.f.col(i).norm() * x_end.col(i).norm() + o.m.col(i).norm();
    moment += x_end.col(i).cross(o.f.col(i)) + o.m.col(i);
  }
  EXPECT_GT(st.eps_p[0], 0.01);  // the step did yield
  EXPECT_LT(o.f.rowwise().sum().norm() / scale, 1e-12);
  EXPECT_LT(moment.norm() / scale, 1e-12);
  std::printf("triangle equilibrium: |sum f| %.2e, |sum M| %.2e (relative)\n",
              o.f.rowwise().sum().norm() / scale, moment.norm() / scale);
}

TEST(TriangleMass, MixedPartMassSumsToDensityThicknessArea) {
  // A part with the 5 patch quads and the 10 patch triangles on the same nodes (not a sensible
  // mesh, but it exercises both loops): sum of nodal masses = rho t (A_quads + A_triangles)
  // = rho t 2 x 288 mm^2 (1e-14 relative); rotational inertia sums to sum_e (A_e + t^2)/4 m_e.
  ShellPart part = test::make_part(test::patch_quads(), ElasticPlaneStress{kE, kNu});
  part.triangles = patch_triangles();
  const Matrix3X x = test::rotation(Vec3(1, 1, 0), 0.3) * test::patch_nodes();
  const double t = 0.8;
  const ShellState st = make_shell_state(element_count(part), 5, t);
  VectorX m, r;
  compute_lumped_mass(part, x, st, m, r);
  ASSERT_EQ(m.size(), 8);
  EXPECT_NEAR(m.sum() / (kRho * t * 2.0 * 288.0), 1.0, 1e-14);
  double r_expect = 0.0;
  for (int e = 0; e < 5; ++e) {
    const Quad3 q = gather_quad(x, part.quads, e);
    const double area = 0.5 * (q.col(2) - q.col(0)).cross(q.col(3) - q.col(1)).norm();
    r_expect += kRho * t * area * 0.25 * (area + t * t);
  }
  for (int k = 0; k < 10; ++k) {
    const Tri3 tr = gather_triangle(x, part.triangles, k);
    const double area = 0.5 * (tr.col(1) - tr.col(0)).cross(tr.col(2) - tr.col(0)).norm();
    r_expect += kRho * t * area * 0.25 * (area + t * t);
  }
  EXPECT_NEAR(r.sum() / r_expect, 1.0, 1e-14);
}

TEST(TriangleTimeStep, SmallestAltitudeOverWaveSpeed) {
  // dt = h_min / c with h_min = 2 A / longest side (LS-DYNA's (1 + beta) A / max side, beta = 1):
  // a right triangle with legs 3 and 4 mm has h_min = 12/5 = 2.4 mm; exact to 1e-15 relative. In
  // a mixed part with a 10 mm square quad (L = 10 mm) the triangle limits and is named by its
  // element index n_quads + k = 1.
  const double c = plane_stress_wave_speed(kE, kNu, kRho);
  Matrix3X x(3, 7);
  x << 0, 10, 10, 0, 20, 24, 20,  //
      0, 0, 10, 10, 0, 0, 3,      //
      0, 0, 0, 0, 0, 0, 0;
  ShellPart part = test::make_part(QuadConn(4, 0), ElasticPlaneStress{kE, kNu});
  part.triangles = TriConn(3, 1);
  part.triangles << 4, 5, 6;
  const StableStep s = compute_stable_time_step(part, x, make_shell_state(1, 5, 1.0));
  EXPECT_NEAR(s.dt / (2.4 / c), 1.0, 1e-15);
  EXPECT_EQ(s.element, 0);
  part.quads = QuadConn(4, 1);
  part.quads << 0, 1, 2, 3;
  const StableStep s2 = compute_stable_time_step(part, x, make_shell_state(2, 5, 1.0));
  EXPECT_NEAR(s2.dt / (2.4 / c), 1.0, 1e-15);
  EXPECT_EQ(s2.element, 1);
  std::printf("triangle 3-4-5 steel: dt = %.6e s (h_min / c = %.6e s)\n", s.dt, 2.4 / c);
}

// Stiffness (6n x 6n: translations of every node, then rotations) of a stress-free elastic part by
// central differences of the internal forces of one step from rest (dt = 1), symmetrised.
Eigen::MatrixXd part_stiffness(const ShellPart& part, const Matrix3X& x0, double t, double h_u,
                               double h_r) {
  const int n = static_cast<int>(x0.cols());
  Eigen::MatrixXd k(6 * n, 6 * n);
  for (int j = 0; j < 6 * n; ++j) {
    const double h = j < 3 * n ? h_u : h_r;
    Eigen::VectorXd col = Eigen::VectorXd::Zero(6 * n);
    for (double sgn : {1.0, -1.0}) {
      Matrix3X u = Matrix3X::Zero(3, n);
      Matrix3X phi = Matrix3X::Zero(3, n);
      (j < 3 * n ? u(j) : phi(j - 3 * n)) = sgn * h;
      const test::StepOut o = step_from_rest(part, x0, u, phi, t);
      col.head(3 * n) += sgn * Eigen::Map<const Eigen::VectorXd>(o.f.data(), 3 * n) / (2 * h);
      col.tail(3 * n) += sgn * Eigen::Map<const Eigen::VectorXd>(o.m.data(), 3 * n) / (2 * h);
    }
    k.col(j) = col;
  }
  return 0.5 * (k + k.transpose());
}

double max_frequency(const Eigen::MatrixXd& k, const Eigen::VectorXd& m) {
  const Eigen::VectorXd s = m.cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd a = s.asDiagonal() * k * s.asDiagonal();
  return std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a).eigenvalues().maxCoeff());
}

TEST(TriangleMass, RotationalInertiaNeverLowersTheStableStep) {
  // K phi = w^2 M phi for one free triangle with the lumped mass and the rotational inertia
  // alpha m, alpha = (A + t^2)/4 as for the quad: the highest frequency with rotations must not
  // exceed the one with the rotations held (translations only), tolerance 1e-6 relative (FD
  // stiffness). Equilateral, right isosceles and a 4:1 right triangle; nu = 0 .. 0.49;
  // t/L = 0.01 .. 1. Prints the translational maximum as w h_min / c, the isolated element's
  // stability factor (the step h_min / c is stable for an element alone when it is <= 2).
  const double l = 10.0;
  const std::vector<Matrix3X> shapes = [&] {
    Matrix3X eq(3, 3), right(3, 3), slender(3, 3);
    eq << 0, l, 0.5 * l, 0, 0, 0.5 * std::sqrt(3.0) * l, 0, 0, 0;
    right << 0, l, 0, 0, 0, l, 0, 0, 0;
    slender << 0, 4 * l, 0, 0, 0, l, 0, 0, 0;
    return std::vector<Matrix3X>{eq, right, slender};
  }();
  for (double nu : {0.0, 0.3, 0.49}) {
    for (std::size_t shape = 0; shape < shapes.size(); ++shape) {
      for (double t_over_l : {0.01, 0.1, 0.5, 1.0}) {
        const double t = t_over_l * l;
        const Matrix3X& x0 = shapes[shape];
        const ShellPart part = make_tri_part(single_triangle(), ElasticPlaneStress{kE, nu});
        const Eigen::MatrixXd k = part_stiffness(part, x0, t, 1e-7, 1e-8);
        VectorX m, r;
        compute_lumped_mass(part, x0, make_shell_state(1, 5, t), m, r);
        Eigen::VectorXd mass(18);
        for (int i = 0; i < 3; ++i) {
          mass.segment<3>(3 * i).setConstant(m(i));
          mass.segment<3>(9 + 3 * i).setConstant(r(i));
        }
        const double w_all = max_frequency(k, mass);
        const double w_trans = max_frequency(k.topLeftCorner(9, 9), mass.head(9));
        EXPECT_LE(w_all, w_trans * (1 + 1e-6))
            << "nu " << nu << " shape " << shape << " t/L " << t_over_l;
        TriangleGeometry g;
        ASSERT_TRUE(compute_triangle_geometry(x0, g));
        const double factor =
            w_trans * triangle_characteristic_length(g) / plane_stress_wave_speed(kE, nu, kRho);
        if (t_over_l == 0.01) {
          std::printf(
              "nu %.2f shape %zu: w_all / w_trans = %.6f (t/L 0.01), w_max h_min / c = %.3f\n", nu,
              shape, w_all / w_trans, factor);
        }
      }
    }
  }
}

// A flat strip [0, n L] x [0, b] of n x m squares, each cut into two triangles (diagonal
// direction alternating when `alternate`), nodes column by column (node (i, j) = i (m + 1) + j).
struct TriangleStrip {
  Matrix3X x;
  TriConn triangles;
};
TriangleStrip make_triangle_strip(int n, int m, double length, double width, bool alternate) {
  TriangleStrip s;
  s.x.resize(3, (n + 1) * (m + 1));
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= m; ++j) {
      s.x.col(i * (m + 1) + j) = Vec3(length * i / n, width * j / m, 0.0);
    }
  }
  s.triangles.resize(3, 2 * n * m);
  int k = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      const int a = i * (m + 1) + j, b = a + m + 1, c = b + 1, d = a + 1;
      if (!alternate || (i + j) % 2 == 0) {
        s.triangles.col(k++) << a, b, c;
        s.triangles.col(k++) << a, c, d;
      } else {
        s.triangles.col(k++) << a, b, d;
        s.triangles.col(k++) << b, c, d;
      }
    }
  }
  return s;
}

// Tip deflection (mm, mean over the tip nodes) of a clamped strip of triangles under a total tip
// force F (N) along -z, from the linear static problem K u = F with the part's FD stiffness.
double cantilever_tip_deflection(const TriangleStrip& s, int n, int m, double t, double force) {
  const ShellPart part = make_tri_part(s.triangles, ElasticPlaneStress{kE, 0.0}, 3);
  const int n_nodes = static_cast<int>(s.x.cols());
  const Eigen::MatrixXd k = part_stiffness(part, s.x, t, 1e-6, 1e-7);
  std::vector<int> free;
  for (int d = 0; d < 6 * n_nodes; ++d) {
    const int node = (d % (3 * n_nodes)) / 3;
    const bool clamped = node <= m;                        // the nodes at x = 0
    const bool drilling = d >= 3 * n_nodes && d % 3 == 2;  // no drilling stiffness
    if (!clamped && !drilling) {
      free.push_back(d);
    }
  }
  const int nf = static_cast<int>(free.size());
  Eigen::MatrixXd kf(nf, nf);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(nf);
  for (int a = 0; a < nf; ++a) {
    for (int b = 0; b < nf; ++b) {
      kf(a, b) = k(free[a], free[b]);
    }
    const int node = free[a] / 3;
    if (free[a] < 3 * n_nodes && free[a] % 3 == 2 && node >= n * (m + 1)) {
      const int j = node - n * (m + 1);
      rhs(a) = -force / m * ((j == 0 || j == m) ? 0.5 : 1.0);  // consistent edge load
    }
  }
  const Eigen::VectorXd uf = kf.ldlt().solve(rhs);
  double tip = 0.0;
  for (int a = 0; a < nf; ++a) {
    const int node = free[a] / 3;
    if (free[a] < 3 * n_nodes && free[a] % 3 == 2 && node >= n * (m + 1)) {
      tip -= uf(a) / (m + 1);
    }
  }
  return tip;
}

TEST(TriangleCantilever, ThinStripUnderTipLoadMatchesBeamTheoryWithoutShearLocking) {
  // Cantilever strip L = 100 mm, b = 10 mm, nu = 0, 20 x 2 squares cut into 80 triangles (both
  // diagonal patterns), clamped at x = 0, tip force F = 1e-3 N (linear regime), linear static
  // solution with the element's stiffness. Exact (Timoshenko beam): d = F L^3 / (3 E I)
  // + F L / (5/6 G b t), I = b t^3 / 12. t/L = 0.01 and 0.001: a locking element loses
  // stiffness ratio ~ (L/t)^2 between the two (100x); this one must give the same normalised
  // deflection within 1 % at both thicknesses. Tolerance 5 % against the beam: 20 elements along,
  // constant-curvature triangles (measured errors are printed and recorded in the docs).
  const int n = 20, m = 2;
  const double length = 100.0, width = 10.0, force = 1e-3;
  for (bool alternate : {false, true}) {
    const TriangleStrip s = make_triangle_strip(n, m, length, width, alternate);
    double ratio[2];
    int idx = 0;
    for (double t : {1.0, 0.1}) {
      const double inertia = width * t * t * t / 12.0;
      const double exact = force * std::pow(length, 3) / (3.0 * kE * inertia) +
                           force * length / (5.0 / 6.0 * 0.5 * kE * width * t);
      const double tip = cantilever_tip_deflection(s, n, m, t, force);
      ratio[idx++] = tip / exact;
      EXPECT_NEAR(tip / exact, 1.0, 0.05) << "t = " << t << " alternate " << alternate;
      std::printf("triangle cantilever %s, t/L = %.3f: tip %.6e mm, beam %.6e mm, ratio %.4f\n",
                  alternate ? "alternating diagonals" : "parallel diagonals", t / length, tip,
                  exact, tip / exact);
    }
    EXPECT_NEAR(ratio[1] / ratio[0], 1.0, 0.01) << "alternate " << alternate;
  }
}

TEST(TriangleFailure, CollapseInversionAndNaNNameTheElement) {
  // In a part with 1 quad and 2 triangles, triangle 1 (element 2, the only element on node 6)
  // collapses, inverts (node 6 crosses the opposite side 4-5 within the step: the mid-step
  // triangle is valid, the end-of-step normal is reversed) or gets a NaN velocity:
  // InstabilityError naming "shell element 2 (triangle 1)".
  Matrix3X x(3, 7);
  x << 0, 1, 1, 0, 2, 2, 3,   //
      0, 0, 1, 1, 0, 1, 0.5,  //
      0, 0, 0, 0, 0, 0, 0;
  ShellPart part = test::make_part(QuadConn::Zero(4, 1), kSteel);
  part.quads << 0, 1, 2, 3;
  part.triangles = TriConn(3, 2);
  part.triangles << 1, 4,  //
      4, 6,                //
      5, 5;
  const Matrix3X zero = Matrix3X::Zero(3, 7);
  auto expect_names = [&](const Matrix3X& xx, const Matrix3X& vv, const char* what) {
    ShellState st = make_shell_state(3, 5, 1.0);
    try {
      run_step(part, xx, vv, zero, 1e-6, st);
      ADD_FAILURE() << what << ": no exception";
    } catch (const InstabilityError& err) {
      const std::string message = err.what();
      EXPECT_NE(message.find("shell element 2 (triangle 1)"), std::string::npos) << message;
      EXPECT_NE(message.find(what), std::string::npos) << message;
    }
  };
  Matrix3X collapsed = x;
  collapsed.col(6) = Vec3(2.0, 0.5, 0.0);  // onto the side 4-5
  expect_names(collapsed, zero, "collapsed");
  Matrix3X inverted = x;
  inverted.col(6) = Vec3(1.5, 0.5, 0.0);
  Matrix3X v_inv = zero;
  v_inv.col(6) = (Vec3(1.5, 0.5, 0.0) - Vec3(2.9, 0.5, 0.0)) / 1e-6;  // mid-step at x = 2.2
  expect_names(inverted, v_inv, "inverted");
  Matrix3X nan_v = zero;
  nan_v(2, 6) = std::nan("");
  expect_names(x, nan_v, "non-finite");
}

TEST(TriangleModes, OnlyRigidBodyModesInAMeshOfTriangles) {
  // Zero-energy modes: with constant DSG3 shear (2 strains) and constant curvature (3), a single
  // free triangle has one spurious bending mode besides its 6 rigid modes (the rotation field
  // theta spinning about a point where the averaged shear vanishes); it cannot be shared between
  // elements, so the free 10-triangle patch must have exactly the 6 rigid modes. Eigenvalues of
  // the FD stiffness (drilling DOFs removed, t = 1 mm) below 1e-8 of the largest count as zero;
  // the next one is printed to show the gap.
  auto count_zero_modes = [](const ShellPart& part, const Matrix3X& x0) {
    const int n = static_cast<int>(x0.cols());
    const Eigen::MatrixXd k = part_stiffness(part, x0, 1.0, 1e-7, 1e-8);
    std::vector<int> keep;
    for (int d = 0; d < 6 * n; ++d) {
      if (d < 3 * n || d % 3 != 2) {
        keep.push_back(d);
      }
    }
    Eigen::MatrixXd kk(keep.size(), keep.size());
    for (std::size_t a = 0; a < keep.size(); ++a) {
      for (std::size_t b = 0; b < keep.size(); ++b) {
        kk(a, b) = k(keep[a], keep[b]);
      }
    }
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(kk).eigenvalues();
    int zeros = 0;
    while (zeros < ev.size() && ev(zeros) < 1e-8 * ev.maxCoeff()) {
      ++zeros;
    }
    std::printf("%d zero modes of %ld; next eigenvalue / largest = %.2e\n", zeros, ev.size(),
                ev(zeros) / ev.maxCoeff());
    return zeros;
  };
  const Matrix3X x1 = skew_triangle(Mat3::Identity(), Vec3::Zero());
  EXPECT_EQ(count_zero_modes(make_tri_part(single_triangle(), ElasticPlaneStress{kE, kNu}), x1), 7);
  EXPECT_EQ(count_zero_modes(make_tri_part(patch_triangles(), ElasticPlaneStress{kE, kNu}),
                             test::patch_nodes()),
            6);
}

}  // namespace
}  // namespace sf
