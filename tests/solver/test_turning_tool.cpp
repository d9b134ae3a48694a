// A turning tool at run level: a flat plate, hinged about the y axis through its own surface at
// x = a, turns down by a small angle theta onto the free end of a clamped elastic strip
// (tests/data/strip.geo: L = 100 mm, b = 10 mm, t = 2 mm, nu = 0, clamped at x = 0).
//
// With a >= L / 3 the plate touches only the strip's tip: the plate's slope theta is then at
// least the tip slope of the cantilever it bends, 3 w / (2 L) with w = (L - a) theta, so the
// straight plate stays above the strip elsewhere. Statically (Euler-Bernoulli, small rotation):
//   tip deflection w = (L - a) tan(theta),  tip force P = 3 E I w / L^3,
//   torque about the hinge T = P (L - a) = 3 E I (L - a)^2 tan(theta) / L^3,
// and the work the press did, the strain energy P w / 2 = T theta / 2, up to what the damping
// took. The checks:
// - the press torque (history column flanger_torque) and the force on the plate against the
//   closed forms within 2 %: the element's tip deflection under an end load on 20 quads is
//   within 1 % (test_cantilever.cpp's small-rotation checks), theta^2 terms are 1e-4, the
//   penalty spring's give is 1e-4 of w, and the damping leaves a residual motion below 0.5 %;
// - the strip's tip at the plate: its deflection (L - a) tan(theta) less half the thickness's
//   offset along the turned normal, within 1 %;
// - the strain energy within 4 % of T theta / 2 (P and w within 2 % each), and the energy
//   balance closed to 1e-3 of the external work: the tool's work is the torque's (the moment of
//   the contact forces turned through the step's rotation), not a translation's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "case_fixture.hpp"
#include "core/errors.hpp"
#include "solver/tool_update.hpp"

namespace {

namespace fs = std::filesystem;

constexpr double kLength = 100.0;                                                  // mm
constexpr double kWidth = 10.0;                                                    // mm
constexpr double kThickness = 2.0;                                                 // mm
constexpr double kYoung = 210000.0;                                                // MPa
constexpr double kInertia = kWidth * kThickness * kThickness * kThickness / 12.0;  // mm^4
constexpr double kHinge = 50.0;                                                    // mm, a
constexpr double kDegrees = 1.0;                                                   // theta

// The plate: x in [a, L + 20], y in [-5, 15], on the strip's top surface (z = t / 2).
const char* plate_geo = R"(
Point(1) = {50, -5, 1}; Point(2) = {120, -5, 1}; Point(3) = {120, 15, 1}; Point(4) = {50, 15, 1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Mesh.MeshSizeMax = 5.0;
Physical Surface("flanger") = {1};
)";

// Writes test_output/NAME/{flanger.geo, case.toml}: the clamped elastic strip (nu = 0), then
// `tools_and_control` (the [[tools]] entry named "flanger" and what follows).
fs::path write_strip_case(const std::string& name, const std::string& tools_and_control) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "flanger.geo") << plate_geo;
  std::ofstream(folder / "case.toml") << R"([blank]
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
[[tools]]
name = "flanger"
mesh = "flanger.geo"
)" + tools_and_control;
  return folder / "case.toml";
}

