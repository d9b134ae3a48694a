// Case-file keys of a force-controlled tool ([tools.motion] type = "force": direction, curve in N,
// mass, damping): values and defaults, errors that name the file, the key and the tool, the
// stroke tool rules, and the resolved-case round trip.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "casefile/case_config.hpp"
#include "core/errors.hpp"

namespace fs = std::filesystem;

namespace {

// A case with a holder whose [tools.motion] table is `holder` and a punch after it (`punch`: its
// [tools.motion] table); `control` is the [control] table's body.
fs::path write_case(const std::string& name, const std::string& holder,
                    const std::string& control = "stroke = 10.0\n",
                    const std::string& punch =
                        "type = \"velocity\"\n"
                        "curve = [[0.0, 0.0], [0.0005, 3000.0]]\n") {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / "read_case_force_tool" / name;
  fs::create_directories(folder);
  for (const char* mesh : {"blank.msh", "holder.msh", "punch.msh"}) {
    std::ofstream(folder / mesh) << "";
  }
  std::ofstream(folder / "case.toml") << R"([blank]
mesh = "blank.msh"
thickness = 0.81
material = "alu"
[materials.alu]
type = "elastic"
density = 2.7e-9
young = 71000.0
poisson = 0.33
[[tools]]
name = "holder"
mesh = "holder.msh"
[tools.motion]
)" + holder + R"(
[[tools]]
name = "punch"
mesh = "punch.msh"
[tools.motion]
)" + punch + R"(
[control]
)" + control;
  return folder / "case.toml";
}

std::string error_of(const fs::path& file) {
  try {
    sf::read_case(file);
  } catch (const sf::InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for " << file;
  return "";
}

void expect_error(const fs::path& file, std::initializer_list<std::string> parts) {
  const std::string message = error_of(file);
  EXPECT_NE(message.find(file.string()), std::string::npos) << message;
  for (const std::string& part : parts) {
    EXPECT_NE(message.find(part), std::string::npos)
        << "message: " << message << "\nlacks: " << part;
  }
}

const char* full_holder = R"(type = "force"
direction = [0.0, 0.0, -2.0]
curve = [[0.0, 0.0], [0.0002, 4900.0]]
mass = 2.5e-5
damping = 1.0e4
)";

TEST(ReadCaseForceTool, ReadsEveryValue) {
  const sf::CaseConfig c = sf::read_case(write_case("full", full_holder));
  const sf::MotionConfig& m = c.tools[0].motion;
  EXPECT_EQ(m.type, sf::MotionConfig::Type::force);
  EXPECT_EQ(m.direction, (std::array<double, 3>{0.0, 0.0, -1.0}));  // normalised
  EXPECT_EQ(m.curve.times, (std::vector<double>{0.0, 0.0002}));
  EXPECT_EQ(m.curve.values, (std::vector<double>{0.0, 4900.0}));
  ASSERT_TRUE(m.mass.has_value());
  EXPECT_EQ(*m.mass, 2.5e-5);
  EXPECT_EQ(m.damping, 1.0e4);
  // The stroke tool defaults to the first tool with a prescribed motion, not the holder.
  EXPECT_EQ(c.control.stroke_tool, "punch");
}

TEST(ReadCaseForceTool, DefaultsAndANegativeForce) {
  // Only the type and the curve: direction -z, the mass left to build_model (the blank's mass),
  // no damping. A negative force (the holder pulled back, e.g. lifting) is accepted.
  const sf::CaseConfig c =
      sf::read_case(write_case("defaults", "type = \"force\"\ncurve = [[0.0, -100.0]]\n"));
  const sf::MotionConfig& m = c.tools[0].motion;
  EXPECT_EQ(m.direction, (std::array<double, 3>{0.0, 0.0, -1.0}));
  EXPECT_FALSE(m.mass.has_value());
  EXPECT_EQ(m.damping, 0.0);
  EXPECT_EQ(m.curve.values, (std::vector<double>{-100.0}));
}

TEST(ReadCaseForceTool, ResolvedCaseRoundTrips) {
  for (const std::string& holder :
       {std::string(full_holder), std::string("type = \"force\"\ncurve = [[0.0, 4900.0]]\n")}) {
    const sf::CaseConfig a = sf::read_case(write_case("round_trip", holder));
    const std::string resolved = sf::format_resolved_case(a);
    SCOPED_TRACE(resolved);
    const fs::path again = write_case("round_trip_again", holder);
    std::ofstream(again) << resolved;
    const sf::CaseConfig b = sf::read_case(again);
    const sf::MotionConfig &x = a.tools[0].motion, &y = b.tools[0].motion;
    EXPECT_EQ(y.type, x.type);
    EXPECT_EQ(y.direction, x.direction);
    EXPECT_EQ(y.curve.times, x.curve.times);
    EXPECT_EQ(y.curve.values, x.curve.values);
    EXPECT_EQ(y.mass, x.mass);
    EXPECT_EQ(y.damping, x.damping);
    EXPECT_EQ(b.control.stroke_tool, a.control.stroke_tool);
  }
}

TEST(ReadCaseForceTool, BadValuesNameTheKey) {
  expect_error(write_case("zero_mass", "type = \"force\"\ncurve = [[0.0, 1.0]]\nmass = 0.0\n"),
               {"tools[0].motion.mass", "expected a number > 0 (tonne)"});
  expect_error(write_case("negative_mass", "type = \"force\"\ncurve = [[0.0, 1.0]]\nmass = -1\n"),
               {"tools[0].motion.mass", "> 0 (tonne)", "-1"});
  expect_error(
      write_case("negative_damping", "type = \"force\"\ncurve = [[0.0, 1.0]]\ndamping = -5.0\n"),
      {"tools[0].motion.damping", ">= 0 (1/s)"});
  expect_error(write_case("no_curve", "type = \"force\"\nmass = 1e-5\n"),
               {"tools[0].motion.curve", "missing"});
  expect_error(
      write_case("mass_on_velocity", "type = \"velocity\"\ncurve = [[0.0, 1.0]]\nmass = 1e-5\n"),
      {"tools[0].motion.mass", "not allowed", "type = \"force\""});
  expect_error(write_case("damping_on_fixed", "type = \"fixed\"\ndamping = 1.0\n"),
               {"tools[0].motion.damping", "not allowed"});
  expect_error(write_case("unknown_type", "type = \"pressure\"\ncurve = [[0.0, 1.0]]\n"),
               {"tools[0].motion.type", "\"force\""});
}

TEST(ReadCaseForceTool, AForceControlledToolCannotDefineTheStroke) {
  expect_error(
      write_case("stroke_tool", full_holder, "stroke = 10.0\nstroke_tool = \"holder\"\n"),
      {"control.stroke_tool", "\"holder\"", "force-controlled", "cannot define the stroke"});
  // Refused with end_time too (stroke_tool names the tool whose travel is the stroke).
  expect_error(write_case("stroke_tool_end_time", full_holder,
                          "end_time = 0.001\nstroke_tool = \"holder\"\n"),
               {"control.stroke_tool", "force-controlled"});
  // A stroke needs a tool with a prescribed motion: a force-controlled one does not count.
  expect_error(
      write_case("stroke_without_prescribed", full_holder, "stroke = 10.0\n", "type = \"fixed\"\n"),
      {"control.stroke", "prescribed motion"});
}

}  // namespace
