// Through-thickness rules of the shell section: Gauss-Legendre and Gauss-Lobatto exactness, the
// elastic bending moment through the element, and the fully plastic moment's convergence.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/errors.hpp"
#include "element/shell_test_support.hpp"

namespace sf {
namespace {

using test::kE;
using test::kNu;
using test::run_step;

TEST(ShellSection, BothRulesIntegrateTheirExactDegree) {
  // Gauss n points: zeta^j exact for j <= 2n - 1; Lobatto: j <= 2n - 3 (A&S 25.4.29 and 25.4.32);
  // tolerance 1e-14. Lobatto's end points are the surfaces zeta = -1, +1; points ascend.
  for (ThroughThicknessRule rule : {ThroughThicknessRule::gauss, ThroughThicknessRule::lobatto}) {
    const bool lobatto = rule == ThroughThicknessRule::lobatto;
    for (int n = lobatto ? 2 : 1; n <= 9; ++n) {
      const ShellSection s = make_section(n, rule);
      EXPECT_EQ(s.n_points, n);
      EXPECT_EQ(s.rule, rule);
      const int degree = lobatto ? 2 * n - 3 : 2 * n - 1;
      for (int j = 0; j <= degree; ++j) {
        double sum = 0.0;
        for (int k = 0; k < n; ++k) {
          sum += s.weight[k] * std::pow(s.zeta[k], j);
        }
        const double exact = j % 2 == 1 ? 0.0 : 2.0 / (j + 1);
        EXPECT_NEAR(sum, exact, 1e-14) << "rule " << lobatto << " n=" << n << " j=" << j;
      }
      // One degree higher (even) is not exact: the rule has exactly that degree.
      if (degree % 2 == 1) {
        double sum = 0.0;
        for (int k = 0; k < n; ++k) {
          sum += s.weight[k] * std::pow(s.zeta[k], degree + 1);
        }
        EXPECT_GT(std::abs(sum - 2.0 / (degree + 2)), 1e-6) << "rule " << lobatto << " n=" << n;
      }
      for (int k = 1; k < n; ++k) {
        EXPECT_LT(s.zeta[k - 1], s.zeta[k]);
      }
      if (lobatto) {
        EXPECT_EQ(s.zeta[0], -1.0);
        EXPECT_EQ(s.zeta[n - 1], 1.0);
      }
    }
  }
  EXPECT_NEAR(make_section(3, ThroughThicknessRule::lobatto).weight[1], 4.0 / 3.0, 1e-15);
  EXPECT_NEAR(make_section(4, ThroughThicknessRule::lobatto).zeta[2], 1.0 / std::sqrt(5.0), 1e-15);
  EXPECT_THROW(make_section(1, ThroughThicknessRule::lobatto), InputError);
  EXPECT_THROW(make_section(10, ThroughThicknessRule::lobatto), InputError);
  EXPECT_THROW(make_section(0, ThroughThicknessRule::gauss), InputError);
}

// End moment (N mm) of a cylindrically bent strip of 4 elements 10 x 2 mm, t = 1.5 mm, curvature
// c = 1e-9 /mm in one step (as ShellPatch.ConstantCurvatureGivesPlateMoment), and D c b.
double bent_strip_end_moment(const ShellSection& section, double& exact) {
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
  ShellPart part = test::make_part(q, ElasticPlaneStress{kE, kNu}, section.n_points);
  part.section = section;
  ShellState st = make_shell_state(n_el, section.n_points, t);
  const test::StepOut o = run_step(part, x0 + u, u / dt, phi / dt, dt, st);
  exact = kE * t * t * t / (12.0 * (1 - kNu * kNu)) * c * b;
  return o.m(1, 2 * n_el) + o.m(1, 2 * n_el + 1);
}

TEST(ShellSection, ElasticBendingMomentIsExactForBothRules) {
  // z^2 is integrated exactly by Gauss n >= 2 and Lobatto n >= 3: end moment = D c b to 1e-7
  // (the strip's geometric nonlinearity, as in the Gauss patch test). Lobatto n = 2 (the two
  // surfaces only) overestimates the bending stiffness 3 times.
  for (ThroughThicknessRule rule : {ThroughThicknessRule::gauss, ThroughThicknessRule::lobatto}) {
    const bool lobatto = rule == ThroughThicknessRule::lobatto;
    for (int n = lobatto ? 3 : 2; n <= 9; ++n) {
      double exact = 0.0;
      const double m = bent_strip_end_moment(make_section(n, rule), exact);
      EXPECT_NEAR(m / exact, 1.0, 1e-7) << "rule " << lobatto << " n=" << n;
    }
  }
  double exact = 0.0;
  const double m2 = bent_strip_end_moment(make_section(2, ThroughThicknessRule::lobatto), exact);
  EXPECT_NEAR(m2 / exact, 3.0, 1e-6);
}

TEST(ShellSection, FullyPlasticMomentConvergesWithThePointCount) {
  // Perfectly plastic section in uniaxial bending, fully plastic: sxx = sigma_y sign(z), so
  // M_p = sigma_y t^2 / 4 per unit width. The stress is set at the points of one 5 x 5 mm element
  // (J2, H = 0: a zero increment keeps it) and the element integrates the moment; the nodes at
  // x = L carry M b as m_y. The kink at z = 0 makes both rules converge slowly (O(1/n^2)); the
  // error must decrease with n for both, and stay below 2 % (Gauss) / 5 % (Lobatto) at n = 9.
  const double sigma_y = 250.0;
  const double t = 1.2;
  const double side = 5.0;
  QuadConn q(4, 1);
  q << 0, 1, 2, 3;
  Matrix3X x(3, 4);
  x << 0, side, side, 0, 0, 0, side, side, 0, 0, 0, 0;
  const double m_p = sigma_y * t * t / 4.0;
  for (ThroughThicknessRule rule : {ThroughThicknessRule::gauss, ThroughThicknessRule::lobatto}) {
    const bool lobatto = rule == ThroughThicknessRule::lobatto;
    double previous = 1.0;
    for (int n : {3, 5, 7, 9}) {
      ShellPart part =
          test::make_part(q, J2PlaneStress{kE, kNu, LinearHardening{sigma_y, 0.0}}, n, 0.0);
      part.section = make_section(n, rule);
      ShellState st = make_shell_state(1, n, t);
      for (int k = 0; k < n; ++k) {
        const double zeta = part.section.zeta[k];
        st.sxx[k] = zeta > 0 ? sigma_y : (zeta < 0 ? -sigma_y : 0.0);
      }
      const test::StepOut o =
          run_step(part, x, Matrix3X::Zero(3, 4), Matrix3X::Zero(3, 4), 1e-7, st);
      const double m = std::abs(o.m(1, 1) + o.m(1, 2)) / side;
      const double err = std::abs(m / m_p - 1.0);
      EXPECT_LT(err, previous) << "rule " << lobatto << " n=" << n;
      previous = err;
      std::printf("plastic moment, %s n=%d: M / M_p - 1 = %+.4e\n", lobatto ? "Lobatto" : "Gauss",
                  n, m / m_p - 1.0);
    }
    EXPECT_LT(previous, lobatto ? 0.05 : 0.02);
  }
}

}  // namespace
}  // namespace sf
