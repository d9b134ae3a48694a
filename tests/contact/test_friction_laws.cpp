// Friction beyond Coulomb (src/contact/coulomb_friction.hpp; docs/contact.md "Friction laws"):
// the tables, the pressure power law, the orthotropic (elliptic) limit, and their use through
// compute_penalty_contact with the nodes' contact pressures. References, all closed forms:
//   - a table: linear between its points, the end values held beyond them;
//   - the power law mu = mu_c(v) (p / p0)^(n - 1) (grade C: the tests check the formula's
//     implementation, not the formula), times the slip-speed factor;
//   - a node sliding under a known pressure history p(t) on area A: its force is
//     mu(p(t), v) p(t) A at every step, opposite to the slip;
//   - the elliptic limit (F_1 / mu_1)^2 + (F_2 / mu_2)^2 <= F_n^2 with a radial return: sliding
//     at an angle a to the along axis gives |F| = F_n / sqrt(cos^2 a / mu_1^2 + sin^2 a / mu_2^2)
//     opposite to the slip.
// Tolerances are relative round-off of the few operations between the closed form and the code
// (1e-12 unless said).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>

#include "contact/coulomb_friction.hpp"
#include "contact/penalty_contact.hpp"
#include "contact_pair_fixture.hpp"
#include "core/errors.hpp"
#include "mesh/nodal_area.hpp"
#include "test_meshes.hpp"

