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
