// Case-file keys for loads, initial and prescribed velocities, gravity and damping: values,
// errors that name the key, and the resolved-case round trip.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "casefile/case_config.hpp"
#include "core/errors.hpp"

namespace fs = std::filesystem;

namespace {

fs::path write_case(const std::string& name, const std::string& extra) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / "read_case_loads" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "blank.msh") << "";
  std::ofstream(folder / "case.toml") << R"([blank]
mesh = "blank.msh"
thickness = 1.0
material = "steel"
[materials.steel]
type = "elastic"
density = 7.85e-9
young = 210000.0
poisson = 0.3
)" + extra;
  return folder / "case.toml";
}

std::string error_of(const fs::path& file) {
  try {
    sf::read_case(file);
  } catch (const sf::InputError& e) {
    return e.what();
  }
  return "";
}

const char* full_loads = R"(
[[load]]
group = "tip"
type = "force"
value = [0.0, 0.0, -2.5]
curve = [[0.0, 0.0], [0.001, 1.0]]
[[load]]
group = "blank"
type = "pressure"
pressure = 0.3
[[initial_velocity]]
velocity = [0.0, 0.0, -1000.0]
[[initial_velocity]]
group = "edge"
angular_velocity = [0.0, 50.0, "2 * x + z"]
[[prescribed_velocity]]
group = "edge"
velocity = [10.0, 0.0, 0.0]
components = ["x", "z"]
[control]
end_time = 0.01
gravity = [0.0, 0.0, -9810.0]
damping = 50.0
)";

TEST(ReadCaseLoads, ReadsEveryValue) {
  const sf::CaseConfig c = sf::read_case(write_case("full", full_loads));
  ASSERT_EQ(c.loads.size(), 2u);
  EXPECT_EQ(c.loads[0].type, sf::LoadConfig::Type::force);
  EXPECT_EQ(c.loads[0].value[2], -2.5);
  EXPECT_EQ(c.loads[0].curve.times.size(), 2u);
  EXPECT_EQ(c.loads[1].type, sf::LoadConfig::Type::pressure);
  EXPECT_EQ(c.loads[1].pressure, 0.3);
  ASSERT_EQ(c.initial_velocities.size(), 2u);
  EXPECT_TRUE(c.initial_velocities[0].group.empty());
  const auto value = [](const sf::Expression& e) { return e.evaluate(1.0, 2.0, 3.0); };
  EXPECT_EQ(value(c.initial_velocities[0].velocity[2]), -1000.0);
  EXPECT_EQ(value(c.initial_velocities[0].angular_velocity[1]), 0.0);  // default
  EXPECT_EQ(c.initial_velocities[1].group, "edge");
  EXPECT_EQ(value(c.initial_velocities[1].velocity[0]), 0.0);  // default
  EXPECT_EQ(value(c.initial_velocities[1].angular_velocity[1]), 50.0);
  EXPECT_EQ(value(c.initial_velocities[1].angular_velocity[2]), 2.0 * 1.0 + 3.0);  // 2 x + z
  ASSERT_EQ(c.prescribed_velocities.size(), 1u);
  EXPECT_TRUE(c.prescribed_velocities[0].components[0]);
  EXPECT_FALSE(c.prescribed_velocities[0].components[1]);
  EXPECT_TRUE(c.prescribed_velocities[0].components[2]);
  EXPECT_EQ(c.control.gravity[2], -9810.0);
  EXPECT_EQ(c.control.damping, 50.0);
}

TEST(ReadCaseLoads, ResolvedCaseRoundTrips) {
  const sf::CaseConfig a = sf::read_case(write_case("round_trip", full_loads));
  const fs::path again = write_case("round_trip_again", "");
  std::ofstream(again) << sf::format_resolved_case(a);
  const sf::CaseConfig b = sf::read_case(again);
  ASSERT_EQ(b.loads.size(), 2u);
  EXPECT_EQ(b.loads[0].value, a.loads[0].value);
  EXPECT_EQ(b.loads[0].curve.values, a.loads[0].curve.values);
  EXPECT_EQ(b.loads[1].pressure, a.loads[1].pressure);
  for (std::size_t k = 0; k < 2; ++k) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(b.initial_velocities[k].velocity[c].text(),
                a.initial_velocities[k].velocity[c].text());
      EXPECT_EQ(b.initial_velocities[k].angular_velocity[c].text(),
                a.initial_velocities[k].angular_velocity[c].text());
    }
  }
  EXPECT_EQ(b.prescribed_velocities[0].components, a.prescribed_velocities[0].components);
  EXPECT_EQ(b.control.gravity, a.control.gravity);
  EXPECT_EQ(b.control.damping, a.control.damping);
}

TEST(ReadCaseLoads, ErrorsNameTheKey) {
  const std::string control = "[control]\nend_time = 0.01\n";
  EXPECT_NE(
      error_of(
          write_case("value_on_pressure",
                     "[[load]]\ngroup = \"a\"\ntype = \"pressure\"\nvalue = [1, 2, 3]\n" + control))
          .find("load[0].value"),
      std::string::npos);
  EXPECT_NE(
      error_of(write_case("missing_value", "[[load]]\ngroup = \"a\"\ntype = \"force\"\n" + control))
          .find("load[0].value"),
      std::string::npos);
  EXPECT_NE(
      error_of(write_case("bad_type", "[[load]]\ngroup = \"a\"\ntype = \"torque\"\n" + control))
          .find("load[0].type"),
      std::string::npos);
  EXPECT_NE(error_of(write_case("bad_component",
                                "[[prescribed_velocity]]\ngroup = \"a\"\n"
                                "velocity = [1, 0, 0]\ncomponents = [\"w\"]\n" +
                                    control))
                .find("prescribed_velocity[0].components"),
            std::string::npos);
  // An expression that does not parse: the key, the character and what was expected.
  const std::string bad_expression = error_of(write_case(
      "bad_expression", "[[initial_velocity]]\nvelocity = [0, 0, \"sin(x\"]\n" + control));
  EXPECT_NE(bad_expression.find("initial_velocity[0].velocity"), std::string::npos)
      << bad_expression;
  EXPECT_NE(bad_expression.find("expected ')'"), std::string::npos) << bad_expression;
  // Neither a velocity nor an angular velocity: the message offers both.
  const std::string no_velocity =
      error_of(write_case("no_velocity", "[[initial_velocity]]\ngroup = \"a\"\n" + control));
  EXPECT_NE(no_velocity.find("initial_velocity[0].velocity"), std::string::npos) << no_velocity;
  EXPECT_NE(no_velocity.find("angular_velocity"), std::string::npos) << no_velocity;
  EXPECT_NE(error_of(write_case("negative_damping", "[control]\nend_time = 0.01\ndamping = -1.0\n"))
                .find("control.damping"),
            std::string::npos);
  EXPECT_NE(error_of(write_case("short_gravity", "[control]\nend_time = 0.01\ngravity = [0, 1]\n"))
                .find("control.gravity"),
            std::string::npos);
}

}  // namespace
