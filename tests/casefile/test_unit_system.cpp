// The case's unit system: parsed names and the derived units messages use.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "casefile/unit_system.hpp"

namespace {

std::string error_of(const std::string& text) {
  try {
    sf::parse_unit_system(text);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  ADD_FAILURE() << "no error for " << text;
  return {};
}

TEST(UnitSystem, FormingUnitsAndTheirDerivedNames) {
  const sf::UnitSystem u = sf::parse_unit_system("mm-s-tonne-N-MPa");
  EXPECT_EQ(u.length, "mm");
  EXPECT_EQ(u.time, "s");
  EXPECT_EQ(u.mass, "tonne");
  EXPECT_EQ(u.force, "N");
  EXPECT_EQ(u.stress, "MPa");
  // The names the banner, the summary and the history attributes write.
  EXPECT_EQ(u.velocity(), "mm/s");
  EXPECT_EQ(u.acceleration(), "mm/s^2");
  EXPECT_EQ(u.density(), "tonne/mm^3");
  EXPECT_EQ(u.moment(), "N mm");
  EXPECT_EQ(u.stiffness(), "N/mm");
  EXPECT_EQ(u.area(), "mm^2");
  EXPECT_EQ(u.rate(), "1/s");
}

TEST(UnitSystem, SiUnits) {
  const sf::UnitSystem u = sf::parse_unit_system("m-s-kg-N-Pa");
  EXPECT_EQ(u.moment(), "N m");
  EXPECT_EQ(u.density(), "kg/m^3");
}

TEST(UnitSystem, ConsistentSetWithoutNamesPrintsDimensions) {
  // MacNeal-Harder's benchmarks give their data in no named system.
  const sf::UnitSystem u = sf::parse_unit_system("consistent");
  EXPECT_EQ(u.length, "[L]");
  EXPECT_EQ(u.force, "[F]");
  EXPECT_EQ(u.stress, "[F/L^2]");
  EXPECT_EQ(u.moment(), "[F] [L]");
}

TEST(UnitSystem, ErrorsSayWhatIsWrong) {
  // tonne x m / s^2 = 1e3 N = kN: N is inconsistent, and the accepted name of the implied unit
  // is given.
  EXPECT_EQ(error_of("m-s-tonne-N-Pa"),
            "inconsistent units: tonne x m / s^2 is kN, not N (force = mass x length / time^2)");
  // g x mm / s^2 = 1e-6 N has no accepted name: its size in N is given.
  EXPECT_EQ(error_of("mm-s-g-N-MPa"),
            "inconsistent units: g x mm / s^2 is 1e-06 N (no accepted name), not N (force = mass "
            "x length / time^2)");
  EXPECT_EQ(error_of("mm-s-tonne-N-Pa"),
            "inconsistent units: N / mm^2 is MPa, not Pa (stress = force / length^2)");
  EXPECT_EQ(error_of("inch-s-tonne-N-MPa"),
            "unknown length unit \"inch\" (accepted: m, cm, mm, um)");
  EXPECT_EQ(error_of("mm-s-tonne-N-MPa-K"),
            "expected five units LENGTH-TIME-MASS-FORCE-STRESS separated by '-' (e.g. "
            "\"mm-s-tonne-N-MPa\" or \"m-s-kg-N-Pa\"), or \"consistent\", got 6 parts");
}

TEST(UnitSystem, SizesOfDerivedUnits) {
  const sf::UnitSystem forming = sf::parse_unit_system("mm-s-tonne-N-MPa");
  ASSERT_TRUE(forming.named());
  EXPECT_DOUBLE_EQ(forming.si_size({-1, -2, 1}), 1e6);  // MPa in Pa
  EXPECT_DOUBLE_EQ(forming.si_size({-3, 0, 1}), 1e12);  // tonne/mm^3 in kg/m^3
  EXPECT_DOUBLE_EQ(forming.si_size({1, -1, 0}), 1e-3);  // mm/s in m/s
  EXPECT_FALSE(sf::parse_unit_system("consistent").named());
  EXPECT_EQ(sf::parse_unit_system("consistent").si_size({1, 0, 0}), 0.0);
}

TEST(UnitSystem, AcceptedSystemsAreTheConsistentOnes) {
  // 15 of the 1200 combinations of the accepted names are consistent, the forming and SI systems
  // among them; each reads back as itself.
  const auto& systems = sf::accepted_unit_systems();
  EXPECT_EQ(systems.size(), 15u);
  int forming = 0, si = 0;
  for (const sf::UnitSystem& u : systems) {
    const std::string name =
        u.length + "-" + u.time + "-" + u.mass + "-" + u.force + "-" + u.stress;
    EXPECT_NO_THROW(sf::parse_unit_system(name)) << name;
    forming += name == "mm-s-tonne-N-MPa";
    si += name == "m-s-kg-N-Pa";
  }
  EXPECT_EQ(forming, 1);
  EXPECT_EQ(si, 1);
}

}  // namespace
