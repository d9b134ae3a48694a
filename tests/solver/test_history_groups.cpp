// History groups ([[history]]): the summed reactions of held nodes against the loads they carry,
// in a static analysis (equilibrium to the Newton tolerance) and an explicit run (the inertia of
// a prescribed motion, m a, exactly; a damped cantilever at rest), and the mean rotation against
// the beam formula.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "casefile/case_config.hpp"
#include "model/build_model.hpp"
#include "solver/case_fixture.hpp"
#include "solver/explicit_driver.hpp"
#include "solver/group_history.hpp"
#include "solver/reactions.hpp"
#include "solver/static_driver.hpp"

namespace fs = std::filesystem;

namespace {

constexpr double kLength = 100.0;                           // mm, tests/data/strip.geo
constexpr double kYoung = 210000.0;                         // MPa
constexpr double kInertia = 10.0 * 2.0 * 2.0 * 2.0 / 12.0;  // mm^4, 10 x 2 mm section

// The elastic strip of tests/data/strip.geo (clamped at x = 0 unless `boundaries` says otherwise)
// with `extra` (loads, [[history]], [analysis], [implicit], [control], ...).
sf::Model build_strip(const std::string& name, const std::string& extra, bool clamped = true) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "case.toml")
      << "[blank]\nmesh = \"" << (fs::path(SF_TEST_DATA_DIR) / "strip.geo").string()
      << "\"\nthickness = 2.0\nmaterial = \"steel\"\n"
         "[materials.steel]\ntype = \"elastic\"\ndensity = 7.85e-9\nyoung = 210000.0\n"
         "poisson = 0.0\n"
      << (clamped ? "[[boundary]]\ngroup = \"clamp\"\ntype = \"fixed\"\n" : "") << extra;
  return sf::build_model(sf::read_case(folder / "case.toml"));
}

const sf::HistoryGroupResult& group_result(const sf::RunSummary& summary,
                                           const std::string& group) {
  for (const sf::HistoryGroupResult& g : summary.history_groups) {
    if (g.group == group) {
      return g;
    }
  }
  throw std::logic_error("no history group " + group);
}

TEST(HistoryGroups, StaticClampReactionBalancesTheTipLoad) {
  // 10 N up at the tip (5 N on each of its nodes), geometrically nonlinear, Newton to 1e-11.
  sf::Model model = build_strip("history_static_cantilever", R"(
[[load]]
group = "tip"
type = "force"
value = [0.0, 0.0, 5.0]
[[history]]
group = "clamp"
[[history]]
group = "tip"
[analysis]
type = "static"
[implicit]
increments = 4
force_tolerance = 1e-11
displacement_tolerance = 1e-11
[control]
end_time = 1.0
)");
  sf::RunOptions options;
  options.write_results = false;
  const sf::RunSummary summary = sf::run_static(model, options);
  const sf::GroupMeasures& clamp = group_result(summary, "clamp").values;
  const sf::GroupMeasures& tip = group_result(summary, "tip").values;
  // Equilibrium: every element's nodal forces sum to zero, so the reactions on the held degrees
  // of freedom balance the load up to the residual of the free ones (1e-11 of the reference
  // force): -10 N in z, nothing else.
  EXPECT_NEAR(clamp.reaction_force.z(), -10.0, 1e-8 * 10.0);
  EXPECT_NEAR(clamp.reaction_force.x(), 0.0, 1e-8 * 10.0);
  EXPECT_NEAR(clamp.reaction_force.y(), 0.0, 1e-8 * 10.0);
  // Moment about the clamp's line (x = 0, z = 0): the clamp's nodal moments carry the load's
  // moment on the deformed strip, 10 N x (L + the tip's mean u_x). The drilling springs (about
  // the nodal normals) carry no y moment on this planar bending.
  EXPECT_NEAR(clamp.reaction_moment.y(), 10.0 * (kLength + tip.displacement.x()), 1e-8 * 1000.0);
  // The clamp does not move; the tip's mean rotation about -y is within 0.1 % of the beam's
  // P L^2 / (2 E I) = 0.035714 rad (measured 0.047 % below it: 20 one-point elements, and the
  // strip's u_z / L of 2.4 % shortens the lever arm).
  EXPECT_EQ(clamp.displacement.norm(), 0.0);
  EXPECT_EQ(clamp.rotation.norm(), 0.0);
  const double theta = 10.0 * kLength * kLength / (2.0 * kYoung * kInertia);
  EXPECT_NEAR(-tip.rotation.y() / theta, 1.0, 1e-3) << "tip rotation " << tip.rotation.y();
}