sf::Model build_turning_case(const std::string& name, const std::string& control) {
  return sf::build_model(sf::read_case(write_strip_case(name, R"([tools.motion]
type = "fixed"
angle = [[0.0, 0.0], [0.03, 1.0]]
axis = [0.0, 1.0, 0.0]
pivot = [50.0, 0.0, 1.0]
[[contact]]
tool = "flanger"
[control]
)" + control)));
}

// The message of the InputError reading the case throws ("(accepted)" if it reads).
std::string refusal_of(const fs::path& case_file) {
  try {
    sf::read_case(case_file);
  } catch (const sf::InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(TurningTool, APlateTurnedOntoACantileverTipCarriesTheBeamsTorque) {
  // First period of the strip 2 pi / (1.8751^2 sqrt(E I / (rho A L^4))) = 6.0 ms: the turn takes
  // 5 periods and is held 3 more, under damping of a quarter of the critical at that frequency.
  sf::Model model =
      build_turning_case("turning_tool_cantilever", "end_time = 0.048\ndamping = 500.0\n");
  ASSERT_TRUE(model.tools[0].motion.turns());
  sf::SolutionState s = sf::make_initial_state(model);
  sf::compute_forces(model, s, 0.0);
  sf::test::run_to_end(model, s, [](const sf::SolutionState&) {});

  const double theta = kDegrees * std::numbers::pi / 180.0;
  const double tip_deflection = (kLength - kHinge) * std::tan(theta);
  const double tip_force = 3.0 * kYoung * kInertia * tip_deflection / std::pow(kLength, 3);
  const double torque = tip_force * (kLength - kHinge);
  const sf::ToolState& tool = s.tools[0];
  std::printf("torque %.6g N mm (exact %.6g), force %.6g N (exact %.6g)\n",
              sf::press_torque(model, 0, tool), torque, tool.force.norm(), tip_force);
  EXPECT_NEAR(tool.angle, theta, 1e-15);
  EXPECT_NEAR(sf::press_torque(model, 0, tool), torque, 0.02 * torque);
  EXPECT_NEAR(tool.force.norm(), tip_force, 0.02 * tip_force);
  EXPECT_GT(tool.nodes_in_contact, 0);

  // The tip's mid-surface node lies half the thickness below the turned plate: its deflection
  // is the plate's at x = L, (L - a) tan(theta), less nothing to first order (the offset t/2
  // along the turned normal moves it by t/2 (1 - cos(theta)) down and t/2 sin(theta) along x).
  int tip = 0;  // the strip's tip at y = 0
  for (int i = 0; i < model.blank.mesh.nodes.cols(); ++i) {
    if (model.blank.mesh.nodes(0, i) == kLength && model.blank.mesh.nodes(1, i) == 0.0) {
      tip = i;
    }
  }
  ASSERT_EQ(model.blank.mesh.nodes(0, tip), kLength);
  const double deflection = -s.x(2, tip);
  EXPECT_NEAR(deflection, tip_deflection, 0.01 * tip_deflection);

  // The tool's work is what the press did: the balance closes.
  std::printf("tip deflection %.6g mm (exact %.6g)\n", deflection, tip_deflection);
  const sf::Energies& e = s.energies;
  std::printf("internal %.6g N mm (exact %.6g), external %.6g, damping %.6g, balance %.3g\n",
              e.internal, 0.5 * torque * theta, e.external_work, e.damping, e.balance_error());
  const double strain_energy = 0.5 * torque * theta;             // = P w / 2
  EXPECT_NEAR(e.internal, strain_energy, 0.04 * strain_energy);  // P and w within 2 % each
  EXPECT_GT(e.external_work, e.internal);                        // and the damping took some
  EXPECT_LT(std::abs(e.balance_error()), 1e-3);
}

TEST(TurningTool, AForceControlledToolCannotTurn) {
  const std::string message = refusal_of(write_strip_case("turning_tool_forced", R"([tools.motion]
type = "force"
curve = [[0.0, 10.0]]
angle = [[0.0, 0.0], [1.0, 10.0]]
)"));
  EXPECT_NE(message.find("tools[0].motion.angle"), std::string::npos) << message;
  EXPECT_NE(message.find("along its direction only"), std::string::npos) << message;
}

TEST(TurningTool, AxisAndPivotNeedAnAngle) {
  const std::string message = refusal_of(write_strip_case("turning_tool_no_angle", R"([tools.motion]
type = "fixed"
pivot = [1.0, 2.0, 3.0]
)"));
  EXPECT_NE(message.find("tools[0].motion.pivot"), std::string::npos) << message;
  EXPECT_NE(message.find("give its `angle` curve"), std::string::npos) << message;
}

}  // namespace
