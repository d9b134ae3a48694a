// ForceControlledTool: the central-difference step of a force-driven rigid tool, against what the
// scheme must give exactly (derivations beside each test).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "model/force_controlled_tool.hpp"

namespace {

// Constant force F on a free tool of mass M, from rest, with steps that vary at random by a factor
// 3. The scheme v(n+1/2) = v(n-1/2) + (dt(n-1/2) + dt(n+1/2)) / 2 a, v(1/2) = dt(1/2) / 2 a,
// s(n+1) = s(n) + dt(n+1/2) v(n+1/2) gives by induction v(n+1/2) = a (t(n) + dt(n+1/2) / 2), the
// exact velocity at the mid-step time, so s(n+1) - s(n) = a (t(n+1)^2 - t(n)^2) / 2: the travel is
// exactly a t^2 / 2 at every step, for any sequence of steps (the velocity is linear in time and
// the midpoint rule integrates it exactly). The whole-step velocity v(n+1/2) + dt/2 a = a t(n+1).
// Checked to round-off: 1e-13 relative over 1000 steps (measured 2.0e-15).
TEST(ForceControlledTool, ConstantForceGivesTheExactTravelForAnySteps) {
  const double force = 4900.0;  // N
  const double mass = 1.2e-5;   // tonne
  const double a = force / mass;
  const sf::ForceControlledTool tool(sf::Vec3(0.0, 0.0, -2.0), sf::LoadCurve({0.0}, {force}), mass,
                                     0.0);
  EXPECT_EQ(tool.direction(), sf::Vec3(0.0, 0.0, -1.0));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> factor(0.5, 1.5);
  double t = 0.0, velocity = 0.0, travel = 0.0, dt_previous = 0.0, worst = 0.0;
  const sf::Vec3 no_reaction = sf::Vec3::Zero();
  for (int n = 0; n < 1000; ++n) {
    const double dt = 4e-7 * factor(random);
    const double weight = dt_previous > 0.0 ? 0.5 * (dt_previous + dt) : 0.5 * dt;
    tool.step(t, no_reaction, weight, dt, velocity, travel);
    EXPECT_NEAR(velocity, a * (t + 0.5 * dt), 1e-13 * a * (t + dt));
    t += dt;
    dt_previous = dt;
    worst = std::max(worst, std::abs(travel / (0.5 * a * t * t) - 1.0));
    EXPECT_NEAR(tool.whole_step_velocity(t, no_reaction, velocity, dt), a * t, 1e-13 * a * t);
  }
  std::printf("travel after %.4e s: %.10e mm (F t^2 / 2M = %.10e), worst relative error %.2e\n", t,
              travel, 0.5 * a * t * t, worst);
  EXPECT_LT(worst, 1e-13);
}

// The tool on a linear spring: reaction R = -k s d (the blank as a spring of stiffness k pushing
// back along the axis), constant force F, from rest, constant step. Taking R(n) from the travel
// s(n) of the same step (what the driver does: the contact at t(n) sees the tool at t(n)), the
// scheme is central difference for M s'' = F - k s:
//   s(n+1) - 2 s(n) + s(n-1) = (w dt)^2 (s_eq - s(n)),  s_eq = F / k,  w^2 = k / M,
// with s(0) = 0 and s(1) = (w dt)^2 s_eq / 2 from the half first step. Its exact solution is
//   s(n) = s_eq (1 - cos(n theta)),  cos(theta) = 1 - (w dt)^2 / 2,
// (the start values fix the cosine's amplitude to -s_eq and the sine's to zero): stable for
// w dt < 2, with the phase error theta / dt - w = w (w dt)^2 / 24 + ..., second order. Checked to
// round-off over 2000 steps at w dt = 0.5 and 1.9 (near the limit): 1e-11 of s_eq (measured
// 1.5e-13 and 1.8e-12). A step that took R from the previous travel (a one-step lag) would not
// satisfy it.
TEST(ForceControlledTool, OnASpringItIsExactlyCentralDifference) {
  for (const double w_dt : {0.5, 1.9}) {
    const double force = 1000.0, mass = 1e-5, stiffness = 2e6;  // N, tonne, N/mm
    const double w = std::sqrt(stiffness / mass);
    const double dt = w_dt / w;
    const sf::Vec3 d(0.0, 0.0, -1.0);
    const sf::ForceControlledTool tool(d, sf::LoadCurve({0.0}, {force}), mass, 0.0);
    const double s_eq = force / stiffness;
    const double theta = std::acos(1.0 - 0.5 * w_dt * w_dt);
    double velocity = 0.0, travel = 0.0, worst = 0.0;
    for (int n = 0; n < 2000; ++n) {
      const sf::Vec3 reaction = -stiffness * travel * d;  // the spring pushes the tool back
      tool.step(n * dt, reaction, n == 0 ? 0.5 * dt : dt, dt, velocity, travel);
      worst = std::max(worst, std::abs(travel - s_eq * (1.0 - std::cos((n + 1) * theta))));
    }
    std::printf("w dt = %.2f: max |s - s_eq (1 - cos(n theta))| = %.2e of s_eq\n", w_dt,
                worst / s_eq);
    EXPECT_LT(worst, 1e-11 * s_eq);
  }
}

// A gas spring (force_of = "travel"): the force F(s) = F0 - k s of the tool's own travel, no
// blank. The scheme is the same central difference as on the blank's spring above, with the
// force taken at the travel s(n) of the step: s(n) = s_eq (1 - cos(n theta)), s_eq = F0 / k,
// cos(theta) = 1 - (w dt)^2 / 2, w^2 = k / M; 1e-11 of s_eq over 2000 steps. The curve runs to
// s = 2 s_eq, past the largest travel, so F stays linear. stiffness() is the slope, k.
TEST(ForceControlledTool, AForceOfTheTravelIsASpring) {
  const double f0 = 1000.0, mass = 1e-5, k = 2e6;  // N, tonne, N/mm
  const double s_eq = f0 / k;
  const sf::ForceControlledTool tool(sf::Vec3(0.0, 0.0, -1.0),
                                     sf::LoadCurve({0.0, 2.0 * s_eq}, {f0, f0 - 2.0 * s_eq * k}),
                                     mass, 0.0, true);
  EXPECT_TRUE(tool.of_travel());
  EXPECT_DOUBLE_EQ(tool.stiffness(), k);
  EXPECT_DOUBLE_EQ(tool.applied_force(123.0, 0.5 * s_eq), 0.5 * f0);  // the time plays no part
  const double w_dt = 0.7;
  const double dt = w_dt / std::sqrt(k / mass);
  const double theta = std::acos(1.0 - 0.5 * w_dt * w_dt);
  double velocity = 0.0, travel = 0.0, worst = 0.0;
  for (int n = 0; n < 2000; ++n) {
    tool.step(n * dt, sf::Vec3::Zero(), n == 0 ? 0.5 * dt : dt, dt, velocity, travel);
    worst = std::max(worst, std::abs(travel - s_eq * (1.0 - std::cos((n + 1) * theta))));
  }
  EXPECT_LT(worst, 1e-11 * s_eq);
  // A force of the time has no stiffness.
  EXPECT_EQ(sf::ForceControlledTool(sf::Vec3(0.0, 0.0, -1.0), sf::LoadCurve({0.0, 1.0}, {0.0, 9.0}),
                                    mass, 0.0)
                .stiffness(),
            0.0);
}

TEST(ForceControlledTool, RateHasTheForceTheReactionAndTheDamping) {
  const sf::ForceControlledTool tool(sf::Vec3(1.0, 0.0, 0.0),
                                     sf::LoadCurve({0.0, 1.0}, {0.0, 100.0}), 2.0, 3.0);
  // F(0.5) = 50 N; the reaction's x component -10 N pushes back; damping 3 1/s on v = 4 mm/s.
  EXPECT_DOUBLE_EQ(tool.applied_force(0.5), 50.0);
  EXPECT_DOUBLE_EQ(tool.rate(0.5, sf::Vec3(-10.0, 7.0, 9.0), 4.0), (50.0 - 10.0) / 2.0 - 3.0 * 4.0);
  EXPECT_THROW(
      sf::ForceControlledTool(sf::Vec3(1.0, 0.0, 0.0), sf::LoadCurve({0.0}, {1.0}), 0.0, 0.0),
      std::invalid_argument);
}

}  // namespace
