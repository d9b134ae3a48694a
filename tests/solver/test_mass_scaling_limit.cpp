// The cap on mass scaling (control.mass_scaling_max_added, docs/case-file.md): a target step that
// needs more added mass than the cap at the start is an input error naming the file and both keys;
// a run that crushes elements until the added mass passes the cap stops as unstable, naming the
// key, the time and the cycle.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "casefile/case_config.hpp"
#include "core/errors.hpp"
#include "model/build_model.hpp"
#include "solver/explicit_driver.hpp"

namespace fs = std::filesystem;

namespace {

// The 100 x 10 mm strip of tests/data/strip.geo (20 x 1 elements of 5 x 10 mm), clamped at x = 0,
// elastic steel, every node thrown toward the clamp at 50 m/s: the compression shortens the
// elements near the clamp (strain about v / c = 1 %), so their step falls.
sf::CaseConfig strip_thrown_at_the_clamp(const std::string& name) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "case.toml") << R"([blank]
mesh = ")" + (fs::path(SF_TEST_DATA_DIR) / "strip.geo").string() +
                                             R"("
thickness = 2.0
material = "steel"
[materials.steel]
type = "elastic"
density = 7.85e-9
young = 210000.0
poisson = 0.3
[[boundary]]
group = "clamp"
type = "fixed"
[[initial_velocity]]
group = "blank"
velocity = [-50000.0, 0.0, 0.0]
[control]
end_time = 2.0e-5
)";
  return sf::read_case(folder / "case.toml");
}

TEST(MassScalingLimit, TargetNeedingMoreThanTheCapAtTheStartIsAnInputError) {
  sf::CaseConfig config = strip_thrown_at_the_clamp("mass_scaling_limit_start");
  const double dt0 = sf::build_model(config).time.time_step;
  // 1.5 x the step needs 1.5^2 - 1 = 125 % more mass in every element; the cap is 1 %.
  config.control.mass_scaling_dt = 1.5 * dt0;
  config.control.mass_scaling_max_added = 0.01;
  try {
    sf::build_model(config);
    FAIL() << "a target step beyond the mass cap must be refused";
  } catch (const sf::InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(config.file.string()), std::string::npos) << message;
    EXPECT_NE(message.find("control.mass_scaling_dt"), std::string::npos) << message;
    EXPECT_NE(message.find("control.mass_scaling_max_added"), std::string::npos) << message;
    EXPECT_NE(message.find("125.00 %"), std::string::npos) << message;
  }
}

TEST(MassScalingLimit, CrushingPastTheCapStopsTheRunNamingTheKeyTimeAndCycle) {
  sf::CaseConfig config = strip_thrown_at_the_clamp("mass_scaling_limit_run");
  const double dt0 = sf::build_model(config).time.time_step;
  config.control.mass_scaling_dt = dt0;  // nothing is below the target at the start
  config.control.mass_scaling_max_added = 1e-4;
  sf::Model model = sf::build_model(config);
  ASSERT_EQ(model.blank.scaling.added_mass, 0.0);
  sf::SolutionState s = sf::make_initial_state(model);
  sf::compute_forces(model, s, 0.0);
  std::string message;
  double dt_previous = 0.0;
  try {
    while (s.time < model.time.end_time) {
      const double dt = sf::compute_time_step(model, s);
      sf::advance_one_step(model, s, dt, dt_previous);
      dt_previous = dt;
    }
  } catch (const sf::InstabilityError& e) {
    message = e.what();
  }
  ASSERT_FALSE(message.empty()) << "crushing elements past the cap must stop the run";
  EXPECT_NE(message.find("control.mass_scaling_max_added"), std::string::npos) << message;
  EXPECT_NE(message.find("at t = "), std::string::npos) << message;
  EXPECT_NE(message.find("cycle "), std::string::npos) << message;
  // It stopped as soon as the cap was passed: the added mass is above it, but not far.
  const double added = s.scaling.added_mass / model.blank.physical_mass;
  EXPECT_GT(added, 1e-4);
  EXPECT_LT(added, 1e-2);
  std::printf("%s\n(added %.4f %% at the stop)\n", message.c_str(), 100.0 * added);
}

}  // namespace
