// The contact's result fields (issue 33, item 4; docs/results-format.md): a 10 x 10 x 1 mm
// elastic plate pressed onto a flat die by a uniform pressure p = 2 MPa on its top face and slid
// along x at 100 mm/s for 2 ms. At rest in z, every node's normal force balances the load on its
// area, so contact_pressure_die is p at every node (the pressure load and the area the field
// divides by are both the node's tributary share); every node slides 0.2 mm less the few steps
// before it first touches; contact_tool names the die (index 0) everywhere. The punch above,
// never touched, shows zero pressure, zero sliding and no tool.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "case_fixture.hpp"
#include "results/hdf5_file.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

constexpr double kPressure = 2.0;  // MPa
constexpr double kSlid = 0.2;      // mm: 100 mm/s for 2 ms

TEST(ContactResults, PressedPlateShowsThePressureItsSlideAndItsTool) {
  const std::string name = "contact_results";
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "die.geo") << test::flat_tool_geo(-10.0, -10.0, 25.0, 20.0, 0.0, 8.0);
  std::ofstream(folder / "punch.geo") << test::flat_tool_geo(-10.0, -10.0, 25.0, 20.0, 5.0, 8.0);
  const CaseConfig config = test::write_case(name, test::square_plate_geo(10.0, 0.5, 11),
                                             std::string(test::kElasticSteelSheet) + R"(
[[tools]]
name = "die"
mesh = "die.geo"
group = "plate"
[[tools]]
name = "punch"
mesh = "punch.geo"
group = "plate"
[[contact]]
tool = "die"
[[contact]]
tool = "punch"
)" + test::pressed_and_slid(kPressure) + "output_frames = 2\n");
  const Model model = build_model(config);
  RunOptions options;
  options.output_directory = folder / "results";
  options.checkpoints = false;
  fs::remove_all(options.output_directory);
  SolutionState s;
  run_explicit(model, options, &s);
  const h5::File file(options.output_directory / "results.h5", h5::FileMode::read_only);
  const std::string frame = "/parts/blank/frames/000002/";
  const std::vector<double> pressure = file.read_doubles(frame + "contact_pressure_die");
  const std::vector<double> sliding = file.read_doubles(frame + "sliding_distance_die");
  const std::vector<double> tool = file.read_doubles(frame + "contact_tool");
  const std::vector<double> punch = file.read_doubles(frame + "contact_pressure_punch");
  const std::vector<double> punch_sliding = file.read_doubles(frame + "sliding_distance_punch");
  ASSERT_EQ(pressure.size(), 121u);
  double low = 1e9, high = -1e9, slid_low = 1e9, slid_high = -1e9;
  for (std::size_t i = 0; i < pressure.size(); ++i) {
    low = std::min(low, pressure[i]);
    high = std::max(high, pressure[i]);
    slid_low = std::min(slid_low, sliding[i]);
    slid_high = std::max(slid_high, sliding[i]);
    EXPECT_EQ(tool[i], 0.0) << i;
    EXPECT_EQ(punch[i], 0.0) << i;
    EXPECT_EQ(punch_sliding[i], 0.0) << i;
  }
  std::printf(
      "contact_pressure_die %.6f to %.6f MPa (p = %g); sliding_distance_die %.6f to "
      "%.6f mm (%g)\n",
      low, high, kPressure, slid_low, slid_high, kSlid);
  EXPECT_NEAR(low, kPressure, 0.01 * kPressure);
  EXPECT_NEAR(high, kPressure, 0.01 * kPressure);
  EXPECT_NEAR(slid_low, kSlid, 0.01 * kSlid);
  EXPECT_LE(slid_high, kSlid * (1.0 + 1e-9));
}

}  // namespace
}  // namespace sf
