// read_case: the anisotropic material, hardening and section keys (hill48 r-values, voce and
// tabulated hardening, integration_rule, hourglass_form, rolling_direction): values, and each
// error naming the case file, the line and the dotted key. The values themselves are in
// test_read_case.cpp (FullCaseReadsEveryValue) and its round trip; the rolling direction against
// the mesh is checked by build_model (tests/solver/test_hill48_run.cpp).
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "casefile/case_config.hpp"
#include "casefile/read_case_fixture.hpp"

namespace {

using namespace sf_test;

/// kMinimal with its material turned into a Hill48 one (r-values given after `poisson`).
std::string hill_case(std::string_view r_values = "r0 = 1.8\nr45 = 1.5\nr90 = 2.3\n") {
  std::string text =
      replaced(kMinimal, "[materials.steel]\n", "[materials.steel]\ntype = \"hill48\"\n");
  return replaced(text, "poisson = 0.3\n", "poisson = 0.3\n" + std::string(r_values));
}

TEST_F(ReadCase, Hill48ReadsItsLankfordCoefficients) {
  const sf::CaseConfig c = sf::read_case(write_case(hill_case()));
  const sf::MaterialConfig& m = c.blank_material();
  EXPECT_EQ(m.type, sf::MaterialConfig::Type::hill48);
  EXPECT_EQ(m.r0, 1.8);
  EXPECT_EQ(m.r45, 1.5);
  EXPECT_EQ(m.r90, 2.3);
  EXPECT_EQ(m.hardening.law, sf::HardeningConfig::Law::swift);  // any hardening law applies
}

TEST_F(ReadCase, Hill48RValuesMustBePositiveAndPresent) {
  std::string text = hill_case("r0 = 1.8\nr45 = 0\nr90 = 2.3\n");
  expect_error(text, line_of(text, "r45 = 0"),
               {"materials.steel.r45", "expected a number > 0", "got 0"});

  text = hill_case("r0 = -1.0\nr45 = 1.5\nr90 = 2.3\n");
  expect_error(text, line_of(text, "r0 = -1.0"), {"materials.steel.r0", "got -1.0"});

  text = hill_case("r0 = 1.8\nr45 = 1.5\n");
  expect_error(text, line_of(text, "[materials.steel]"),
               {"materials.steel.r90", "missing required key"});

  text = hill_case("r0 = 1.8\nr45 = 1.5\nr90 = \"2.3\"\n");
  expect_error(text, line_of(text, "r90 ="), {"materials.steel.r90", "got the string \"2.3\""});
}

TEST_F(ReadCase, LankfordCoefficientsAreOnlyForHill48) {
  const std::string text = replaced(kMinimal, "poisson = 0.3\n", "poisson = 0.3\nr0 = 1.8\n");
  expect_error(text, line_of(text, "r0 = 1.8"),
               {"materials.steel.r0", "not allowed", "\"hill48\""});
}

TEST_F(ReadCase, Hill48NeedsAHardeningTable) {
  std::string text = hill_case();
  text =
      replaced(text, "[materials.steel.hardening]\nK = 565.3\neps0 = 0.007117\nn = 0.2589\n", "");
  expect_error(text, line_of(text, "[materials.steel]"),
               {"materials.steel.hardening", "missing required key"});
}

TEST_F(ReadCase, UnknownMaterialTypeListsHill48) {
  const std::string text =
      replaced(kMinimal, "[materials.steel]\n", "[materials.steel]\ntype = \"barlat\"\n");
  expect_error(text, line_of(text, "type = \"barlat\""),
               {"materials.steel.type", "\"hill48\"", "got the string \"barlat\""});
}

const std::string_view kSwiftTable = "K = 565.3\neps0 = 0.007117\nn = 0.2589\n";

TEST_F(ReadCase, LudwikHardeningValuesAndErrors) {
  std::string text =
      replaced(kMinimal, kSwiftTable, "law = \"ludwik\"\nA = 200\nB = 500\nn = 0.3\n");
  const sf::HardeningConfig h = sf::read_case(write_case(text)).blank_material().hardening;
  EXPECT_EQ(h.law, sf::HardeningConfig::Law::ludwik);
  EXPECT_EQ(h.ludwik_a, 200.0);
  EXPECT_EQ(h.ludwik_b, 500.0);
  EXPECT_EQ(h.ludwik_n, 0.3);

  text = replaced(kMinimal, kSwiftTable, "law = \"ludwik\"\nA = 0\nB = 500\nn = 0.3\n");
  expect_error(text, line_of(text, "A = 0"), {"materials.steel.hardening.A", "> 0 (MPa)", "got 0"});

  text = replaced(kMinimal, kSwiftTable, "law = \"ludwik\"\nA = 200\nB = 500\nn = 1.5\n");
  expect_error(text, line_of(text, "n = 1.5"), {"materials.steel.hardening.n", "got 1.5"});

  text = replaced(kMinimal, kSwiftTable, "law = \"ludwik\"\nA = 200\nn = 0.3\n");
  expect_error(text, line_of(text, "[materials.steel.hardening]"),
               {"materials.steel.hardening.B", "missing required key"});

  text = replaced(kMinimal, kSwiftTable, "law = \"ludwik\"\nA = 200\nB = 500\nn = 0.3\nK = 1\n");
  expect_error(text, line_of(text, "K = 1"),
               {"materials.steel.hardening.K", "unknown key", "A, B, n"});
}

TEST_F(ReadCase, VoceHardeningValuesAndErrors) {
  std::string text =
      replaced(kMinimal, kSwiftTable, "law = \"voce\"\nsigma0 = 200\nQ = 150.5\nb = 9.0\n");
  const sf::HardeningConfig h = sf::read_case(write_case(text)).blank_material().hardening;
  EXPECT_EQ(h.law, sf::HardeningConfig::Law::voce);
  EXPECT_EQ(h.voce_sigma0, 200.0);
  EXPECT_EQ(h.voce_q, 150.5);
  EXPECT_EQ(h.voce_b, 9.0);

  text = replaced(kMinimal, kSwiftTable, "law = \"voce\"\nsigma0 = 200\nQ = 150.5\nb = 0\n");
  expect_error(text, line_of(text, "b = 0"),
               {"materials.steel.hardening.b", "expected a number > 0", "got 0"});

  text = replaced(kMinimal, kSwiftTable, "law = \"voce\"\nsigma0 = 200\nQ = -1\nb = 9\n");
  expect_error(text, line_of(text, "Q = -1"), {"materials.steel.hardening.Q", ">= 0 (MPa)"});

  text = replaced(kMinimal, kSwiftTable, "law = \"voce\"\nsigma0 = 200\nb = 9\n");
  expect_error(text, line_of(text, "[materials.steel.hardening]"),
               {"materials.steel.hardening.Q", "missing required key"});

  // Keys of another law are unknown here.
  text = replaced(kMinimal, kSwiftTable, "law = \"voce\"\nsigma0 = 200\nQ = 1\nb = 9\nn = 0.2\n");
  expect_error(text, line_of(text, "n = 0.2"),
               {"materials.steel.hardening.n", "unknown key", "sigma0, Q, b"});
}

TEST_F(ReadCase, TabulatedHardeningFileIsRelativeToTheCaseAndMustExist) {
  std::string text = replaced(kMinimal, kSwiftTable, "law = \"tabulated\"\nfile = \"flow.csv\"\n");
  const sf::HardeningConfig h = sf::read_case(write_case(text)).blank_material().hardening;
  EXPECT_EQ(h.law, sf::HardeningConfig::Law::tabulated);
  EXPECT_EQ(h.table_file, dir_ / "flow.csv");

  text = replaced(kMinimal, kSwiftTable, "law = \"tabulated\"\nfile = \"tables/missing.csv\"\n");
  expect_error(text, line_of(text, "file ="),
               {"materials.steel.hardening.file", "file not found",
                (dir_ / "tables" / "missing.csv").string()});

  text = replaced(kMinimal, kSwiftTable, "law = \"tabulated\"\nfile = \"flow.txt\"\n");
  expect_error(text, line_of(text, "file ="),
               {"materials.steel.hardening.file", "expected a .csv file"});

  text = replaced(kMinimal, kSwiftTable, "law = \"tabulated\"\n");
  expect_error(text, line_of(text, "[materials.steel.hardening]"),
               {"materials.steel.hardening.file", "missing required key"});

  text = replaced(kMinimal, kSwiftTable, "law = \"tabulated\"\nfile = \"flow.csv\"\nK = 565.3\n");
  expect_error(text, line_of(text, "K = 565.3"),
               {"materials.steel.hardening.K", "unknown key", "law, file"});
}

TEST_F(ReadCase, SectionHourglassAndRollingDirectionValues) {
  const std::string text = replaced(kMinimal, "thickness = 0.81\n",
                                    "thickness = 0.81\nintegration_rule = \"lobatto\"\n"
                                    "integration_points = 2\nformulation = \"belytschko_tsay\"\n"
                                    "hourglass_form = \"stiffness\"\n"
                                    "rolling_direction = [0, 2, 0]\n");
  const sf::BlankConfig b = sf::read_case(write_case(text)).blank;
  EXPECT_EQ(b.integration_rule, sf::ThroughThicknessRule::lobatto);
  EXPECT_EQ(b.integration_points, 2);
  EXPECT_EQ(b.hourglass_form, sf::HourglassForm::stiffness);
  EXPECT_EQ(b.hourglass_coefficient, 0.1);                                 // default kept
  EXPECT_EQ(b.rolling_direction, (std::array<double, 3>{0.0, 1.0, 0.0}));  // normalised, exact
}

TEST_F(ReadCase, SectionHourglassAndRollingDirectionErrors) {
  const auto with = [](std::string_view keys) {
    return replaced(kMinimal, "thickness = 0.81\n", "thickness = 0.81\n" + std::string(keys));
  };
  std::string text = with("integration_rule = \"simpson\"\n");
  expect_error(
      text, line_of(text, "integration_rule"),
      {"blank.integration_rule", "one of \"gauss\", \"lobatto\"", "got the string \"simpson\""});

  // Gauss-Lobatto needs both surfaces: at least 2 points.
  text = with("integration_rule = \"lobatto\"\nintegration_points = 1\n");
  expect_error(text, line_of(text, "integration_points"),
               {"blank.integration_points", "[2, 9]", "lobatto", "got 1"});

  text = with("formulation = \"belytschko_tsay\"\nhourglass_form = \"viscuous\"\n");
  expect_error(text, line_of(text, "hourglass_form"),
               {"blank.hourglass_form", "\"viscous\", \"stiffness\"", "\"viscuous\""});

  // The assumed-strain element has no hourglass control to set.
  text = with("formulation = \"assumed_strain\"\nhourglass = 0.05\n");
  expect_error(text, line_of(text, "hourglass"),
               {"blank.hourglass", "belytschko_tsay", "no coefficient"});

  // ... nor has the default formulation: the message says how to get the hourglass keys.
  text = with("hourglass_form = \"stiffness\"\n");
  expect_error(text, line_of(text, "hourglass_form"),
               {"blank.hourglass_form", "(the default)", "set formulation = \"belytschko_tsay\""});

  text = with("rolling_direction = [0, 0, 0]\n");
  expect_error(text, line_of(text, "rolling_direction"),
               {"blank.rolling_direction", "not all zero", "got [0, 0, 0]"});

  text = with("rolling_direction = [1, 0]\n");
  expect_error(text, line_of(text, "rolling_direction"),
               {"blank.rolling_direction", "an array of 3 numbers"});
}

/// kMinimal with `forming_limit_curve = <value>` in its material.
std::string flc_case(std::string_view value) {
  return replaced(kMinimal, "poisson = 0.3\n",
                  fmt::format("poisson = 0.3\nforming_limit_curve = {}\n", value));
}

TEST_F(ReadCase, FormingLimitCurveReadsItsPoints) {
  // True strains [minor, major]; integers accepted as numbers (the round trip is in
  // test_read_case.cpp; the formability results use it, tests/model/test_formability.cpp).
  const sf::MaterialConfig m =
      sf::read_case(write_case(flc_case("[[-0.4, 0.6], [0, 0.25], [0.3, 0.4], [1, 1]]")))
          .blank_material();
  EXPECT_EQ(m.forming_limit_curve,
            (std::vector<std::array<double, 2>>{{-0.4, 0.6}, {0.0, 0.25}, {0.3, 0.4}, {1.0, 1.0}}));
}

TEST_F(ReadCase, FormingLimitCurveErrorsNameTheKeyAndThePoint) {
  constexpr std::string_view key = "materials.steel.forming_limit_curve";
  // Not an array, and fewer than 2 points.
  std::string text = flc_case("0.25");
  expect_error(
      text, line_of(text, "forming_limit_curve"),
      {key, "expected an array of at least 2 [minor, major] true-strain points", "got 0.25"});
  text = flc_case("[[0.0, 0.25]]");
  expect_error(text, line_of(text, "forming_limit_curve"),
               {key, "at least 2 [minor, major] true-strain points", "got [[0.0, 0.25]]"});
  text = flc_case("[]");
  expect_error(text, line_of(text, "forming_limit_curve"), {key, "at least 2", "got []"});
  // A point that is not 2 numbers.
  text = flc_case("[[-0.2, 0.3], [0.0, 0.25, 1.0]]");
  expect_error(text, line_of(text, "forming_limit_curve"),
               {"materials.steel.forming_limit_curve[1]",
                "expected a point [minor, major] of 2 finite numbers", "got [0.0, 0.25, 1.0]"});
  text = flc_case(R"([[-0.2, 0.3], [0.0, "0.25"]])");
  expect_error(text, line_of(text, "forming_limit_curve"),
               {"forming_limit_curve[1]", "2 finite numbers", R"(got [0.0, "0.25"])"});
  // Not finite.
  text = flc_case("[[-0.2, 0.3], [nan, 0.25]]");
  expect_error(text, line_of(text, "forming_limit_curve"),
               {"forming_limit_curve[1]", "2 finite numbers", "got [nan, 0.25]"});
  text = flc_case("[[-0.2, inf], [0.0, 0.25]]");
  expect_error(text, line_of(text, "forming_limit_curve"),
               {"forming_limit_curve[0]", "2 finite numbers", "got [-0.2, inf]"});
  // Major strain must be > 0.
  text = flc_case("[[-0.2, 0.3], [0.0, 0.0]]");
  expect_error(text, line_of(text, "forming_limit_curve"),
               {"forming_limit_curve[1]", "expected a major strain > 0, got 0.0"});
  text = flc_case("[[-0.2, -0.1], [0.0, 0.2]]");
  expect_error(text, line_of(text, "forming_limit_curve"),
               {"forming_limit_curve[0]", "expected a major strain > 0, got -0.1"});
  // Minor strains strictly increasing.
  text = flc_case("[[-0.2, 0.3], [0.1, 0.25], [0.1, 0.3]]");
  expect_error(
      text, line_of(text, "forming_limit_curve"),
      {"forming_limit_curve[2]", "minor strains strictly increasing", "got 0.1 after 0.1"});
  text = flc_case("[[0.1, 0.3], [-0.2, 0.25]]");
  expect_error(text, line_of(text, "forming_limit_curve"),
               {"forming_limit_curve[1]", "strictly increasing", "got -0.2 after 0.1"});
  // Falling to its lowest point, rising after it: a rise on the left and a fall on the right are
  // refused at the point where they happen.
  text = flc_case("[[-0.4, 0.5], [-0.2, 0.6], [0, 0.25], [0.3, 0.4]]");
  expect_error(text, line_of(text, "forming_limit_curve"),
               {"forming_limit_curve[1]", "falls to its lowest major strain (0.25 at minor 0.0)",
                "major 0.6 at minor -0.2 rises after 0.5"});
  text = flc_case("[[-0.4, 0.6], [0, 0.25], [0.2, 0.4], [0.4, 0.35]]");
  expect_error(
      text, line_of(text, "forming_limit_curve"),
      {"forming_limit_curve[3]", "rises after it", "major 0.35 at minor 0.4 falls after 0.4"});
}

}  // namespace