TEST(HistoryGroups, LinearStaticClampReactionBalancesTheTipLoad) {
  // The same strip, one linear solve: the reactions come from the linear problem's forces, K u
  // and the loads on the undeformed geometry, so they balance the load to the linear solve's
  // residual (measured 1.6e-10), on the undeformed lever arm L (the forces at the displaced
  // solution would miss the balance by 8e-4 of the load in x).
  sf::Model model = build_strip("history_linear_cantilever", R"(
[[load]]
group = "tip"
type = "force"
value = [0.0, 0.0, 5.0]
[[history]]
group = "clamp"
quantities = ["reaction"]
[analysis]
type = "static"
geometry = "linear"
[control]
end_time = 1.0
)");
  sf::RunOptions options;
  options.write_results = false;
  const sf::RunSummary summary = sf::run_static(model, options);
  const sf::GroupMeasures& clamp = group_result(summary, "clamp").values;
  EXPECT_NEAR(clamp.reaction_force.z(), -10.0, 1e-8 * 10.0);
  EXPECT_NEAR(clamp.reaction_force.x(), 0.0, 1e-8 * 10.0);
  EXPECT_NEAR(clamp.reaction_force.y(), 0.0, 1e-8 * 10.0);
  EXPECT_NEAR(clamp.reaction_moment.y(), 10.0 * kLength, 1e-8 * 1000.0);
}

TEST(HistoryGroups, ExplicitReactionOfAPrescribedMotionIsItsInertiaLessTheLoad) {
  // Every node moves rigidly with the prescribed velocity (100, 0, 0) mm/s ramped up over
  // 0.1 ms (a = 1e6 mm/s^2) and held from then on, while a 10 N tip load pulls in z: the strip
  // is not strained (zero internal forces), so the constraints supply m a - f_ext exactly.
  sf::Model model = build_strip("history_explicit_translation", R"(
[[load]]
group = "tip"
type = "force"
value = [0.0, 0.0, 5.0]
[[prescribed_velocity]]
group = "blank"
velocity = [100.0, 0.0, 0.0]
curve = [[0.0, 0.0], [1e-4, 1.0]]
[[history]]
group = "blank"
[control]
end_time = 2e-4
)",
                                false);
  sf::SolutionState s = sf::make_initial_state(model);
  sf::compute_forces(model, s, 0.0);
  const std::vector<int>& all = model.blank.group("blank").nodes;
  const double mass = model.blank.mass.sum();  // tonne
  sf::Matrix3X force, moment;                  // N, N mm per node
  int checked_ramp = 0, checked_held = 0;
  sf::test::run_to_end(model, s, [&](const sf::SolutionState& state) {
    // Steps whose half-step window [t - dt/2, t + dt/2] lies inside the ramp or after it.
    const double h = 0.5 * state.dt;
    const bool in_ramp = state.time + h < 1e-4;
    const bool after = state.time - h > 1e-4;
    if (!in_ramp && !after) {
      return;
    }
    sf::compute_reactions(model, state, force, moment);
    const sf::GroupMeasures m = sf::measure_group(model, state, all, {force, moment});
    const double expected_x = in_ramp ? mass * 100.0 / 1e-4 : 0.0;  // N: m a
    EXPECT_NEAR(m.reaction_force.x(), expected_x, 1e-9 * mass * 1e6) << "t = " << state.time;
    EXPECT_NEAR(m.reaction_force.z(), -10.0, 1e-12 * 10.0) << "t = " << state.time;
    EXPECT_NEAR(m.reaction_force.y(), 0.0, 1e-12 * 10.0);
    EXPECT_EQ(m.reaction_moment.norm(), 0.0);  // no rotation is held
    (in_ramp ? checked_ramp : checked_held) += 1;
  });
  EXPECT_GT(checked_ramp, 10);
  EXPECT_GT(checked_held, 10);
}

TEST(HistoryGroups, ExplicitClampReactionOfADampedCantileverAtRest) {
  // A 10 N tip load held from the start, mass-proportional damping of 2000 1/s, about the first
  // mode's critical value 2 omega1 = 2.1e3 1/s (omega1 = 1.8751^2 sqrt(E I / (rho A L^4))): after
  // 30 ms (5 periods of 6 ms) the strip is at rest (kinetic energy 1e-17 N mm, measured) and the
  // clamp's reaction (f_int - f_ext on its held components) carries the load: -10 N and the
  // load's moment about the clamp, 10 N x (L + the tip's mean u_x). Measured: both within 1.4e-14
  // relative; 1e-9 leaves room for the strip's last motion.
  sf::Model model = build_strip("history_explicit_damped", R"(
[[load]]
group = "tip"
type = "force"
value = [0.0, 0.0, 5.0]
[[history]]
group = "clamp"
quantities = ["reaction"]
[[history]]
group = "tip"
quantities = ["displacement"]
[control]
end_time = 0.03
damping = 2000.0
)");
  sf::RunOptions options;
  options.write_results = false;
  const sf::RunSummary summary = sf::run_explicit(model, options);
  const sf::GroupMeasures& clamp = group_result(summary, "clamp").values;
  const sf::GroupMeasures& tip = group_result(summary, "tip").values;
  EXPECT_NEAR(clamp.reaction_force.z(), -10.0, 1e-9 * 10.0);
  EXPECT_NEAR(clamp.reaction_moment.y(), 10.0 * (kLength + tip.displacement.x()), 1e-9 * 1000.0);
}

}  // namespace
