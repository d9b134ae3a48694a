// Cantilever strip verifications of the shell, the loads and the time loop, against closed forms
// (grade B, /work/shared/REFERENCES.md "Analytic checks for an explicit shell code"):
// - a suddenly applied, held tip force: peak tip deflection 1.966 x the static F L^3 / (3 E I);
// - an end moment M on a strip with nu = 0: the exact elastica is a circular arc of angle
//   theta = M L / (E I), tip at x = (L / theta) sin(theta), z = (L / theta)(1 - cos(theta)).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "io/case_config.hpp"
#include "model/build_model.hpp"
#include "solver/explicit_driver.hpp"

namespace fs = std::filesystem;

namespace {

constexpr double length = 100.0;                                              // mm
constexpr double width = 10.0;                                                // mm
constexpr double thickness = 2.0;                                             // mm
constexpr double young = 210000.0;                                            // MPa
constexpr double density = 7.85e-9;                                           // tonne/mm^3
constexpr double inertia = width * thickness * thickness * thickness / 12.0;  // mm^4

// First bending frequency of the clamped-free strip (rad/s), Euler-Bernoulli:
// omega1 = 1.8751^2 sqrt(E I / (rho A L^4)).
double first_bending_frequency() {
  return 1.8751 * 1.8751 *
         std::sqrt(young * inertia / (density * width * thickness * std::pow(length, 4)));
}

// Writes a case around tests/data/strip.geo (clamped at x = 0, loaded at x = L) and builds it.
sf::Model build_strip_case(const std::string& name, const std::string& load_and_control) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "case.toml") << R"(
[blank]
mesh = ")" + (fs::path(SF_TEST_DATA_DIR) / "strip.geo").string() +
                                             R"("
thickness = 2.0
integration_points = 5
material = "steel"
[materials.steel]
type = "elastic"
density = 7.85e-9
young = 210000.0
poisson = 0.0
[[boundary]]
group = "clamp"
type = "fixed"
)" + load_and_control;
  return sf::build_model(sf::read_case(folder / "case.toml"));
}

TEST(Cantilever, SuddenlyAppliedTipForcePeaksAt1966TimesStatic) {
  const double force = 1.0;  // N in total, small: a linear response
  // First period of the clamped-free beam, T1 = 2 pi / (1.8751^2 sqrt(E I / (rho A L^4))).
  const double omega1 = first_bending_frequency();
  const double period = 2.0 * std::numbers::pi / omega1;
  sf::Model model = build_strip_case("cantilever_step", R"(
[[load]]
group = "tip"
type = "force"
value = [0.0, 0.0, -0.5]
[control]
end_time = )" + std::to_string(0.8 * period) + "\n");
  ASSERT_EQ(model.blank.group("tip").nodes.size(), 2u);

  sf::SolutionState s = sf::make_initial_state(model);
  sf::compute_forces(model, s, 0.0);
  double peak = 0.0, peak_time = 0.0, dt_previous = 0.0;
  const int tip_node = model.blank.group("tip").nodes.front();
  while (s.time < model.end_time) {
    const double dt = sf::compute_time_step(model, s);
    sf::advance_one_step(model, s, dt, dt_previous);
    dt_previous = dt;
    const double deflection = -(s.x(2, tip_node) - model.blank.mesh.nodes(2, tip_node));
    if (deflection > peak) {
      peak = deflection;
      peak_time = s.time;
    }
  }
  const double static_deflection = force * std::pow(length, 3) / (3.0 * young * inertia);
  // Tolerance 2 %: 20 one-point elements in bending and the lumped, scaled rotary inertia.
  EXPECT_NEAR(peak / static_deflection, 1.966, 0.02 * 1.966);
  // The peak comes at 0.535 of the first period (tolerance 3 % of the period).
  EXPECT_NEAR(peak_time / period, 0.535, 0.03);
  // Undamped elastic run: energy conserved to 1e-3 of the work done.
  EXPECT_LT(std::abs(s.energies.balance_error()), 1e-3);
  RecordProperty("peak_ratio", std::to_string(peak / static_deflection));
  std::printf("peak / static = %.4f (1.966), at t / T1 = %.4f (0.535), energy error %.2e\n",
              peak / static_deflection, peak_time / period, s.energies.balance_error());
}

// An end moment in the small-rotation range (theta = 0.02 pi = 3.6 deg): moment loads, load
// curves and damping against the exact elastica. NOTE: the roll-up to a half circle that the
// shell issue asks for does not pass yet: beyond about 20 deg of rotation the strip under a
// fixed-axis end moment deviates and an element inverts (open defect, reported on issue 3).
TEST(Cantilever, EndMomentSmallRotationMatchesTheElastica) {
  const double theta = 0.02 * std::numbers::pi;            // rad, M L / (E I)
  const double moment = theta * young * inertia / length;  // N mm, in total
  const double omega1 = first_bending_frequency();
  const double period = 2.0 * std::numbers::pi / omega1;
  // Ramped over 10 first periods and held, with damping near critical for the first mode so the
  // run settles to the static elastica (dynamic relaxation).
  sf::Model model = build_strip_case("cantilever_end_moment", R"(
[[load]]
group = "tip"
type = "moment"
value = [0.0, )" + std::to_string(-0.5 * moment) + R"(, 0.0]
curve = [[0.0, 0.0], [)" + std::to_string(10.0 * period) + R"(, 1.0]]
[control]
damping = )" + std::to_string(2.0 * omega1) + R"(
end_time = )" + std::to_string(16.0 * period) + "\n");
  sf::SolutionState s = sf::make_initial_state(model);
  sf::compute_forces(model, s, 0.0);
  double dt_previous = 0.0;
  while (s.time < model.end_time) {
    const double dt = sf::compute_time_step(model, s);
    sf::advance_one_step(model, s, dt, dt_previous);
    dt_previous = dt;
  }
  // Exact elastica: a circular arc of radius R = E I / M = L / theta.
  const double radius = length / theta;
  const double x_exact = radius * std::sin(theta), z_exact = radius * (1.0 - std::cos(theta));
  for (int node : model.blank.group("tip").nodes) {
    std::printf("tip node %d: x = %.5f mm (%.5f), z = %.5f mm (%.5f)\n", node, s.x(0, node),
                x_exact, s.x(2, node), z_exact);
    // Tolerances: 1e-3 of L on x, 1 % of the deflection on z (20 elements, residual motion).
    EXPECT_NEAR(s.x(0, node), x_exact, 1e-3 * length);
    EXPECT_NEAR(s.x(2, node), z_exact, 0.01 * z_exact);
  }
}

}  // namespace
