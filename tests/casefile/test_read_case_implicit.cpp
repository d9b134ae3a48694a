// Case-file keys of implicit statics: [analysis], [implicit] and [springback] (with its
// [springback.u_channel] measures): values, defaults, errors that name the key, the rules that
// tie them to the rest of the case, and the resolved-case round trip.
#include <gtest/gtest.h>

#include "casefile/case_config.hpp"
#include "casefile/read_case_fixture.hpp"

namespace {

using sf_test::kMinimal;

// The minimal case with one tool (a fixed die) and the given extra tables appended.
std::string with_tool(std::string_view extra) {
  return std::string(kMinimal) + "\n[[tools]]\nname = \"die\"\nmesh = \"die.msh\"\n" +
         std::string(extra);
}

class ReadCaseImplicit : public sf_test::ReadCase {};

TEST_F(ReadCaseImplicit, DefaultsWhenAbsent) {
  const sf::CaseConfig c = sf::read_case(write_case(kMinimal));
  EXPECT_EQ(c.analysis.type, sf::AnalysisConfig::Type::explicit_dynamic);
  EXPECT_FALSE(c.springback.has_value());
  EXPECT_EQ(c.implicit.increments, 1);
  EXPECT_EQ(c.implicit.max_iterations, 25);
  EXPECT_EQ(c.implicit.max_cuts, 8);
  EXPECT_DOUBLE_EQ(c.implicit.force_tolerance, 1e-6);
  EXPECT_DOUBLE_EQ(c.implicit.displacement_tolerance, 1e-6);
  EXPECT_TRUE(c.implicit.line_search);
  EXPECT_EQ(c.implicit.linear_solver, sf::ImplicitConfig::LinearSolver::automatic);
  EXPECT_EQ(c.implicit.rigid_body_modes, sf::ImplicitConfig::RigidBodyModes::automatic);
}

TEST_F(ReadCaseImplicit, ReadsStaticAnalysisAndNewtonControls) {
  const std::string text = std::string(kMinimal) + R"(
[analysis]
type = "static"
geometry = "linear"
[implicit]
increments = 4
max_iterations = 12
max_cuts = 3
force_tolerance = 1e-8
displacement_tolerance = 1e-7
line_search = false
linear_solver = "umfpack"
rigid_body_modes = "error"
)";
  const sf::CaseConfig c = sf::read_case(write_case(text));
  EXPECT_EQ(c.analysis.type, sf::AnalysisConfig::Type::static_equilibrium);
  EXPECT_TRUE(c.analysis.linear);
  EXPECT_EQ(c.implicit.increments, 4);
  EXPECT_EQ(c.implicit.max_iterations, 12);
  EXPECT_EQ(c.implicit.max_cuts, 3);
  EXPECT_DOUBLE_EQ(c.implicit.force_tolerance, 1e-8);
  EXPECT_DOUBLE_EQ(c.implicit.displacement_tolerance, 1e-7);
  EXPECT_FALSE(c.implicit.line_search);
  EXPECT_EQ(c.implicit.linear_solver, sf::ImplicitConfig::LinearSolver::umfpack);
  EXPECT_EQ(c.implicit.rigid_body_modes, sf::ImplicitConfig::RigidBodyModes::error);
  // The resolved case reads back to the same values.
  const sf::CaseConfig again = sf::read_case(write_case(sf::format_resolved_case(c), "again.toml"));
  EXPECT_EQ(again.analysis.type, c.analysis.type);
  EXPECT_TRUE(again.analysis.linear);
  EXPECT_EQ(again.implicit.increments, 4);
  EXPECT_EQ(again.implicit.linear_solver, c.implicit.linear_solver);
  EXPECT_EQ(again.implicit.rigid_body_modes, c.implicit.rigid_body_modes);
  EXPECT_FALSE(again.implicit.line_search);
}

