// Lumped mass, rotational inertia and the critical time step of the shell.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "element/shell_geometry.hpp"
#include "element/shell_mass.hpp"
#include "element/shell_test_support.hpp"

namespace sf {
namespace {

using test::kE;
using test::kNu;
using test::kRho;

QuadConn single_quad() {
  QuadConn q(4, 1);
  q << 0, 1, 2, 3;
  return q;
}

Matrix3X rectangle(double a, double b) {
  Matrix3X x(3, 4);
  x << 0, a, a, 0, 0, 0, b, b, 0, 0, 0, 0;
  return x;
}

TEST(ShellTimeStep, WaveSpeedOfSteelAndAluminium) {
  // REFERENCES.md (grade B): c = sqrt(E / (rho (1 - nu^2))) = 5422 m/s for steel
  // (210 GPa, 7850 kg/m^3, 0.3) and 5394 m/s for aluminium (70 GPa, 2700, 0.33); the table rounds
  // to 1 m/s, tolerance 0.5 m/s (= 500 mm/s).
  EXPECT_NEAR(plane_stress_wave_speed(210000.0, 0.3, 7.85e-9), 5422e3, 500.0);
  EXPECT_NEAR(plane_stress_wave_speed(70000.0, 0.33, 2.7e-9), 5394e3, 500.0);
}

TEST(ShellTimeStep, SquareElementGivesSideOverWaveSpeed) {
  // LS-DYNA default characteristic length L = A / max side: a 10 mm square gives L = 10 mm and
  // dt = L / c exactly (1e-15 relative); a 10 x 4 rectangle gives L = 4 mm; in a 3-element part
  // the smallest element limits and is named.
  const ShellPart part =
      test::make_part(single_quad(), J2PlaneStress{kE, kNu, LinearHardening{250, 0}});
  const ShellState st = make_shell_state(1, 5, 1.0);
  const double c = plane_stress_wave_speed(kE, kNu, kRho);
  const StableStep s = compute_stable_time_step(part, rectangle(10, 10), st);
  EXPECT_NEAR(s.dt / (10.0 / c), 1.0, 1e-15);
  EXPECT_EQ(s.element, 0);
  std::printf("square 10 mm steel: dt = %.6e s (L/c = %.6e s)\n", s.dt, 10.0 / c);
  EXPECT_NEAR(compute_stable_time_step(part, rectangle(10, 4), st).dt / (4.0 / c), 1.0, 1e-15);

  Matrix3X x(3, 8);
  x << 0, 10, 10, 0, 20, 20, 23, 23, 0, 0, 10, 10, 0, 10, 0, 10, 0, 0, 0, 0, 0, 0, 0, 0;
  QuadConn q(4, 3);
  q << 0, 1, 4, 1, 4, 6, 2, 7, 7, 3, 5, 5;
  ShellPart p3 = part;
  p3.quads = q;
  const StableStep s3 = compute_stable_time_step(p3, x, make_shell_state(3, 5, 1.0));
  EXPECT_EQ(s3.element, 2);  // 3 x 10 mm
  EXPECT_NEAR(s3.dt / (3.0 / c), 1.0, 1e-14);
}

TEST(ShellMass, LumpedMassSumsToDensityThicknessArea) {
  // Sum of nodal masses = rho t A (1e-14 relative) on the 5-element patch (A = 288 mm^2), and the
  // rotational inertia sums to sum_e alpha_e m_e with alpha = (A_e + t^2) / 4.
  const ShellPart part = test::make_part(test::patch_quads(), ElasticPlaneStress{kE, kNu});
  const Matrix3X x = test::rotation(Vec3(1, 1, 0), 0.3) * test::patch_nodes();
  const ShellState st = make_shell_state(5, 5, 0.8);
  VectorX m, r;
  compute_lumped_mass(part, x, st, m, r);
  ASSERT_EQ(m.size(), 8);
  EXPECT_NEAR(m.sum() / (kRho * 0.8 * 288.0), 1.0, 1e-14);
  double r_expect = 0.0;
  for (int e = 0; e < 5; ++e) {
    ShellGeometry g;
    ASSERT_TRUE(compute_shell_geometry(gather_quad(x, part.quads, e), g));
    r_expect += kRho * 0.8 * g.area * 0.25 * (g.area + 0.64);
  }
  EXPECT_NEAR(r.sum() / r_expect, 1.0, 1e-14);
}

// Stiffness (24 x 24: ux uy uz per node, then rx ry rz per node) of a stress-free elastic element
// by central differences of the internal forces over one step (dt = 1), symmetrised.
Eigen::MatrixXd element_stiffness(const ShellPart& part, const Matrix3X& x0, double t) {
  Eigen::MatrixXd k(24, 24);
  for (int j = 0; j < 24; ++j) {
    const double h = 1e-7 * (j < 12 ? 1.0 : 0.1);
    Eigen::VectorXd col(24);
    col.setZero();
    for (double sgn : {1.0, -1.0}) {
      Matrix3X u = Matrix3X::Zero(3, 4);
      Matrix3X phi = Matrix3X::Zero(3, 4);
      (j < 12 ? u(j) : phi(j - 12)) = sgn * h;
      ShellState st = make_shell_state(1, part.section.n_points, t);
      const test::StepOut o = test::run_step(part, x0 + u, u, phi, 1.0, st);
      for (int i = 0; i < 12; ++i) {
        col(i) += sgn * o.f(i) / (2 * h);
        col(12 + i) += sgn * o.m(i) / (2 * h);
      }
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

TEST(ShellMass, RotationalInertiaNeverLowersTheStableStep) {
  // Generalised eigenproblem K phi = w^2 M phi of one free element with the lumped mass and the
  // scaled rotational inertia: the highest frequency with rotations must not exceed the highest
  // frequency with the rotations held (translations only), so the rotational DOFs never limit the
  // step (tolerance 1e-6 relative, FD stiffness). Over t/L = 0.01 .. 1, nu = 0 .. 0.49, aspect
  // ratio 1 and 4. Also: the translational maximum is the membrane one, 2/L sqrt(E/((1-nu) rho)).
  for (double nu : {0.0, 0.3, 0.49}) {
    for (double aspect : {1.0, 4.0}) {
      for (double t_over_l : {0.01, 0.1, 0.5, 1.0}) {
        const double l = 10.0;
        const double t = t_over_l * l;
        const Matrix3X x0 = rectangle(l * aspect, l);
        const ShellPart part = test::make_part(single_quad(), ElasticPlaneStress{kE, nu}, 5, 0.0);
        const Eigen::MatrixXd k = element_stiffness(part, x0, t);
        VectorX m, r;
        compute_lumped_mass(part, x0, make_shell_state(1, 5, t), m, r);
        Eigen::VectorXd mass(24);
        for (int i = 0; i < 4; ++i) {
          mass.segment<3>(3 * i).setConstant(m(i));
          mass.segment<3>(12 + 3 * i).setConstant(r(i));
        }
        const double w_all = max_frequency(k, mass);
        const double w_trans = max_frequency(k.topLeftCorner(12, 12), mass.head(12));
        EXPECT_LE(w_all, w_trans * (1 + 1e-6))
            << "nu " << nu << " aspect " << aspect << " t/L " << t_over_l;
        if (aspect == 1.0) {
          const double w_membrane = 2.0 / l * std::sqrt(kE / ((1 - nu) * kRho));
          EXPECT_NEAR(w_trans / w_membrane, 1.0, 1e-6);
        }
        // Margin: the smallest scale s of the rotational inertia that still keeps w_all <= w_trans.
        double lo = 1e-4;
        double hi = 1.0;
        for (int it = 0; it < 40; ++it) {
          const double s = std::sqrt(lo * hi);
          Eigen::VectorXd ms = mass;
          ms.tail(12) *= s;
          (max_frequency(k, ms) <= w_trans * (1 + 1e-6) ? hi : lo) = s;
        }
        std::printf("nu %.2f aspect %.0f t/L %.2f: w_all / w_trans = %.6f, inertia margin %.3f\n",
                    nu, aspect, t_over_l, w_all / w_trans, hi);
      }
    }
  }
}

}  // namespace
}  // namespace sf
