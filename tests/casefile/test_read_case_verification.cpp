// read_case for what a verification engineer sets: the unit system, [[history]] node groups,
// .geo parameters of a mesh source and command-line overrides (--set). Every error names the
// file, line and key and says what was expected.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "casefile/read_case_fixture.hpp"

namespace fs = std::filesystem;

namespace {

using sf_test::expect_contains;
using sf_test::kFull;
using sf_test::kMinimal;
using sf_test::line_of;
using sf_test::ReadCase;
using sf_test::replaced;

// kMinimal with `extra` appended (new tables go after [control], the last one).
std::string minimal_with(std::string_view extra) {
  return std::string(kMinimal) + std::string(extra);
}

std::string static_with(std::string_view extra) {
  return minimal_with(std::string("\n[analysis]\ntype = \"static\"\n") + std::string(extra));
}

// ----------------------------------------------------------------------------------- units ---

TEST_F(ReadCase, UnitsAcceptConsistentSystems) {
  // Each is consistent: force = mass x length / time^2, stress = force / length^2 (e.g. kg mm /
  // ms^2 = 1e3 N = kN and kN / mm^2 = GPa; g cm / s^2 = dyn and dyn / cm^2 = Ba).
  for (const char* units : {"mm-s-tonne-N-MPa", "m-s-kg-N-Pa", "mm-ms-kg-kN-GPa", "mm-ms-g-N-MPa",
                            "m-s-tonne-kN-kPa", "cm-s-g-dyn-Ba"}) {
    const sf::CaseConfig c =
        sf::read_case(write_case(fmt::format("units = \"{}\"\n{}", units, kMinimal)));
    EXPECT_EQ(c.units, units);
  }
}

TEST_F(ReadCase, UnitsUnknownNameIsAnErrorListingTheAcceptedOnes) {
  // "t" is not accepted for the tonne (it reads as a time or a thickness elsewhere).
  expect_error(
      fmt::format("units = \"mm-s-t-N-MPa\"\n{}", kMinimal), 1,
      {"units: unknown mass unit \"t\" (accepted: kg, g, mg, tonne)", "got \"mm-s-t-N-MPa\""});
}

TEST_F(ReadCase, UnitsInconsistentSystemIsAnErrorNamingTheImpliedUnit) {
  // kg x mm / s^2 = 1e-3 N = mN, not N.
  expect_error(fmt::format("units = \"mm-s-kg-N-MPa\"\n{}", kMinimal), 1,
               {"units: inconsistent units: kg x mm / s^2 is mN, not N (force = mass x length / "
                "time^2)"});
  // N / mm^2 = MPa, not GPa.
  expect_error(fmt::format("units = \"mm-s-tonne-N-GPa\"\n{}", kMinimal), 1,
               {"units: inconsistent units: N / mm^2 is MPa, not GPa"});
}

TEST_F(ReadCase, UnitsNeedFiveParts) {
  expect_error(fmt::format("units = \"mm-s-tonne\"\n{}", kMinimal), 1,
               {"units: expected five units LENGTH-TIME-MASS-FORCE-STRESS", "got 3 parts"});
}

// --------------------------------------------------------------------------------- history ---

TEST_F(ReadCase, HistoryGroupsDefaultToEveryQuantityOfTheAnalysis) {
  const sf::CaseConfig c = sf::read_case(
      write_case(minimal_with("\n[[history]]\ngroup = \"load_point\"\n[[history]]\ngroup = "
                              "\"clamp\"\nquantities = [\"reaction\", \"displacement\"]\n")));
  ASSERT_EQ(c.history_groups.size(), 2u);
  const sf::HistoryGroupConfig& a = c.history_groups[0];
  EXPECT_EQ(a.group, "load_point");
  EXPECT_TRUE(a.displacement && a.velocity && a.rotation && a.reaction);  // all by default
  const sf::HistoryGroupConfig& b = c.history_groups[1];
  EXPECT_TRUE(b.displacement && b.reaction);
  EXPECT_FALSE(b.velocity || b.rotation);  // only the two listed
  // A static analysis has no velocities: its default leaves them out.
  const sf::CaseConfig s =
      sf::read_case(write_case(static_with("\n[[history]]\ngroup = \"load_point\"\n")));
  ASSERT_EQ(s.history_groups.size(), 1u);
  EXPECT_TRUE(s.history_groups[0].displacement && s.history_groups[0].rotation &&
              s.history_groups[0].reaction);
  EXPECT_FALSE(s.history_groups[0].velocity);
}

TEST_F(ReadCase, HistoryGroupErrorsNameTheKey) {
  const std::string missing = minimal_with("\n[[history]]\nquantities = [\"rotation\"]\n");
  expect_error(missing, line_of(missing, "[[history]]"),
               {"history[0].group: missing required key"});
  const std::string spaced = minimal_with("\n[[history]]\ngroup = \"load point\"\n");
  expect_error(spaced, line_of(spaced, "group = \"load point\""),
               {"history[0].group: expected a group name that can name history columns",
                "got the string \"load point\""});
  const std::string twice =
      minimal_with("\n[[history]]\ngroup = \"tip\"\n[[history]]\ngroup = \"tip\"\n");
  expect_error(twice, line_of(twice, "[[history]]\ngroup = \"tip\"\n[[history]]") + 3,
               {"history[1].group: group \"tip\" is already recorded by history[0]"});
  const std::string unknown =
      minimal_with("\n[[history]]\ngroup = \"tip\"\nquantities = [\"displacement\", \"force\"]\n");
  expect_error(unknown, line_of(unknown, "quantities"),
               {"history[0].quantities[1]: expected one of \"displacement\", \"velocity\", "
                "\"rotation\", \"reaction\", got the string \"force\""});
  const std::string repeated =
      minimal_with("\n[[history]]\ngroup = \"tip\"\nquantities = [\"rotation\", \"rotation\"]\n");
  expect_error(repeated, line_of(repeated, "quantities"),
               {"history[0].quantities[1]: \"rotation\" is listed twice"});
  const std::string empty = minimal_with("\n[[history]]\ngroup = \"tip\"\nquantities = []\n");
  expect_error(empty, line_of(empty, "quantities"),
               {"history[0].quantities: expected a non-empty array of \"displacement\""});
  const std::string extra = minimal_with("\n[[history]]\ngroup = \"tip\"\nevery = 10\n");
  expect_error(extra, line_of(extra, "every"),
               {"history[0].every: unknown key; accepted keys here: group, quantities"});
}

TEST_F(ReadCase, HistoryVelocityOfAStaticAnalysisIsAnError) {
  const std::string text =
      static_with("\n[[history]]\ngroup = \"tip\"\nquantities = [\"velocity\"]\n");
  expect_error(text, line_of(text, "quantities"),
               {"history[0].quantities[0]: a static analysis has no velocities",
                "expected \"displacement\", \"rotation\" or \"reaction\""});
}

// ----------------------------------------------------------------------- .geo parameters ---

TEST_F(ReadCase, GeoParametersAreReadSortedWithTheirLocation) {
  const std::string text = replaced(kMinimal, "mesh = \"blank.geo\"\n",
                                    "mesh = \"blank.geo\"\nparameters = { n = 16, b = 2.5 }\n");
  const sf::CaseConfig c = sf::read_case(write_case(text));
  const std::vector<sf::GeoParameter>& p = c.blank.mesh.parameters;
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].name, "b");  // sorted by name
  EXPECT_EQ(p[0].value, 2.5);
  EXPECT_EQ(p[1].name, "n");
  EXPECT_EQ(p[1].value, 16.0);  // an integer is accepted as a number
  // The location names the key in the case file: line 3, column 16 ("parameters = { n").
  EXPECT_EQ(p[1].location, fmt::format("{}:3:16", (dir_ / "case.toml").string()));
}

