// Regularised Coulomb friction: the kernel (src/contact/coulomb_friction.hpp) and its use in
// compute_penalty_contact. References: the Coulomb limit |F_t| <= mu |F_n| and the return
// mapping's closed forms (stick: F = k_t u; steady sliding: F = mu F_n, dissipation mu F_n times
// the slip); the decay law mu(v) = mu_d + (mu_s - mu_d) exp(-c |v|) (LS-DYNA's, grade C: the
// tests check the implementation of that formula, not the formula).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <numbers>
#include <random>

#include "allocation_counter.hpp"
#include "contact/coulomb_friction.hpp"
#include "contact/penalty_contact.hpp"
#include "contact_pair_fixture.hpp"
#include "core/errors.hpp"
#include "test_meshes.hpp"

namespace sf {
namespace {

using test::Contact;
using test::make_law;
using test::make_pair;

TEST(CoulombFriction, CoefficientDecayAndValidation) {
  const FrictionParameters law = make_law(0.3, 0.2, 0.01);
  EXPECT_DOUBLE_EQ(law.coefficient(0), 0.3);
  EXPECT_DOUBLE_EQ(law.coefficient(100), 0.2 + 0.1 * std::exp(-1.0));
  EXPECT_DOUBLE_EQ(law.coefficient(-100), law.coefficient(100));
  EXPECT_NEAR(law.coefficient(1e5), 0.2, 1e-15);
  EXPECT_TRUE(law.active());
  EXPECT_FALSE(FrictionParameters{}.active());
  EXPECT_NO_THROW(law.validate("die"));
  EXPECT_THROW(make_law(0.2, 0.3, 0).validate("die"), InputError);  // mu_d > mu_s
  EXPECT_THROW(make_law(0.3, -0.1, 0).validate("die"), InputError);
  EXPECT_THROW(make_law(0.3, 0.2, -1).validate("die"), InputError);
  FrictionParameters stiff = law;
  stiff.tangential_stiffness_ratio = 1.5;  // beyond the penalty stiffness cap
  EXPECT_THROW(stiff.validate("die"), InputError);
  try {
    make_law(0.2, 0.3, 0).validate("die");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("die"), std::string::npos);
  }
}

Vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return Vec3(g(rng), g(rng), g(rng)).normalized();
}

TEST(CoulombFriction, RandomHistoriesStayInsideTheConeAndDissipate) {
  // Random normals (small tilts and sudden jumps), increments from 1e-6 to 1 mm, normal forces
  // from 0 to 100 N: the force stays within mu(v) F_n and tangent, the work is >= 0 and equals
  // the force times the slip.
  const FrictionParameters law = make_law(0.4, 0.25, 0.05);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(0, 1);
  const double k_t = 500, dt = 1e-4;
  Vec3 stored = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  int slides = 0, sticks = 0;
  for (int k = 0; k < 20000; ++k) {
    if (u(rng) < 0.05) {
      normal = random_unit(rng);
    } else {
      normal = (normal + 0.05 * random_unit(rng)).normalized();
    }
    const Vec3 increment = std::pow(10.0, -6 * u(rng)) * random_unit(rng);
    const double fn = u(rng) < 0.05 ? 0.0 : 100 * u(rng);
    const FrictionStep step = coulomb_friction_update(law, stored, normal, increment, dt, fn, k_t);
    const Vec3 du_t = increment - normal.dot(increment) * normal;
    const double limit = law.coefficient(du_t.norm() / dt) * fn;
    ASSERT_LE(step.force.norm(), limit * (1 + 1e-14)) << "step " << k;
    ASSERT_LE(std::abs(step.force.dot(normal)), 1e-14 * (1 + step.force.norm()));
    ASSERT_GE(step.work, 0.0);
    ASSERT_GE(step.slip, 0.0);
    ASSERT_NEAR(step.work, step.force.norm() * step.slip, 1e-12 * (1 + step.work));
    ASSERT_EQ(stored, step.force);
    ++(step.sliding ? slides : sticks);
  }
  EXPECT_GT(slides, 1000);
  EXPECT_GT(sticks, 1000);
}