TEST_F(ReadCaseImplicit, ReadsSpringbackBothMethodsWithUChannelMeasures) {
  const sf::CaseConfig implicit = sf::read_case(write_case(with_tool(R"(
[springback]
[springback.u_channel]
section = "sym_y"
bottom = [0.0, 25.0]
wall = [-60.0, -10.0]
flange = [45.0, 180.0]
)")));
  ASSERT_TRUE(implicit.springback.has_value());
  EXPECT_EQ(implicit.springback->method, sf::SpringbackConfig::Method::implicit);
  ASSERT_TRUE(implicit.springback->u_channel.has_value());
  EXPECT_EQ(implicit.springback->u_channel->section, "sym_y");
  EXPECT_DOUBLE_EQ(implicit.springback->u_channel->wall[0], -60.0);
  EXPECT_DOUBLE_EQ(implicit.springback->u_channel->flange[1], 180.0);
  EXPECT_DOUBLE_EQ(implicit.springback->stabilization, 1e-6);  // the default
  const sf::CaseConfig stiffer =
      sf::read_case(write_case(with_tool("[springback]\nstabilization = 1e-5\n"), "stiffer.toml"));
  EXPECT_DOUBLE_EQ(stiffer.springback->stabilization, 1e-5);
  const sf::CaseConfig stiffer_again =
      sf::read_case(write_case(sf::format_resolved_case(stiffer), "stiffer_again.toml"));
  EXPECT_DOUBLE_EQ(stiffer_again.springback->stabilization, 1e-5);

  const sf::CaseConfig dr = sf::read_case(write_case(with_tool(R"(
[springback]
method = "dynamic_relaxation"
release_time = 0.01
kinetic_tolerance = 1e-5
)")));
  ASSERT_TRUE(dr.springback.has_value());
  EXPECT_EQ(dr.springback->method, sf::SpringbackConfig::Method::dynamic_relaxation);
  EXPECT_DOUBLE_EQ(dr.springback->release_time, 0.01);
  EXPECT_DOUBLE_EQ(dr.springback->max_time, 0.1);  // default: 10 x release_time
  EXPECT_DOUBLE_EQ(dr.springback->kinetic_tolerance, 1e-5);
  const sf::CaseConfig again =
      sf::read_case(write_case(sf::format_resolved_case(dr), "again.toml"));
  ASSERT_TRUE(again.springback.has_value());
  EXPECT_EQ(again.springback->method, dr.springback->method);
  EXPECT_DOUBLE_EQ(again.springback->max_time, 0.1);
}

TEST_F(ReadCaseImplicit, ErrorsNameTheKeyAndTheRule) {
  const std::string base = std::string(kMinimal);
  expect_error(base + "[analysis]\ntype = \"implicit\"\n", 0,
               {"analysis.type", "\"explicit\"", "\"static\""});
  expect_error(base + "[analysis]\ngeometry = \"linear\"\n", 0, {"analysis.geometry", "static"});
  expect_error(base + "[implicit]\nincrements = 0\n", 0, {"implicit.increments"});
  expect_error(base + "[implicit]\nforce_tolerance = -1e-6\n", 0, {"implicit.force_tolerance"});
  expect_error(base + "[implicit]\nlinear_solver = \"pardiso\"\n", 0,
               {"implicit.linear_solver", "\"cholmod\"", "\"umfpack\""});
  expect_error(base + "[implicit]\nnewton = 3\n", 0, {"newton"});
  // A static analysis: no tools, end_time rather than stroke, no springback.
  expect_error(with_tool("[analysis]\ntype = \"static\"\n"), 0,
               {"analysis.type", "no tools", "1 [[tools]]"});
  // Springback needs tools, and its dynamic-relaxation keys their method.
  expect_error(base + "[springback]\n", 0, {"springback", "no [[tools]]"});
  expect_error(with_tool("[springback]\nrelease_time = 0.01\n"), 0,
               {"springback.release_time", "dynamic_relaxation"});
  expect_error(with_tool("[springback]\nstabilization = -1e-6\n"), 0, {"springback.stabilization"});
  expect_error(with_tool("[springback]\nmethod = \"dynamic_relaxation\"\nrelease_time = 0.01\n"
                         "stabilization = 1e-6\n"),
               0, {"springback.stabilization", "implicit"});
  expect_error(with_tool("[springback]\nmethod = \"dynamic_relaxation\"\n"), 0,
               {"springback.release_time", "missing"});
  expect_error(with_tool("[springback]\n[springback.u_channel]\nsection = \"s\"\nbottom = [0, "
                         "25]\nwall = [-10, -60]\nflange = [45, 180]\n"),
               0, {"springback.u_channel.wall", "lo < hi"});
  expect_error(with_tool("[springback]\n[springback.u_channel]\nsection = \"s\"\nbottom = [0, "
                         "25]\nwall = [-60, -10]\n"),
               0, {"springback.u_channel.flange", "missing"});
}

}  // namespace