TEST_F(ReadCase, GeoParametersOfATool) {
  const std::string text =
      replaced(kFull, "element_size = 2.0\n[tools.motion]",
               "element_size = 2.0\n[tools.parameters]\nr = 5\n[tools.motion]");
  const sf::CaseConfig c = sf::read_case(write_case(text));
  ASSERT_EQ(c.tools[1].mesh.parameters.size(), 1u);
  EXPECT_EQ(c.tools[1].mesh.parameters[0].name, "r");
  EXPECT_EQ(c.tools[1].mesh.parameters[0].value, 5.0);
}

TEST_F(ReadCase, GeoParameterErrorsNameTheKey) {
  const auto with = [](std::string_view parameters) {
    return replaced(kMinimal, "mesh = \"blank.geo\"\n",
                    fmt::format("mesh = \"blank.geo\"\nparameters = {}\n", parameters));
  };
  expect_error(with("{ n = \"16\" }"), 3,
               {"blank.parameters.n: expected a finite number, got the string \"16\""});
  expect_error(with("{ 2n = 16 }"), 3,
               {"blank.parameters.2n: expected a .geo variable name (a letter or '_', then "
                "letters, digits or '_')"});
  expect_error(with("16"), 3, {"blank.parameters: expected a table of numbers, e.g. { n = 16 }"});
  expect_error(with("{ n = nan }"), 3, {"blank.parameters.n: expected a finite number"});
  // A .msh is read as it is: parameters do not apply.
  const std::string msh =
      replaced(kFull, "mesh = \"die.msh\"\n", "mesh = \"die.msh\"\nparameters = { n = 4 }\n");
  expect_error(msh, line_of(msh, "parameters = { n = 4 }"),
               {"tools[0].parameters: not allowed here: parameters are set in a .geo file before "
                "gmsh parses it; a .msh mesh is read as it is"});
}

