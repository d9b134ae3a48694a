// Tool auto-positioning (issue 32, item 7): a tool with position = "touch" is moved along its
// motion's direction until its surface is half the blank's thickness from the blank's
// mid-surface. verify_bounce: a 10 x 10 x 1 mm plate at z = 0 over a floor at z = -0.6 (0.1 mm
// below the plate's bottom face). Moved up along +z, the floor ends at z = -0.5 exactly (to the
// rounding of -0.6 + 0.1), having moved 0.1 mm; moved down it never meets the plate.
#include <gtest/gtest.h>

#include <filesystem>
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

}  // namespace
}  // namespace sf