namespace sf {
namespace {

using test::Contact;
using test::make_law;
using test::make_pair;

FrictionTable table_of(std::vector<double> x, std::vector<double> y) {
  FrictionTable t;
  t.x = std::move(x);
  t.y = std::move(y);
  return t;
}

unsigned bit(TableEnd end) {
  return 1u << static_cast<unsigned>(end);
}

// mu from a pressure table [1, 0.16], [10, 0.13], [50, 0.10] (MPa, -).
FrictionParameters table_law() {
  FrictionParameters law;
  law.pressure_table = table_of({1.0, 10.0, 50.0}, {0.16, 0.13, 0.10});
  return law;
}

// mu = 0.15 (p / 10 MPa)^(0.8 - 1).
FrictionParameters power_law() {
  FrictionParameters law = make_law(0.15, 0.15, 0.0);
  law.pressure_exponent = 0.8;
  law.reference_pressure = 10.0;
  return law;
}

TEST(FrictionTable, LinearBetweenPointsAndHeldBeyondTheEnds) {
  const FrictionParameters law = table_law();
  const FrictionTable& t = law.pressure_table;
  EXPECT_EQ(t(1.0), 0.16);  // at the points: their values
  EXPECT_EQ(t(10.0), 0.13);
  EXPECT_EQ(t(50.0), 0.10);
  EXPECT_NEAR(t(5.5), 0.145, 1e-15);   // halfway between 1 and 10
  EXPECT_NEAR(t(30.0), 0.115, 1e-15);  // halfway between 10 and 50
  EXPECT_NEAR(t(2.8), 0.154, 1e-15);   // a fifth of the way
  EXPECT_EQ(t(0.5), 0.16);             // below: the first value held
  EXPECT_EQ(t(0.0), 0.16);
  EXPECT_EQ(t(1e6), 0.10);  // above: the last value held
  unsigned beyond = 0;
  EXPECT_EQ(law.coefficient(0.5, 0.0, &beyond), 0.16);
  EXPECT_EQ(beyond, bit(TableEnd::pressure_below));
  beyond = 0;
  EXPECT_EQ(law.coefficient(80.0, 0.0, &beyond), 0.10);
  EXPECT_EQ(beyond, bit(TableEnd::pressure_above));
  beyond = 0;
  EXPECT_NEAR(law.coefficient(30.0, 0.0, &beyond), 0.115, 1e-15);
  EXPECT_EQ(beyond, 0u);
  EXPECT_TRUE(law.active());
  EXPECT_TRUE(law.needs_pressure());
}

TEST(FrictionLaws, PowerLawAndSpeedFactorAgainstTheirFormulas) {
  const FrictionParameters law = power_law();
  EXPECT_FALSE(make_law(0.15, 0.15, 0).needs_pressure());
  EXPECT_TRUE(law.needs_pressure());
  // 0.15 x 10^(-0.2) and 0.15 x 10^(+0.2), to 16 digits.
  EXPECT_EQ(law.coefficient(10.0, 0.0), 0.15);
  EXPECT_NEAR(law.coefficient(100.0, 0.0), 0.0946436016720290, 1e-14 * 0.09464);
  EXPECT_NEAR(law.coefficient(1.0, 0.0), 0.2377339788691670, 1e-14 * 0.2377);
  // Decay and speed factor: mu = (mu_d + (mu_s - mu_d) e^(-c v)) (p / p0)^(n - 1) f(v),
  // f linear from 1 at 0 to 0.8 at 200 mm/s: f(100) = 0.9, f(300) = 0.8 (held).
  FrictionParameters shaped = law;
  shaped.static_coefficient = 0.2;
  shaped.dynamic_coefficient = 0.1;
  shaped.decay = 0.01;
  shaped.speed_table = table_of({0.0, 200.0}, {1.0, 0.8});
  for (double p : {0.3, 4.0, 10.0, 55.0}) {
    for (double v : {0.0, 100.0, -100.0, 300.0}) {
      const double f = std::abs(v) <= 200 ? 1.0 - 0.2 * std::abs(v) / 200 : 0.8;
      const double expected =
          (0.1 + 0.1 * std::exp(-0.01 * std::abs(v))) * std::pow(p / 10.0, -0.2) * f;
      unsigned beyond = 0;
      EXPECT_NEAR(shaped.coefficient(p, v, &beyond), expected, 1e-14 * expected) << p << " " << v;
      EXPECT_EQ(beyond, std::abs(v) > 200 ? bit(TableEnd::speed_above) : 0u);
    }
  }
  // Without the laws beyond Coulomb: the Coulomb coefficient, bit for bit.
  const FrictionParameters coulomb = make_law(0.3, 0.2, 0.01);
  for (double v : {0.0, 3.0, 77.7, 1e4}) {
    EXPECT_EQ(coulomb.coefficient(123.0, v), coulomb.coefficient(v));
  }
}

// The expected coefficient of table_law() at p, by a scan of its segments.
double table_mu(double p) {
  const double x[] = {1.0, 10.0, 50.0}, y[] = {0.16, 0.13, 0.10};
  if (p <= x[0]) {
    return y[0];
  }
  for (int k = 1; k < 3; ++k) {
    if (p <= x[k]) {
      return y[k - 1] + (p - x[k - 1]) / (x[k] - x[k - 1]) * (y[k] - y[k - 1]);
    }
  }
  return y[2];
}

TEST(FrictionLaws, BlockSlidingUnderAPressureHistoryFollowsMuOfP) {
  // A node of area A = 4 mm^2 slides along x at 200 mm/s (0.02 mm a step of 1e-4 s) while its
  // pressure ramps up from 0.5 to 60.5 MPa and down to 5.5 MPa (steps of 0.5 MPa), so beyond
  // both ends of the table. k_t du = 40 N per step exceeds every change of the limit (at most
  // 0.5 x 4 x 0.16 = 0.32 N): the node slides at every step, and its force is exactly
  // -mu(p, v) p A x along the motion.
  const double area = 4.0, dt = 1e-4, du = 0.02, k_t = 2000.0, v = du / dt;
  std::vector<double> history;
  for (int k = 1; k <= 121; ++k) {
    history.push_back(0.5 * k);
  }
  for (int k = 120; k >= 11; --k) {
    history.push_back(0.5 * k);
  }
  FrictionParameters coulomb_speed = make_law(0.2, 0.1, 0.002);
  coulomb_speed.speed_table = table_of({0.0, 100.0, 1000.0}, {1.0, 0.95, 0.7});
  struct Case {
    const char* name;
    FrictionParameters law;
    std::function<double(double)> mu;  // the closed form at the sliding speed v
  };
  const Case cases[] = {
      {"power law", power_law(), [](double p) { return 0.15 * std::pow(p / 10.0, -0.2); }},
      {"pressure table", table_law(), table_mu},
      {"Coulomb with decay x speed table", coulomb_speed,
       [v](double) {
         return (0.1 + 0.1 * std::exp(-0.002 * v)) * (0.95 - 0.25 * (v - 100.0) / 900.0);
       }},
  };
  for (const Case& c : cases) {
    Vec3 stored = Vec3::Zero();
    double worst = 0.0, work = 0.0, expected_work = 0.0;
    unsigned beyond = 0;
    for (double p : history) {
      const double normal_force = p * area;
      const FrictionStep step = coulomb_friction_update(c.law, stored, Vec3::UnitZ(),
                                                        Vec3(du, 0, 0), dt, normal_force, k_t, p);
      ASSERT_TRUE(step.sliding) << c.name << " at p = " << p;
      const double expected = c.mu(p) * p * area;
      worst = std::max(worst, std::abs(-step.force.x() - expected) / expected);
      ASSERT_EQ(step.force.y(), 0.0);
      ASSERT_EQ(step.force.z(), 0.0);
      work += step.work;
      expected_work += expected * step.slip;
      beyond |= step.beyond;
    }
    std::printf(
        "%s: friction force against mu(p, v) p A over %zu steps: worst relative error %.2e\n",
        c.name, history.size(), worst);
    EXPECT_LT(worst, 1e-12) << c.name;
    EXPECT_NEAR(work, expected_work, 1e-12 * expected_work);
    if (c.law.pressure_table.empty()) {
      EXPECT_EQ(beyond, 0u) << c.name;  // 200 mm/s lies inside the speed table
    } else {
      EXPECT_EQ(beyond, bit(TableEnd::pressure_below) | bit(TableEnd::pressure_above));
    }
  }
}

TEST(OrthotropicFriction, SlidingAlongEitherAxisAndAtAnAngle) {
  // mu_1 = 0.2 along the rolling direction, mu_2 = 0.1 across it (r = 0.5); F_n = 100 N. The node
  // slides 0.05 mm a step (k_t du = 50 N, above any limit): from rest, the first step slides.
  FrictionParameters law = make_law(0.2, 0.2, 0);
  law.across_ratio = 0.5;
  const double fn = 100, k_t = 1000, dt = 1e-4;
  const auto slide = [&](const FrictionParameters& l, const Vec3& normal, const Vec3& step_dir) {
    Vec3 stored = Vec3::Zero();
    FrictionStep step;
    for (int k = 0; k < 3; ++k) {
      step = coulomb_friction_update(l, stored, normal, 0.05 * step_dir, dt, fn, k_t);
      EXPECT_TRUE(step.sliding);
    }
    return step.force;
  };
  const auto expect_force = [](const Vec3& force, const Vec3& expected, const char* what) {
    std::printf("%s: |F| = %.15f N (closed form %.15f)\n", what, force.norm(), expected.norm());
    EXPECT_LT((force - expected).norm(), 1e-12 * expected.norm()) << what;
  };
  const Vec3 z = Vec3::UnitZ();
  expect_force(slide(law, z, Vec3::UnitX()), Vec3(-20, 0, 0), "along: mu_1 F_n");
  expect_force(slide(law, z, -Vec3::UnitX()), Vec3(20, 0, 0), "along, backwards");
  expect_force(slide(law, z, Vec3::UnitY()), Vec3(0, -10, 0), "across: mu_2 F_n");
  for (double degrees : {30.0, 45.0, 75.0, 160.0}) {
    const double a = degrees * std::numbers::pi / 180;
    const Vec3 dir(std::cos(a), std::sin(a), 0);
    const double c = std::cos(a), s = std::sin(a);
    const double magnitude = fn / std::sqrt(c * c / 0.04 + s * s / 0.01);
    expect_force(slide(law, z, dir), -magnitude * dir, "at an angle");
  }
  EXPECT_NEAR(fn / std::sqrt(0.75 / 0.04 + 0.25 / 0.01), 15.118578920369089, 1e-13);  // 30 deg
  // The rolling direction out of the tangent plane: its projection is the along axis.
  FrictionParameters tilted = law;
  tilted.rolling_direction = Vec3(1, 0, 1).normalized();
  expect_force(slide(tilted, z, Vec3::UnitX()), Vec3(-20, 0, 0), "rolling direction tilted");
  // A tilted contact (normal turned 40 deg about x): along x still mu_1, across it mu_2.
  const Vec3 n(0, -std::sin(0.7), std::cos(0.7));
  const Vec3 across = n.cross(Vec3::UnitX());
  expect_force(slide(law, n, Vec3::UnitX()), Vec3(-20, 0, 0), "tilted contact, along");
  expect_force(slide(law, n, across), -10 * across, "tilted contact, across");
  // The rolling direction normal to the contact: the mean coefficient (1 + r) / 2 mu_1.
  FrictionParameters normal_rd = law;
  normal_rd.rolling_direction = Vec3::UnitZ();
  expect_force(slide(normal_rd, z, Vec3(0.6, 0.8, 0)), Vec3(-9, -12, 0), "direction undefined");
}

TEST(OrthotropicFriction, StoredForceStaysInsideTheEllipseOnRandomHistories) {
  FrictionParameters law = make_law(0.3, 0.2, 0.02);
  law.across_ratio = 1.6;
  law.rolling_direction = Vec3(1, 2, 0.5).normalized();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g;
  const double k_t = 400, dt = 1e-4;
  Vec3 stored = Vec3::Zero();
  Vec3 normal = Vec3(0.1, -0.2, 1).normalized();
  int slides = 0, sticks = 0;
  for (int k = 0; k < 20000; ++k) {
    normal = (normal + 0.03 * Vec3(g(rng), g(rng), g(rng))).normalized();
    const Vec3 increment = std::pow(10.0, -1 - 4 * u(rng)) * Vec3(g(rng), g(rng), g(rng));
    const double fn = 100 * u(rng);
    const FrictionStep step = coulomb_friction_update(law, stored, normal, increment, dt, fn, k_t);
    // The ellipse in the tangent axes: a1 the rolling direction's projection, a2 = n x a1.
    const Vec3 a1 =
        (law.rolling_direction - normal.dot(law.rolling_direction) * normal).normalized();
    const Vec3 a2 = normal.cross(a1);
    const double mu = law.coefficient(
        increment.norm() > 0 ? (increment - normal.dot(increment) * normal).norm() / dt : 0.0);
    const double f1 = stored.dot(a1) / mu, f2 = stored.dot(a2) / (law.across_ratio * mu);
    ASSERT_LE(f1 * f1 + f2 * f2, fn * fn * (1 + 1e-12) + 1e-300) << "step " << k;
    ASSERT_LE(std::abs(stored.dot(normal)), 1e-13 * (1 + stored.norm()));
    ASSERT_GE(step.work, 0.0);
    ++(step.sliding ? slides : sticks);
  }
  EXPECT_GT(slides, 1000);
  EXPECT_GT(sticks, 1000);
}

TEST(FrictionLaws, ValidationNamesTheToolAndTheTable) {
  const auto message = [](const FrictionParameters& law) {
    try {
      law.validate("die");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(table_law()), "no error");
  EXPECT_EQ(message(power_law()), "no error");
  FrictionParameters bad = table_law();
  bad.pressure_table.x = {1.0, 10.0, 5.0};  // not increasing
  EXPECT_NE(message(bad).find("tool 'die': friction pressure table: point 2"), std::string::npos)
      << message(bad);
  bad = table_law();
  bad.pressure_table.y[1] = -0.1;  // negative mu
  EXPECT_NE(message(bad).find("friction pressure table: point 1"), std::string::npos);
  bad = table_law();
  bad.pressure_table.x = {1.0};  // one point
  bad.pressure_table.y = {0.1};
  EXPECT_NE(message(bad).find("at least 2 points"), std::string::npos);
  bad = table_law();
  bad.static_coefficient = 0.1;  // the table and the Coulomb coefficient
  EXPECT_NE(message(bad).find("gives the coefficient itself"), std::string::npos);
  bad = make_law(0.1, 0.1, 0);
  bad.speed_table = table_of({0.0, 1.0}, {1.0, std::nan("")});
  EXPECT_NE(message(bad).find("friction speed table: point 1"), std::string::npos);
  bad = power_law();
  bad.reference_pressure = 0.0;
  EXPECT_NE(message(bad).find("reference pressure p0 > 0"), std::string::npos);
  bad = make_law(0.1, 0.1, 0);
  bad.across_ratio = -1;
  EXPECT_NE(message(bad).find("ratio across / along > 0"), std::string::npos);
}

TEST(FrictionLaws, WarningSaysWhatWasMetAndWhatIsHeld) {
  FrictionParameters law = table_law();
  law.speed_table = table_of({0.0, 100.0}, {1.0, 0.9});
  const std::string below = friction_table_warning(
      law, TableEnd::pressure_below, "case.toml: contact[0] (tool 'die')", 1.5e-3, 42);
  std::printf("%s", below.c_str());
  for (const char* part : {"case.toml: contact[0] (tool 'die')", "friction_pressure_table",
                           "below its first point (1 MPa)", "t = 1.500000e-03 s", "cycle 42",
                           "mu = 0.16 is held constant", "once"}) {
    EXPECT_NE(below.find(part), std::string::npos) << part;
  }
  const std::string above = friction_table_warning(law, TableEnd::speed_above, "here", 0.0, 1);
  for (const char* part : {"friction_speed_table", "slip speed above its last point (100 mm/s)",
                           "factor = 0.9 is held constant"}) {
    EXPECT_NE(above.find(part), std::string::npos) << part;
  }
}

/// Flat tool z = 0 over [-50, 50]^2, normals +z.
TriangleSurface make_table() {
  return test::make_height_field("table", 4, 4, -50, 50, -50, 50,
                                 [](double, double) { return 0.0; });
}

TEST(PenaltyFrictionLaws, PatchPressedByAKnownHistoryAndPulledSideways) {
  // A 2 x 2 patch of 2 mm quads (9 nodes; tributary areas 1, 2 and 4 mm^2 at the corners, edges
  // and centre), half thickness 0.5 mm at the start and 0.45 mm now (areas x 0.5 / 0.45), pressed
  // into the flat tool by d(t) = 0.01 + 1e-4 s mm (k = 1000 N/mm: F_n = 10 to 30 N per node) and
  // pulled along x at 100 mm/s (k_t du = 10 N per step, above every change of the limit). From
  // the first step every node slides: its friction force is -mu(p_i) F_n x with
  // p_i = F_n / A_i(now), and the tool's tangential reaction is sum_i mu(p_i) F_n. The table
  // [3, 0.15], [12, 0.10] (MPa) does not cover the pressures met (2.25 to 27 MPa): the nodes
  // below and above its ends are counted.
  const TriangleSurface table = make_table();
  Matrix3X start(3, 9);
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      start.col(3 * j + i) = Vec3(2.0 * i, 2.0 * j, 0.0);
    }
  }
  QuadConn quads(4, 4);
  quads << 0, 1, 3, 4,  //
      1, 2, 4, 5,       //
      4, 5, 7, 8,       //
      3, 4, 6, 7;
  FrictionParameters law;
  law.pressure_table = table_of({3.0, 12.0}, {0.15, 0.10});
  const double k = 1000, h0 = 0.5, h = 0.45, speed = 100, dt = 1e-4;
  Contact pair = make_pair(table, 9, k, law);
  Matrix3X x = start;
  const Matrix3X v = Vec3(speed, 0, 0).replicate(1, 9);
  const VectorX half = VectorX::Constant(9, h);
  Matrix3X f(3, 9);
  // Without the areas: refused.
  EXPECT_THROW(compute_penalty_contact(pair.pair, pair.state,
                                       {x, v, half, Vec3::Zero(), Vec3::Zero(), dt}, f),
               std::invalid_argument);
  pair.pair.start_area = nodal_tributary_area(start, quads, TriConn(3, 0));
  pair.pair.start_half_thickness = VectorX::Constant(9, h0);
  EXPECT_EQ(pair.pair.start_area[4], 4.0);
  EXPECT_EQ(pair.pair.start_area[0], 1.0);
  double worst = 0.0;
  for (int s = 1; s <= 200; ++s) {
    const double depth = 0.01 + 1e-4 * s;
    x.row(0).array() += speed * dt;
    x.row(2).setConstant(h - depth);
    f.setZero();
    const ContactResult r = compute_penalty_contact(
        pair.pair, pair.state, {x, v, half, Vec3::Zero(), Vec3::Zero(), dt}, f);
    ASSERT_EQ(r.sliding_nodes, 9) << s;
    double reaction = 0.0;
    int below = 0, above = 0;
    for (int i = 0; i < 9; ++i) {
      // The normal force k d, to the rounding of the depth (0.01 to 0.03 mm) found as a distance
      // to a tool whose coordinates reach 50 mm: ~1e-14 mm, 1e-12 relative at the most.
      EXPECT_NEAR(f(2, i), k * depth, 1e-11 * k * depth);
      const double fn = f(2, i);
      const double p = fn / (pair.pair.start_area[i] * h0 / h);
      const double mu = p <= 3 ? 0.15 : p >= 12 ? 0.10 : 0.15 - 0.05 * (p - 3) / 9;
      below += p < 3;
      above += p > 12;
      worst = std::max(worst, std::abs(-f(0, i) - mu * fn) / (mu * fn));
      reaction += mu * fn;
    }
    EXPECT_NEAR(r.force_on_tool.x(), reaction, 1e-11 * reaction) << s;  // the same leak
    EXPECT_EQ(r.beyond_table[static_cast<int>(TableEnd::pressure_below)], below) << s;
    EXPECT_EQ(r.beyond_table[static_cast<int>(TableEnd::pressure_above)], above) << s;
    if (s == 1 || s == 200) {
      std::printf(
          "step %d: tool reaction %.12f N, sum mu(p_i) F_n %.12f N; %d nodes below the "
          "table, %d above\n",
          s, r.force_on_tool.x(), reaction, below, above);
    }
  }
  std::printf("node friction forces against mu(p_i) F_n: worst relative error %.2e\n", worst);
  // Above a tool triangle's edge (the nodes on y = 0 are) the normal is the node's offset from its
  // closest point made unit, true to ~1e-15: the normal force (up to 30 N) leaks ~1e-14 N into x
  // beside a friction force of 1 to 3 N (5.8e-13 relative at the most), so 1e-11.
  EXPECT_LT(worst, 1e-11);
}

}  // namespace
}  // namespace sf
