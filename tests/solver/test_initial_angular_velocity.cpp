// [[initial_velocity]] angular_velocity: the nodes' rotational velocities at time 0 (rad/s).
// A free elastic plate whose nodes start spinning about x (no translation, so the plate bends and
// twists from rest in a way with no closed form). What is exact: the initial kinetic energy is
// 1/2 sum J |omega|^2 over the nodes given it, a held rotation starts at zero, and the energy
// balance's invariant total - supplied - (D - D_ref) stays at round-off (docs/time-integration.md:
// an identity of central difference for any forces), which fails if the rotational velocities
// are missing from the kinetic energy or the kicks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "case_fixture.hpp"

namespace {

constexpr const char* kGeo = R"(
Point(1) = {0, 0, 0}; Point(2) = {10, 0, 0}; Point(3) = {10, 10, 0}; Point(4) = {0, 10, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 5;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("blank") = {1};
Physical Curve("left") = {4};
)";

constexpr const char* kCase = R"(thickness = 1.0
material = "steel"
[materials.steel]
type = "elastic"
density = 7.85e-9
young = 210000.0
poisson = 0.3
[[boundary]]
group = "left"
type = "hold"
hold = ["rx"]
[[initial_velocity]]
angular_velocity = [200.0, 0.0, 0.0]
[control]
end_time = 2.0e-4
)";

TEST(InitialAngularVelocity, KineticEnergyAndBalanceIncludeTheRotations) {
  sf::Model model = sf::build_model(sf::test::write_case("initial_angular_velocity", kGeo, kCase));
  sf::SolutionState state = sf::make_initial_state(model);
  const std::vector<int>& left = model.blank.group("left").nodes;
  double expected = 0.0;  // N mm
  for (Eigen::Index i = 0; i < state.omega.cols(); ++i) {
    const bool held = std::find(left.begin(), left.end(), static_cast<int>(i)) != left.end();
    EXPECT_EQ(state.omega(0, i), held ? 0.0 : 200.0) << "node " << i;
    EXPECT_EQ(state.v.col(i).norm(), 0.0);
    expected += held ? 0.0 : 0.5 * model.blank.rotational_inertia[i] * 200.0 * 200.0;
  }
  ASSERT_GT(expected, 0.0);
  EXPECT_NEAR(state.energies.initial_kinetic / expected, 1.0, 1e-14);

  sf::compute_forces(model, state, 0.0);
  const double e0 = state.energies.initial_kinetic;
  double max_invariant = 0.0;
  double max_internal = 0.0;
  sf::test::run_to_end(model, state, [&](const sf::SolutionState& s) {
    const sf::Energies& e = s.energies;
    max_invariant =
        std::max(max_invariant, std::abs(e.total() - e.half_kick_change() - e.supplied()) / e0);
    max_internal = std::max(max_internal, e.internal);
  });
  std::printf(
      "initial kinetic %.6e N mm; largest internal energy %.3e N mm; largest "
      "|total - (D - D_ref) - supplied| %.2e of it over %ld cycles\n",
      e0, max_internal, max_invariant, state.cycle);
  EXPECT_GT(max_internal, 0.1 * e0);  // the spin does deform the plate
  EXPECT_LT(max_invariant, 1e-10);    // round-off over the cycles
}

}  // namespace

namespace {

// A velocity field: the first plate mode w' = V sin(pi x / L) sin(pi y / L) with the matching
// rotational velocities (theta_x' = dw'/dy, theta_y' = -dw'/dx), each node given the field's
// value at its initial coordinates, exactly as the library evaluates the same formula.
TEST(InitialVelocityField, EveryNodeTakesTheFieldAtItsCoordinates) {
  const std::string geo_case = std::string(kCase).replace(
      std::string(kCase).find("[[initial_velocity]]"), std::string::npos,
      "[[initial_velocity]]\n"
      "velocity = [0, 0, \"2e4 * sin(pi * x / 10) * sin(pi * y / 10)\"]\n"
      "angular_velocity = [\"2e4 * pi / 10 * sin(pi * x / 10) * cos(pi * y / 10)\",\n"
      "                    \"-2e4 * pi / 10 * cos(pi * x / 10) * sin(pi * y / 10)\", 0]\n"
      "[control]\nend_time = 2.0e-4\n");
  sf::Model model = sf::build_model(sf::test::write_case("initial_velocity_field", kGeo, geo_case));
  const sf::SolutionState state = sf::make_initial_state(model);
  const std::vector<int>& left = model.blank.group("left").nodes;
  const double pi = std::numbers::pi;
  double kinetic = 0.0;
  for (Eigen::Index i = 0; i < state.v.cols(); ++i) {
    const double x = model.blank.mesh.nodes(0, i), y = model.blank.mesh.nodes(1, i);
    const double w = 2e4 * std::sin(pi * x / 10) * std::sin(pi * y / 10);
    const double rx = 2e4 * pi / 10 * std::sin(pi * x / 10) * std::cos(pi * y / 10);
    const double ry = -2e4 * pi / 10 * std::cos(pi * x / 10) * std::sin(pi * y / 10);
    const bool held = std::find(left.begin(), left.end(), static_cast<int>(i)) != left.end();
    EXPECT_EQ(state.v(2, i), w) << "node " << i;
    EXPECT_EQ(state.omega(0, i), held ? 0.0 : rx) << "node " << i;  // rx held on the left edge
    EXPECT_EQ(state.omega(1, i), ry) << "node " << i;
    kinetic += 0.5 * model.blank.mass[i] * w * w +
               0.5 * model.blank.rotational_inertia[i] * ((held ? 0.0 : rx * rx) + ry * ry);
  }
  EXPECT_NEAR(state.energies.initial_kinetic / kinetic, 1.0, 1e-14);
}

}  // namespace