TEST(CoulombFriction, TiltingNormalKeepsTheStoredForceTangent) {
  // A stuck node (no relative motion) whose normal tilts by 1 degree per step about a fixed
  // axis, 80 steps: the stored force follows the tangent plane and keeps its length (below the
  // limit nothing slips).
  const FrictionParameters law = make_law(0.5, 0.5, 0);
  Vec3 stored(3.0, 4.0, 0.0);  // 5 N in the plane of n = z
  const Vec3 axis = Vec3(1, -2, 0).normalized();
  for (int k = 1; k <= 80; ++k) {
    const Vec3 normal = Eigen::AngleAxisd(k * std::numbers::pi / 180, axis) * Vec3::UnitZ();
    const FrictionStep step =
        coulomb_friction_update(law, stored, normal, Vec3::Zero(), 1e-4, 100.0, 1000.0);
    EXPECT_FALSE(step.sliding);
    EXPECT_NEAR(stored.dot(normal), 0, 1e-14);
    EXPECT_NEAR(stored.norm(), 5.0, 1e-13);
  }
}

TEST(CoulombFriction, SteadySlidingForceFollowsTheDecayLaw) {
  // Kinematic sliding at speeds from 0.1 to 1000 mm/s under F_n = 50 N: after the elastic
  // build-up the force is mu(v) F_n, opposite to the motion, to round-off; it falls from
  // mu_s F_n toward mu_d F_n as the speed grows (the static -> dynamic transition).
  const FrictionParameters law = make_law(0.3, 0.15, 0.02);
  const double fn = 50, k_t = 200, dt = 1e-4;
  double previous = 1e300;
  for (double speed : {0.1, 1.0, 10.0, 100.0, 1000.0}) {
    Vec3 stored = Vec3::Zero();
    const Vec3 increment(speed * dt, 0, 0);
    // The limit is reached after mu F_n / (k_t v dt) steps.
    const int steps = static_cast<int>(0.3 * fn / (k_t * speed * dt)) + 10;
    FrictionStep step;
    for (int k = 0; k < steps; ++k) {
      step = coulomb_friction_update(law, stored, Vec3::UnitZ(), increment, dt, fn, k_t);
    }
    const double expected = law.coefficient(speed) * fn;
    std::printf("slip speed %7.1f mm/s: friction force %.6f N (mu %.6f)\n", speed,
                step.force.norm(), step.force.norm() / fn);
    EXPECT_TRUE(step.sliding);
    EXPECT_NEAR(step.force.x(), -expected, 1e-13 * expected);
    EXPECT_LT(expected, previous);
    previous = expected;
  }
}

/// Flat tool z = 0 over [-50, 50]^2, normals +z.
TriangleSurface make_table() {
  return test::make_height_field("table", 4, 4, -50, 50, -50, 50,
                                 [](double, double) { return 0.0; });
}

TEST(PenaltyFriction, BlockPulledAtConstantVelocity) {
  // Four nodes pressed 0.1 mm into a flat tool (k = 1000 N/mm: F_n = 100 N each), pulled along
  // x at V = 50 mm/s; c = 1 s/mm makes exp(-c V) = 2e-22, so mu = mu_d. Two frames: the nodes
  // move over a fixed tool, or the tool moves under fixed nodes -- the same relative motion.
  // Expected: after k_t x limit build-up, a steady force mu_d F_n per node against the motion;
  // the friction work is mu_d F_n times the slip, the slip being the travel less the elastic
  // stick displacement mu_d F_n / k_t (all collinear: exact to round-off).
  const FrictionParameters law = make_law(0.3, 0.2, 1.0);
  const TriangleSurface table = make_table();
  const double k = 1000, h = 0.5, speed = 50, dt = 1e-5, fn = 100;
  const int n = 4, steps = 2000;  // travel 1 mm
  for (bool tool_moves : {false, true}) {
    Contact pair = make_pair(table, n, k, law);
    Matrix3X x(3, n);
    x << 0, 1, 0, 1,  //
        0, 0, 1, 1,   //
        0.4, 0.4, 0.4, 0.4;
    const Matrix3X v =
        tool_moves ? Matrix3X::Zero(3, n) : Matrix3X(Vec3(speed, 0, 0).replicate(1, n));
    const VectorX half = VectorX::Constant(n, h);
    Vec3 tool = Vec3::Zero();
    Matrix3X f(3, n);
    double work = 0;
    ContactResult r;
    for (int s = 1; s <= steps; ++s) {
      Vec3 tool_step = Vec3::Zero();
      if (tool_moves) {
        tool_step = Vec3(-speed * dt, 0, 0);
        tool += tool_step;
      } else {
        x.row(0).array() += speed * dt;
      }
      f.setZero();
      r = compute_penalty_contact(pair.pair, pair.state, {x, v, half, tool, tool_step, dt}, f);
      ASSERT_GE(r.friction_work, 0.0);
      work += r.friction_work;
    }
    const double limit = law.coefficient(speed) * fn;
    EXPECT_NEAR(limit, 0.2 * fn, 1e-12);
    EXPECT_EQ(r.sliding_nodes, n);
    EXPECT_EQ(r.nodes_in_contact, n);
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR((f.col(i) - Vec3(-limit, 0, fn)).norm(), 0, 1e-10);
    }
    EXPECT_NEAR((r.force_on_tool - Vec3(n * limit, 0, -n * fn)).norm(), 0, 1e-9);
    const double travel = steps * speed * dt;
    const double slip = travel - limit / (law.tangential_stiffness_ratio * k);
    std::printf("block (%s moves): friction work %.12f N mm, mu_d F_n x slip %.12f N mm\n",
                tool_moves ? "tool" : "block", work, n * limit * slip);
    EXPECT_NEAR(work, n * limit * slip, 1e-12 * n * limit * slip);
  }
}

