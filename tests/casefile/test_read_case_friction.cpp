// Case-file keys of friction beyond Coulomb ([[contact]] friction_pressure_exponent,
// friction_reference_pressure, friction_pressure_table, friction_speed_table,
// friction_across_ratio; docs/contact.md "Friction laws"): values and defaults, errors that name
// the file, the line, the key and the tool, the rules between the keys, and the resolved-case
// round trip (written only when given: a case without them resolves as before).
#include <gtest/gtest.h>

#include <string>

#include "read_case_fixture.hpp"

namespace sf_test {
namespace {

// The minimal case with a die and one [[contact]] with it whose body is `contact`.
std::string with_contact(const std::string& contact) {
  return std::string(kMinimal) +
         "[[tools]]\nname = \"die\"\nmesh = \"die.msh\"\n[[contact]]\ntool = \"die\"\n" + contact;
}

const std::string kPowerLaw =
    "friction_static = 0.15\n"
    "friction_pressure_exponent = 0.8\n"
    "friction_reference_pressure = 10.0\n"
    "friction_speed_table = [[0.0, 1.0], [100.0, 0.9], [1000.0, 0.8]]\n"
    "friction_across_ratio = 1.25\n";

const std::string kTable = "friction_pressure_table = [[1.0, 0.16], [10.0, 0.13], [50.0, 0.1]]\n";

TEST_F(ReadCase, FrictionReadsEveryValue) {
  const sf::CaseConfig a = sf::read_case(write_case(with_contact(kPowerLaw)));
  const sf::ContactConfig& c = a.contacts[0];
  EXPECT_EQ(c.friction_static, 0.15);
  EXPECT_EQ(c.friction_dynamic, 0.15);
  EXPECT_EQ(c.friction_pressure_exponent, 0.8);
  EXPECT_EQ(c.friction_reference_pressure, 10.0);
  ASSERT_EQ(c.friction_speed_table.size(), 3u);
  EXPECT_EQ(c.friction_speed_table[1][0], 100.0);
  EXPECT_EQ(c.friction_speed_table[1][1], 0.9);
  EXPECT_TRUE(c.friction_pressure_table.empty());
  EXPECT_EQ(c.friction_across_ratio, 1.25);
  const sf::CaseConfig b = sf::read_case(write_case(with_contact(kTable)));
  const sf::ContactConfig& t = b.contacts[0];
  EXPECT_EQ(t.friction_static, 0.0);
  ASSERT_EQ(t.friction_pressure_table.size(), 3u);
  EXPECT_EQ(t.friction_pressure_table[2][0], 50.0);
  EXPECT_EQ(t.friction_pressure_table[2][1], 0.1);
  EXPECT_EQ(t.friction_pressure_exponent, 1.0);  // the defaults
  EXPECT_EQ(t.friction_across_ratio, 1.0);
  EXPECT_TRUE(t.friction_speed_table.empty());
}

TEST_F(ReadCase, FrictionResolvedCaseRoundTripsAndOmitsWhatWasNotGiven) {
  for (const std::string& contact : {kPowerLaw, kTable, std::string("friction = 0.1\n")}) {
    const sf::CaseConfig a = sf::read_case(write_case(with_contact(contact)));
    const std::string resolved = sf::format_resolved_case(a);
    SCOPED_TRACE(resolved);
    const sf::CaseConfig b = sf::read_case(write_case(resolved, "again.toml"));
    const sf::ContactConfig &x = a.contacts[0], &y = b.contacts[0];
    EXPECT_EQ(y.friction_static, x.friction_static);
    EXPECT_EQ(y.friction_pressure_exponent, x.friction_pressure_exponent);
    EXPECT_EQ(y.friction_reference_pressure, x.friction_reference_pressure);
    EXPECT_EQ(y.friction_pressure_table, x.friction_pressure_table);
    EXPECT_EQ(y.friction_speed_table, x.friction_speed_table);
    EXPECT_EQ(y.friction_across_ratio, x.friction_across_ratio);
    if (contact == "friction = 0.1\n") {
      EXPECT_EQ(resolved.find("friction_pressure"), std::string::npos);
      EXPECT_EQ(resolved.find("friction_speed"), std::string::npos);
      EXPECT_EQ(resolved.find("friction_across"), std::string::npos);
      EXPECT_EQ(resolved.find("friction_reference"), std::string::npos);
    }
  }
}

TEST_F(ReadCase, FrictionBadTablesNameTheFileTheKeyAndTheTool) {
  // Reading the case with the contact body `contact` fails naming the case file, with `parts`.
  const auto expect_bad = [this](const std::string& contact,
                                 std::initializer_list<std::string_view> parts) {
    expect_error(with_contact(contact), 0, parts);
  };
  expect_bad("friction_pressure_table = [[1.0, 0.16], [1.0, 0.13]]\n",
             {"case.toml:", "contact[0].friction_pressure_table[1]", "contact with tool 'die'",
              "pressure to increase strictly", "got 1.0 after 1.0"});
  expect_bad("friction_pressure_table = [[1.0, 0.16], [2.0, -0.1]]\n",
             {"contact[0].friction_pressure_table[1]", "tool 'die'", "a mu that is",
              "a number >= 0", "-0.1"});
  expect_bad("friction_pressure_table = [[-1.0, 0.16], [2.0, 0.1]]\n",
             {"contact[0].friction_pressure_table[0]", "pressure", ">= 0 (MPa)", "-1.0"});
  expect_bad("friction_pressure_table = [[1.0, 0.16]]\n",
             {"contact[0].friction_pressure_table", "at least 2 points", "[pressure (MPa), mu]"});
  expect_bad("friction_pressure_table = [[1.0, 0.16, 3.0], [2, 1]]\n",
             {"contact[0].friction_pressure_table[0]", "2 finite numbers"});
  expect_bad("friction_pressure_table = [[1.0, nan], [2.0, 0.1]]\n",
             {"contact[0].friction_pressure_table[0]", "2 finite numbers"});
  expect_bad("friction = 0.1\nfriction_speed_table = [[10.0, 1.0], [5.0, 0.9]]\n",
             {"contact[0].friction_speed_table[1]", "tool 'die'", "slip speed to increase strictly",
              "5.0 after 10.0"});
  expect_bad("friction = 0.1\nfriction_speed_table = [[0.0, 1.0], [5.0, -2.0]]\n",
             {"contact[0].friction_speed_table[1]", "factor", ">= 0", "-2.0"});
}

TEST_F(ReadCase, FrictionRulesBetweenTheKeys) {
  // Reading the case with the contact body `contact` fails naming the case file, with `parts`.
  const auto expect_bad = [this](const std::string& contact,
                                 std::initializer_list<std::string_view> parts) {
    expect_error(with_contact(contact), 0, parts);
  };
  // A pressure table gives the coefficient: no Coulomb key with it.
  expect_bad("friction_static = 0.1\n" + kTable,
             {"contact[0].friction_static", "friction_pressure_table gives the coefficient"});
  expect_bad("friction = 0.1\n" + kTable, {"contact[0].friction", "tool 'die'"});
  // ... nor the power law.
  expect_bad(kTable + "friction_pressure_exponent = 0.8\n",
             {"contact[0].friction_pressure_exponent",
              "gives the coefficient against the pressure itself"});
  // The power law's p0 is required with it and refused without it.
  expect_bad("friction = 0.1\nfriction_pressure_exponent = 0.8\n",
             {"contact[0].friction_reference_pressure", "missing"});
  expect_bad("friction = 0.1\nfriction_reference_pressure = 5.0\n",
             {"contact[0].friction_reference_pressure", "needs friction_pressure_exponent"});
  expect_bad(
      "friction = 0.1\nfriction_pressure_exponent = 0.8\n"
      "friction_reference_pressure = 0.0\n",
      {"contact[0].friction_reference_pressure", "> 0 (MPa)"});
  expect_bad("friction = 0.1\nfriction_pressure_exponent = 0.0\n",
             {"contact[0].friction_pressure_exponent", "> 0"});
  // Shaping keys without friction.
  expect_bad("friction_across_ratio = 2.0\n",
             {"contact[0].friction_across_ratio", "no friction to shape"});
  expect_bad("friction_speed_table = [[0.0, 1.0], [1.0, 1.0]]\n",
             {"contact[0].friction_speed_table", "no friction to shape"});
  expect_bad("friction = 0.1\nfriction_across_ratio = 0.0\n",
             {"contact[0].friction_across_ratio", "> 0"});
}

}  // namespace
}  // namespace sf_test
