// Tool auto-positioning (issue 32, item 7): a tool with position = "touch" is moved along its
// motion's direction until its surface is half the blank's thickness from the blank's
// mid-surface. verify_bounce: a 10 x 10 x 1 mm plate at z = 0 over a floor at z = -0.6 (0.1 mm
// below the plate's bottom face). Moved up along +z, the floor ends at z = -0.5 exactly (to the
// rounding of -0.6 + 0.1), having moved 0.1 mm; moved down it never meets the plate.
// A tailor-welded strip (tests/data/twb_strip.geo: 1.2 mm for x < 40, 0.8 mm beyond) under a flat
// tool at z = 5 moving down: the tool stops on the thick part's top face (z = 0.6) when it spans
// both parts, on the thin part's (z = 0.4) when it spans only the thin part.
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "casefile/case_config.hpp"
#include "core/errors.hpp"
#include "model/build_model.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

Model bounce_with_floor_moving(const std::string& direction, const std::string& position) {
  const std::vector<std::string> set = {
      "tools[0].position=\"" + position + "\"", "tools[0].motion.type=\"velocity\"",
      "tools[0].motion.direction=" + direction, "tools[0].motion.curve=[[0.0, 0.0], [1.0, 0.0]]"};
  return build_model(
      read_case(fs::path(SF_SOURCE_DIR) / "cases/verify_bounce/case.toml",
                CaseOptions{.set = set, .stroke = {}, .end_time = {}, .search = {}}));
}

TEST(ToolPositioning, TouchMovesTheFloorUpToTheBlanksBottomFace) {
  const Model model = bounce_with_floor_moving("[0.0, 0.0, 1.0]", "touch");
  const Tool& floor = model.tools[0];
  EXPECT_NEAR(floor.touch_shift, 0.1, 1e-12);
  for (Eigen::Index i = 0; i < floor.surface.nodes().cols(); ++i) {
    EXPECT_NEAR(floor.surface.nodes()(2, i), -0.5, 1e-12);
    EXPECT_EQ(floor.mesh.nodes.col(i), floor.surface.nodes().col(i));  // output: where it is
  }
}

TEST(ToolPositioning, AsMeshedLeavesTheFloorWhereItsMeshPutsIt) {
  const Model model = bounce_with_floor_moving("[0.0, 0.0, 1.0]", "as_meshed");
  EXPECT_EQ(model.tools[0].touch_shift, 0.0);
  EXPECT_EQ(model.tools[0].surface.nodes()(2, 0), -0.6);
}

TEST(ToolPositioning, ATouchThatNeverHappensIsAnErrorNamingTheKey) {
  try {
    bounce_with_floor_moving("[0.0, 0.0, -1.0]", "touch");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tools[0].position = \"touch\": tool 'floor' moving "
                                         "along (0, 0, -1) never meets the blank"),
              std::string::npos)
        << e.what();
  }
}

TEST(ToolPositioning, AFixedToolCannotTouch) {
  try {
    build_model(read_case(
        fs::path(SF_SOURCE_DIR) / "cases/verify_bounce/case.toml",
        CaseOptions{
            .set = {"tools[0].position=\"touch\""}, .stroke = {}, .end_time = {}, .search = {}}));
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tools[0].position"), std::string::npos) << e.what();
  }
}

// The strip of two parts under a flat tool at z = 5 mm over x in [x0, x1], moving down, "touch".
Model tailor_welded_strip_under_a_tool(const std::string& name, double x0, double x1) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / "tool_positioning" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "plate.geo") << fmt::format(
      "Point(1) = {{{0}, -1, 5}}; Point(2) = {{{1}, -1, 5}}; Point(3) = {{{1}, 11, 5}};\n"
      "Point(4) = {{{0}, 11, 5}};\nLine(1) = {{1, 2}}; Line(2) = {{2, 3}}; Line(3) = {{3, 4}};\n"
      "Line(4) = {{4, 1}};\nCurve Loop(1) = {{1, 2, 3, 4}};\nPlane Surface(1) = {{1}};\n"
      "Physical Surface(\"plate\") = {{1}};\n",
      x0, x1);
  std::ofstream(folder / "case.toml")
      << fmt::format(R"([blank]
mesh = "{}"
[[blank.parts]]
name = "thick"
group = "inner"
thickness = 1.2
material = "steel"
[[blank.parts]]
name = "thin"
group = "outer"
thickness = 0.8
material = "steel"
[materials.steel]
type = "elastic"
density = 7.85e-9
young = 210000.0
poisson = 0.3
[[tools]]
name = "plate"
mesh = "plate.geo"
element_size = 4.0
position = "touch"
[tools.motion]
type = "velocity"
direction = [0.0, 0.0, -1.0]
curve = [[0.0, 0.0], [1.0, 0.0]]
[control]
end_time = 1e-4
)",
                     (fs::path(SF_TEST_DATA_DIR) / "twb_strip.geo").string());
  return build_model(read_case(folder / "case.toml"));
}

TEST(ToolPositioning, TouchOnABlankOfTwoThicknessesStopsAtEachPartsOwnFace) {
  const Model both = tailor_welded_strip_under_a_tool("twb_both", -5.0, 105.0);
  EXPECT_NEAR(both.tools[0].touch_shift, 4.4, 1e-12);
  EXPECT_NEAR(both.tools[0].surface.nodes().row(2).maxCoeff(), 0.6, 1e-12);
  const Model thin = tailor_welded_strip_under_a_tool("twb_thin", 50.0, 105.0);
  EXPECT_NEAR(thin.tools[0].touch_shift, 4.6, 1e-12);
  EXPECT_NEAR(thin.tools[0].surface.nodes().row(2).minCoeff(), 0.4, 1e-12);
}

}  // namespace
}  // namespace sf