/// A point mass m pressed onto the flat tool by P (N, along -z) and pulled along x by
/// pull(t) (N), central differences: returns the largest x displacement over [0, t_end], the
/// friction work and the number of steps in which it slid.
struct PullResult {
  double max_x = 0, final_x = 0, work = 0, pull_at_first_slide = -1;
  int sliding_steps = 0;
};

template <class Pull>
PullResult pull_pressed_mass(const FrictionParameters& law, double m, double k, double press,
                             Pull pull, double dt, double t_end) {
  const TriangleSurface table = make_table();
  Contact pair = make_pair(table, 1, k, law);
  const double h = 0.5;
  Matrix3X x = Vec3(0, 0, h - press / k);  // normal equilibrium: k (-g) = P
  Matrix3X v = Matrix3X::Zero(3, 1);       // mid-step velocity
  const VectorX half = VectorX::Constant(1, h);
  Matrix3X f(3, 1);
  PullResult out;
  double dt_taken = 0, t = 0;
  while (t < t_end) {
    f.setZero();
    const ContactResult r = compute_penalty_contact(
        pair.pair, pair.state, {x, v, half, Vec3::Zero(), Vec3::Zero(), dt_taken}, f);
    out.work += r.friction_work;
    if (r.sliding_nodes > 0) {
      if (out.sliding_steps == 0) {
        out.pull_at_first_slide = pull(t);
      }
      ++out.sliding_steps;
    }
    const Vec3 force = f.col(0) + Vec3(pull(t), 0, -press);
    v.col(0) += (dt / m) * force;
    x.col(0) += dt * v.col(0);
    t += dt;
    dt_taken = dt;
    out.max_x = std::max(out.max_x, std::abs(x(0, 0)));
  }
  out.final_x = x(0, 0);
  return out;
}

