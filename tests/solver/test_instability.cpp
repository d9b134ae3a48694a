// A run that goes unstable stops with a message naming the node or element, the time and the
// cycle (the driver's checks, exercised on the demo model).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <variant>

#include "casefile/case_config.hpp"
#include "core/errors.hpp"
#include "model/build_model.hpp"
#include "solver/explicit_driver.hpp"

namespace fs = std::filesystem;

namespace {

class Instability : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    sf::CaseConfig config =
        sf::read_case(fs::path(SF_SOURCE_DIR) / "cases/square_cup_aluminium/case.toml");
    config.control.stroke = 1.0;
    model_ = new sf::Model(sf::build_model(config));
  }
  static void TearDownTestSuite() { delete model_; }
  static sf::Model* model_;
};
sf::Model* Instability::model_ = nullptr;

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const sf::InstabilityError& e) {
    return e.what();
  }
  return "";
}

TEST_F(Instability, NonFiniteForceNamesTheNodeTimeAndCycle) {
  sf::SolutionState s = sf::make_initial_state(*model_);
  sf::compute_forces(*model_, s, 0.0);
  s.f_int(2, 17) = std::nan("");
  const std::string message =
      message_of([&] { sf::advance_one_step(*model_, s, model_->time.time_step, 0.0); });
  ASSERT_FALSE(message.empty()) << "a NaN force must stop the run";
  EXPECT_NE(message.find("blank node 17"), std::string::npos) << message;
  EXPECT_NE(message.find("cycle 0"), std::string::npos) << message;
}

TEST_F(Instability, InvertedElementNamesTheElementTimeAndCycle) {
  sf::SolutionState s = sf::make_initial_state(*model_);
  // Fold the elements around one node over: move it beyond the opposite corner of element 40.
  const auto quad = model_->blank.part.quads.col(40);
  const int moved = quad[0];
  s.x.col(moved) = s.x.col(quad[2]) + 1.5 * (s.x.col(quad[2]) - s.x.col(moved));
  s.cycle = 12;
  const std::string message =
      message_of([&] { sf::compute_forces(*model_, s, model_->time.time_step); });
  ASSERT_FALSE(message.empty()) << "an inverted element must stop the run";
  EXPECT_NE(message.find("cycle 12"), std::string::npos) << message;
  // The element named is one of those folded: it holds the moved node.
  int named = -1;
  ASSERT_EQ(std::sscanf(message.c_str(), "shell element %d", &named), 1) << message;
  const auto named_quad = model_->blank.part.quads.col(named);
  EXPECT_TRUE((named_quad.array() == moved).any()) << message;
}

// A step that does not move the time on stops the run instead of cycling at t = 0 for ever
// (issue 31: young = 1e300 made the wave speed overflow, so the critical step and the initial step
// were both 0, and the collapse check, dt < 1e-3 x the initial step, never fired). build_model
// refuses such a material now; here the model is changed after it was built.
TEST(TimeLoopGuard, AStepOfZeroStopsTheRun) {
  sf::CaseConfig config =
      sf::read_case(fs::path(SF_SOURCE_DIR) / "cases/square_cup_aluminium/case.toml");
  config.control.stroke = 1.0;
  sf::Model model = sf::build_model(config);
  std::visit([](auto& law) { law.E = 1e300; }, model.blank.part.materials[0].law);
  model.time.time_step = 0.0;
  sf::RunOptions options;
  options.write_results = false;
  const std::string message = message_of([&] { sf::run_explicit(model, options); });
  EXPECT_NE(message.find("the time step 0.000e+00 s does not advance the time t = 0.000000e+00 s "
                         "at cycle 0"),
            std::string::npos)
      << message;
}

}  // namespace
