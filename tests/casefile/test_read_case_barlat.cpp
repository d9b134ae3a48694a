// read_case: Barlat's criteria (type = "yld2000", "yld89"), kinematic hardening
// ([materials.NAME.kinematic]), the Cowper-Symonds rate dependence
// ([materials.NAME.cowper_symonds]) and the Hockett-Sherby and Swift-Voce hardening laws: values,
// each error naming the case file, the line and the dotted key, and the resolved-case round trip
// (bit for bit).
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "casefile/case_config.hpp"
#include "casefile/read_case_fixture.hpp"

namespace {

using namespace sf_test;

// kMinimal with its material's type and keys (after `poisson`) replaced.
std::string material_case(std::string_view type, std::string_view keys) {
  std::string text = replaced(kMinimal, "[materials.steel]\n",
                              fmt::format("[materials.steel]\ntype = \"{}\"\n", type));
  return replaced(text, "poisson = 0.3\n", "poisson = 0.3\n" + std::string(keys));
}

// Barlat et al. (2003) Table 2's AA2090-T3 data.
constexpr std::string_view kData =
    "sigma0 = 279.6\nsigma45 = 226.8\nsigma90 = 254.4\nsigma_b = 289.4\n"
    "r0 = 0.21\nr45 = 1.58\nr90 = 0.69\nr_b = 0.67\n";

TEST_F(ReadCase, Yld2000ReadsItsDataOrItsCoefficients) {
  sf::CaseConfig c = sf::read_case(write_case(material_case("yld2000", kData)));
  const sf::MaterialConfig& m = c.blank_material();
  EXPECT_EQ(m.type, sf::MaterialConfig::Type::yld2000);
  EXPECT_EQ(m.exponent, 8.0);  // the default
  EXPECT_TRUE(m.alpha.empty());
  EXPECT_EQ(m.sigma0, 279.6);
  EXPECT_EQ(m.sigma_b, 289.4);
  EXPECT_EQ(m.r45, 1.58);
  EXPECT_EQ(m.r_b, 0.67);

  c = sf::read_case(write_case(
      material_case("yld2000",
                    "exponent = 6\nalpha = [0.4865, 1.3783, 0.7536, 1.0246, 1.0363, 0.9036, "
                    "1.2321, 1.4858]\n")));
  EXPECT_EQ(c.blank_material().exponent, 6.0);
  EXPECT_EQ(c.blank_material().alpha,
            (std::vector<double>{0.4865, 1.3783, 0.7536, 1.0246, 1.0363, 0.9036, 1.2321, 1.4858}));
}

TEST_F(ReadCase, Yld2000ErrorsNameTheKey) {
  // Coefficients and data together: ambiguous.
  std::string text = material_case("yld2000", "alpha = [1, 1, 1, 1, 1, 1, 1, 1]\nr0 = 0.21\n");
  expect_error(text, line_of(text, "r0 = 0.21"), {"materials.steel.r0", "alpha is given"});
  // Seven coefficients.
  text = material_case("yld2000", "alpha = [1, 1, 1, 1, 1, 1, 1]\n");
  expect_error(text, line_of(text, "alpha ="), {"materials.steel.alpha", "an array of 8 numbers"});
  // A datum missing.
  text = material_case("yld2000", replaced(kData, "r_b = 0.67\n", ""));
  expect_error(text, line_of(text, "[materials.steel]"),
               {"materials.steel.r_b", "missing required key"});
  // An exponent below 2.
  text = material_case("yld2000", std::string(kData) + "exponent = 1.5\n");
  expect_error(text, line_of(text, "exponent = 1.5"),
               {"materials.steel.exponent", "expected a number >= 2"});
  // A datum of another type.
  text = material_case("yld89", "r0 = 0.7\nr45 = 0.6\nr90 = 0.7\nsigma45 = 250\n");
  expect_error(text, line_of(text, "sigma45"), {"materials.steel.sigma45", "\"yld2000\""});
  text = material_case("von_mises", "exponent = 8\n");
  expect_error(text, line_of(text, "exponent = 8"), {"materials.steel.exponent", "\"yld89\""});
}

TEST_F(ReadCase, Yld89ReadsItsRValuesAndExponent) {
  const sf::CaseConfig c =
      sf::read_case(write_case(material_case("yld89",
                                             "r0 = 1.79\nr45 = 1.51\nr90 = 2.27\n"
                                             "exponent = 6\n")));
  const sf::MaterialConfig& m = c.blank_material();
  EXPECT_EQ(m.type, sf::MaterialConfig::Type::yld89);
  EXPECT_EQ(m.exponent, 6.0);
  EXPECT_EQ(m.r90, 2.27);
  const std::string text = material_case("yld89", "r0 = 1.79\nr45 = 1.51\n");
  expect_error(text, line_of(text, "[materials.steel]"),
               {"materials.steel.r90", "missing required key"});
}

TEST_F(ReadCase, KinematicHardeningReadsOneCAndGammaPerBackStress) {
  const std::string kinematic =
      "\n[materials.steel.kinematic]\nC = [15000, 2000]\ngamma = [150, 5]\n";
  const sf::CaseConfig c = sf::read_case(write_case(std::string(kMinimal) + kinematic));
  EXPECT_EQ(c.blank_material().kinematic.C, (std::vector<double>{15000, 2000}));
  EXPECT_EQ(c.blank_material().kinematic.gamma, (std::vector<double>{150, 5}));

  std::string text =
      std::string(kMinimal) + "\n[materials.steel.kinematic]\nC = [15000, 2000]\ngamma = [150]\n";
  expect_error(text, line_of(text, "gamma ="), {"materials.steel.kinematic.gamma", "one gamma"});
  text = std::string(kMinimal) + "\n[materials.steel.kinematic]\nC = [-1]\ngamma = [150]\n";
  expect_error(text, line_of(text, "-1"), {"materials.steel.kinematic.C[0]", "got -1"});
  text = std::string(kMinimal) +
         "\n[materials.steel.kinematic]\nC = [1, 2, 3, 4, 5]\ngamma = [1, 2, 3, 4, 5]\n";
  expect_error(text, line_of(text, "C ="),
               {"materials.steel.kinematic.C", "an array of 1 to 4 numbers"});
  text = std::string(kMinimal) + "\n[materials.steel.kinematic]\nC = [100]\n";
  expect_error(text, 0, {"materials.steel.kinematic.gamma", "missing required key"});
  text = replaced(std::string(kMinimal) + kinematic, "[materials.steel]\n",
                  "[materials.steel]\ntype = \"elastic\"\n");
  text =
      replaced(text, "[materials.steel.hardening]\nK = 565.3\neps0 = 0.007117\nn = 0.2589\n", "");
  expect_error(text, 0, {"materials.steel.kinematic", "elastic"});
}

TEST_F(ReadCase, CowperSymondsReadsDAndQ) {
  const std::string rate = "\n[materials.steel.cowper_symonds]\nD = 40.4\nq = 5\n";
  const sf::CaseConfig c = sf::read_case(write_case(std::string(kMinimal) + rate));
  EXPECT_EQ(c.blank_material().cowper_symonds.D, 40.4);
  EXPECT_EQ(c.blank_material().cowper_symonds.q, 5.0);
  EXPECT_EQ(sf::read_case(write_case(kMinimal)).blank_material().cowper_symonds.D, 0.0);  // off
  std::string text = std::string(kMinimal) + "\n[materials.steel.cowper_symonds]\nD = 0\nq = 5\n";
  expect_error(text, line_of(text, "D = 0"), {"materials.steel.cowper_symonds.D", "1/s"});
  text = std::string(kMinimal) + "\n[materials.steel.cowper_symonds]\nD = 40.4\n";
  expect_error(text, 0, {"materials.steel.cowper_symonds.q", "missing required key"});
  text = std::string(kMinimal) + "\n[materials.steel.cowper_symonds]\nD = 40.4\nq = 5\nC = 1\n";
  expect_error(text, line_of(text, "C = 1"), {"materials.steel.cowper_symonds", "C"});
}

TEST_F(ReadCase, BarlatAndKinematicKeysRoundTripThroughTheResolvedCase) {
  for (const std::string& text :
       {material_case("yld2000", std::string(kData) + "exponent = 7.5\n") +
            "\n[materials.steel.kinematic]\nC = [15000.5, 2000]\ngamma = [150, 0]\n",
        material_case("yld2000",
                      "alpha = [0.4865, 1.3783, 0.7536, 1.0246, 1.0363, 0.9036, "
                      "1.2321, 1.4858]\n"),
        material_case("yld89", "r0 = 0.71\nr45 = 0.58\nr90 = 0.70\nexponent = 8\n") +
            "\n[materials.steel.cowper_symonds]\nD = 6500.25\nq = 4\n"}) {
    const sf::CaseConfig a = sf::read_case(write_case(text));
    const std::string resolved = sf::format_resolved_case(a);
    const sf::CaseConfig b = sf::read_case(write_case(resolved, "again.toml"));
    // The same text, but for the header line naming the file it was read from.
    const auto body = [](const std::string& t) { return t.substr(t.find("\ntitle")); };
    EXPECT_EQ(body(sf::format_resolved_case(b)), body(resolved));
    const sf::MaterialConfig& ma = a.blank_material();
    const sf::MaterialConfig& mb = b.blank_material();
    EXPECT_EQ(mb.type, ma.type);
    EXPECT_EQ(mb.exponent, ma.exponent);
    EXPECT_EQ(mb.alpha, ma.alpha);
    EXPECT_EQ(mb.sigma45, ma.sigma45);
    EXPECT_EQ(mb.r_b, ma.r_b);
    EXPECT_EQ(mb.r90, ma.r90);
    EXPECT_EQ(mb.kinematic.C, ma.kinematic.C);
    EXPECT_EQ(mb.kinematic.gamma, ma.kinematic.gamma);
    EXPECT_EQ(mb.cowper_symonds.D, ma.cowper_symonds.D);
    EXPECT_EQ(mb.cowper_symonds.q, ma.cowper_symonds.q);
  }
}

TEST_F(ReadCase, HockettSherbyAndSwiftVoceHardeningRoundTrip) {
  constexpr std::string_view kSwiftTable = "K = 565.3\neps0 = 0.007117\nn = 0.2589\n";
  const std::string hs = replaced(kMinimal, kSwiftTable,
                                  "law = \"hockett_sherby\"\nsigma_s = 420\nsigma_i = 150\n"
                                  "N = 6\np = 0.7\n");
  const std::string sv = replaced(kMinimal, kSwiftTable,
                                  "law = \"swift_voce\"\nweight = 0.3\nK = 576.79\n"
                                  "eps0 = 0.01658\nn = 0.3593\nsigma0 = 180\nQ = 250\nb = 12.5\n");
  sf::CaseConfig c = sf::read_case(write_case(hs));
  EXPECT_EQ(c.blank_material().hardening.law, sf::HardeningConfig::Law::hockett_sherby);
  EXPECT_EQ(c.blank_material().hardening.hs_sigma_i, 150.0);
  EXPECT_EQ(c.blank_material().hardening.hs_p, 0.7);
  c = sf::read_case(write_case(sv));
  EXPECT_EQ(c.blank_material().hardening.law, sf::HardeningConfig::Law::swift_voce);
  EXPECT_EQ(c.blank_material().hardening.sv_weight, 0.3);
  EXPECT_EQ(c.blank_material().hardening.voce_b, 12.5);
  for (const std::string& text : {hs, sv}) {
    const std::string resolved = sf::format_resolved_case(sf::read_case(write_case(text)));
    const std::string again =
        sf::format_resolved_case(sf::read_case(write_case(resolved, "again.toml")));
    EXPECT_EQ(again.substr(again.find("\ntitle")), resolved.substr(resolved.find("\ntitle")));
  }
  // sigma_i above sigma_s, a weight above 1: named.
  std::string text = replaced(hs, "sigma_i = 150", "sigma_i = 500");
  expect_error(text, line_of(text, "sigma_i = 500"), {"materials.steel.hardening.sigma_i"});
  text = replaced(sv, "weight = 0.3", "weight = 1.3");
  expect_error(text, line_of(text, "weight = 1.3"), {"materials.steel.hardening.weight"});
}

}  // namespace