TEST(PenaltyFriction, SticksBelowTheStaticLimitAndSlidesAbove) {
  // m = 1e-3 t, k = k_t = 1000 N/mm (period 2 pi sqrt(m/k) = 6.3 ms), dt = 1e-5 s, P = 100 N,
  // mu_s = 0.3, mu_d = 0.2, c = 0.01 s/mm. The pull ramps over 0.2 s (32 periods: quasi-static)
  // to F_max and is then held for 0.05 s.
  const FrictionParameters law = make_law(0.3, 0.2, 0.01);
  const double m = 1e-3, k = 1000, press = 100, dt = 1e-5, ramp = 0.2;
  {
    const double f_max = 0.5 * 0.3 * press;  // 15 N
    const auto pull = [=](double t) { return f_max * std::min(t / ramp, 1.0); };
    const PullResult r = pull_pressed_mass(law, m, k, press, pull, dt, ramp + 0.05);
    std::printf(
        "pull 15 N (half of mu_s P): max displacement %.6f mm (F/k_t = %.6f), slid in "
        "%d steps, friction work %.3e N mm\n",
        r.max_x, f_max / k, r.sliding_steps, r.work);
    EXPECT_EQ(r.sliding_steps, 0);
    EXPECT_EQ(r.work, 0.0);
    // The elastic stick displacement F / k_t, up to the small dynamic overshoot of the ramp.
    EXPECT_LE(r.max_x, 1.01 * f_max / k);
    EXPECT_NEAR(r.final_x, f_max / k, 0.01 * f_max / k);
  }
  {
    const double f_max = 1.5 * 0.3 * press;  // 45 N
    const auto pull = [=](double t) { return f_max * std::min(t / ramp, 1.0); };
    const PullResult r = pull_pressed_mass(law, m, k, press, pull, dt, ramp + 0.05);
    std::printf(
        "pull 45 N (1.5 mu_s P): first slide at a pull of %.4f N (mu_s P = 30 N), "
        "final displacement %.3f mm, friction work %.4f N mm\n",
        r.pull_at_first_slide, r.final_x, r.work);
    EXPECT_GT(r.sliding_steps, 0);
    // Sliding starts when the pull reaches mu_s P; the creep speed before it (ramp rate / k_t =
    // 0.2 mm/s) lowers mu by only (mu_s - mu_d)(1 - exp(-0.002)) = 2e-4.
    EXPECT_NEAR(r.pull_at_first_slide, 0.3 * press, 0.01 * 0.3 * press);
    EXPECT_GT(r.final_x, 100 * f_max / k);  // far beyond any elastic displacement
    EXPECT_GT(r.work, 0.0);
  }
}

TEST(PenaltyFriction, ForceWithinTheConeAndWorkNonNegativeOnRandomHistories) {
  // 50 nodes with random velocities, pressed by random amounts, against a flat tool moving at a
  // random velocity; the force's tangential part never exceeds mu(v) times its normal part (the
  // tool normal is z), and the work of every call is >= 0.
  const FrictionParameters law = make_law(0.35, 0.2, 0.003);
  const TriangleSurface table = make_table();
  const int n = 50;
  Contact pair = make_pair(table, n, 800, law);
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1, 1);
  Matrix3X x(3, n), v(3, n), f(3, n);
  for (int i = 0; i < n; ++i) {
    x.col(i) = Vec3(10 * u(rng), 10 * u(rng), 0.5 + 0.3 * u(rng));
  }
  const VectorX half = VectorX::Constant(n, 0.5);
  const double dt = 1e-4;
  Vec3 tool = Vec3::Zero();
  int sliding = 0, sticking = 0;
  for (int s = 0; s < 2000; ++s) {
    for (int i = 0; i < n; ++i) {
      v.col(i) = Vec3(200 * u(rng), 200 * u(rng), 50 * u(rng)) * (u(rng) > 0 ? 1.0 : 0.01);
    }
    const Vec3 tool_step = dt * Vec3(100 * u(rng), 100 * u(rng), 0);
    tool += tool_step;
    x += dt * v;
    x.row(2) = x.row(2).cwiseMax(0.1).cwiseMin(0.9);  // keep them near the tool
    f.setZero();
    const ContactResult r =
        compute_penalty_contact(pair.pair, pair.state, {x, v, half, tool, tool_step, dt}, f);
    ASSERT_GE(r.friction_work, 0.0);
    sliding += r.sliding_nodes;
    sticking += r.sticking_nodes;
    for (int i = 0; i < n; ++i) {
      if (f(2, i) == 0) {
        continue;
      }
      const Vec3 du = dt * v.col(i) - tool_step;
      const double mu = law.coefficient(std::hypot(du.x(), du.y()) / dt);
      ASSERT_LE(std::hypot(f(0, i), f(1, i)), mu * f(2, i) * (1 + 1e-14)) << i;
    }
  }
  EXPECT_GT(sliding, 1000);
  EXPECT_GT(sticking, 1000);
}