// ---------------------------------------------------------------- the resolved case ---

TEST_F(ReadCase, ResolvedCaseKeepsHistoryGroupsAndGeoParameters) {
  const std::string text =
      replaced(kMinimal, "mesh = \"blank.geo\"\n",
               "mesh = \"blank.geo\"\nparameters = { n = 16, b = 2.5 }\n") +
      "\n[[history]]\ngroup = \"tip\"\nquantities = [\"rotation\", \"reaction\"]\n";
  const sf::CaseConfig original = sf::read_case(write_case(text));
  const sf::CaseConfig again =
      sf::read_case(write_case(sf::format_resolved_case(original), "resolved.toml"));
  ASSERT_EQ(again.blank.mesh.parameters.size(), 2u);
  EXPECT_EQ(again.blank.mesh.parameters[1].name, "n");
  EXPECT_EQ(again.blank.mesh.parameters[1].value, 16.0);
  ASSERT_EQ(again.history_groups.size(), 1u);
  EXPECT_EQ(again.history_groups[0].group, "tip");
  EXPECT_TRUE(again.history_groups[0].rotation && again.history_groups[0].reaction);
  EXPECT_FALSE(again.history_groups[0].displacement || again.history_groups[0].velocity);
}

// ------------------------------------------------------------------------- overrides ---

TEST_F(ReadCase, OverridesSetKeysBeforeReading) {
  const fs::path file = write_case(kFull);
  const sf::CaseConfig c =
      sf::read_case(file, {"blank.parameters.n=32", "control.output_frames=7",
                           "tools[1].element_size = 1.5", "title=\"refined\""});
  // A table the case does not have is created; its value names the override as its source.
  ASSERT_EQ(c.blank.mesh.parameters.size(), 1u);
  EXPECT_EQ(c.blank.mesh.parameters[0].value, 32.0);
  EXPECT_EQ(c.blank.mesh.parameters[0].location, "command line (--set blank.parameters.n=32)");
  EXPECT_EQ(c.control.output_frames, 7);         // replaces the case's 40
  EXPECT_EQ(c.tools[1].mesh.element_size, 1.5);  // the second [[tools]] (punch)
  EXPECT_EQ(c.tools[0].mesh.element_size, 0.0);  // the first is untouched
  EXPECT_EQ(c.title, "refined");
  // The resolved case holds the overridden values.
  const std::string resolved = sf::format_resolved_case(c);
  expect_contains(resolved, "parameters = { n = 32.0 }");
  expect_contains(resolved, "output_frames = 7");
}

TEST_F(ReadCase, OverrideValueErrorsNameTheOverride) {
  const fs::path file = write_case(kFull);
  const auto message_of = [&](const std::string& override_text) {
    try {
      sf::read_case(file, {override_text});
    } catch (const sf::InputError& error) {
      return std::string(error.what());
    }
    ADD_FAILURE() << "no InputError for --set " << override_text;
    return std::string();
  };
  // Checked like the file's own values, the location being the override.
  expect_contains(message_of("blank.thickness=-1"),
                  "command line (--set blank.thickness=-1): blank.thickness: expected a number > "
                  "0 (mm), got -1");
  expect_contains(message_of("blank.thicknes=1"),
                  "command line (--set blank.thicknes=1): blank.thicknes: unknown key");
  // Malformed overrides.
  expect_contains(message_of("blank.thickness"),
                  "--set blank.thickness: expected KEY=VALUE, e.g. blank.parameters.n=32");
  expect_contains(message_of("title=refined"),
                  "--set title=refined: 'refined' is not a TOML value");
  expect_contains(message_of("tools[9].element_size=1"),
                  "--set tools[9].element_size=1: the case has no tools[9] (it has 3 [[tools]] "
                  "tables)");
  expect_contains(message_of("title.x=1"), "--set title.x=1: title is not a table in the case");
  expect_contains(message_of("tools[0]=1"),
                  "--set tools[0]=1: the last part of KEY must be a key, not an array element");
  expect_contains(message_of("tools[x].name=1"),
                  "--set tools[x].name=1: 'tools[x]': expected an index >= 0 in [ ]");
  expect_contains(message_of("blank..n=1"), "--set blank..n=1: '' is not a key");
  expect_contains(message_of("title=1\nother=2"), "expected one TOML value after '='");
}

}  // namespace