TEST(PenaltyFriction, LeavingContactResetsTheStickForce) {
  const FrictionParameters law = make_law(0.3, 0.3, 0);
  const TriangleSurface table = make_table();
  Contact pair = make_pair(table, 1, 1000, law);
  const VectorX half = VectorX::Constant(1, 0.5);
  Matrix3X x = Vec3(0, 0, 0.45);  // F_n = 50 N
  const Matrix3X v = Vec3(10, 0, 0);
  Matrix3X f = Matrix3X::Zero(3, 1);
  // A 0.01 mm tangential step: stick force -10 N.
  compute_penalty_contact(pair.pair, pair.state, {x, v, half, Vec3::Zero(), Vec3::Zero(), 1e-3}, f);
  EXPECT_NEAR(f(0, 0), -10.0, 1e-12);
  EXPECT_NEAR(pair.state.stick_force(0, 0), -10.0, 1e-12);
  // Lifted off: no force, the stored force is cleared.
  x(2, 0) = 0.6;
  f.setZero();
  const Matrix3X rest = Matrix3X::Zero(3, 1);
  compute_penalty_contact(pair.pair, pair.state, {x, rest, half, Vec3::Zero(), Vec3::Zero(), 1e-3},
                          f);
  EXPECT_EQ(f.norm(), 0.0);
  EXPECT_EQ(pair.state.stick_force.norm(), 0.0);
  // Back in contact at rest: the normal force only.
  x(2, 0) = 0.45;
  f.setZero();
  const ContactResult r = compute_penalty_contact(
      pair.pair, pair.state, {x, rest, half, Vec3::Zero(), Vec3::Zero(), 1e-3}, f);
  EXPECT_NEAR((f.col(0) - Vec3(0, 0, 50)).norm(), 0, 1e-12);
  EXPECT_EQ(r.sticking_nodes, 1);
}

TEST(PenaltyFriction, ContactStepDoesNotAllocate) {
  // Interpolated projection and friction on a warped tool; the first call sizes the state. Coulomb
  // friction, then every law beyond it at once (power law, speed table, orthotropic ratio).
  const TriangleSurface s = test::make_height_field(
      "warped", 20, 20, -5, 5, -5, 5,
      [](double x, double y) { return 0.8 * std::sin(0.7 * x) * std::cos(0.5 * y); });
  const int n = 100;
  FrictionParameters shaped = make_law(0.15, 0.15, 0);
  shaped.pressure_exponent = 0.8;
  shaped.reference_pressure = 10.0;
  shaped.speed_table.x = {0.0, 10.0, 100.0};
  shaped.speed_table.y = {1.0, 0.9, 0.8};
  shaped.across_ratio = 0.7;
  for (const FrictionParameters& law : {make_law(0.3, 0.2, 0.01), shaped}) {
    Contact pair = make_pair(s, n, 500, law);
    pair.pair.start_area = VectorX::Constant(n, 1.0);  // mm^2, for the pressure
    pair.pair.start_half_thickness = VectorX::Constant(n, 0.5);
    pair.pair.projection = ContactProjection::interpolated;
    pair.pair.projector = std::make_unique<InterpolatedProjector>(s);
    std::mt19937 rng(29);
    std::uniform_real_distribution<double> u(-4, 4);
    Matrix3X x(3, n), v(3, n), f(3, n);
    for (int i = 0; i < n; ++i) {
      const double px = u(rng), py = u(rng);
      x.col(i) = Vec3(px, py, 0.8 * std::sin(0.7 * px) * std::cos(0.5 * py) + 0.1 * u(rng));
      v.col(i) = Vec3(20 * u(rng), 20 * u(rng), 0);
    }
    const VectorX half = VectorX::Constant(n, 0.5);
    const double dt = 1e-4;
    f.setZero();
    compute_penalty_contact(pair.pair, pair.state, {x, v, half, Vec3::Zero(), Vec3::Zero(), dt},
                            f);  // sizes state
    const long before = test::allocation_count();
    int in_contact = 0;
    for (int step = 0; step < 20; ++step) {
      x += dt * v;
      f.setZero();
      in_contact += compute_penalty_contact(pair.pair, pair.state,
                                            {x, v, half, Vec3::Zero(), Vec3::Zero(), dt}, f)
                        .nodes_in_contact;
    }
    EXPECT_EQ(test::allocation_count() - before, 0);
    EXPECT_GT(in_contact, 0);
  }
}

}  // namespace
}  // namespace sf
