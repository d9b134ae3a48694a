// The physical ranges of a case's values (docs/case-file.md, "Physical ranges"): what a range is
// in the case's units, and in any unit system sheetform accepts.
#include <gtest/gtest.h>

#include "casefile/unit_system.hpp"
#include "model/physical_ranges.hpp"

namespace {

TEST(PhysicalRanges, InTheCasesUnits) {
  // A Young's modulus of 1e8 to 2e12 Pa is 100 to 2e6 MPa; a density of 100 to 1e5 kg/m^3 is
  // 1e-10 to 1e-7 tonne/mm^3 (steel, 7.85e-9, inside).
  const sf::UnitSystem forming = sf::parse_unit_system("mm-s-tonne-N-MPa");
  const auto young = sf::range_in_units(sf::kYoungRange, forming);
  ASSERT_TRUE(young);
  EXPECT_DOUBLE_EQ(young->first, 100.0);
  EXPECT_DOUBLE_EQ(young->second, 2e6);
  const auto density = sf::range_in_units(sf::kDensityRange, forming);
  ASSERT_TRUE(density);
  EXPECT_DOUBLE_EQ(density->first, 1e-10);
  EXPECT_DOUBLE_EQ(density->second, 1e-7);
  // "consistent" has no sizes: no range in its units.
  EXPECT_FALSE(sf::range_in_units(sf::kYoungRange, sf::parse_unit_system("consistent")));
}

TEST(PhysicalRanges, InAnyAcceptedUnits) {
  // Stress units run from Ba (0.1 Pa) to GPa, lengths from um to m.
  const auto young = sf::range_in_any_units(sf::kYoungRange);
  EXPECT_DOUBLE_EQ(young.first, 0.1);    // 1e8 Pa in GPa
  EXPECT_DOUBLE_EQ(young.second, 2e13);  // 2e12 Pa in Ba
  const auto thickness = sf::range_in_any_units(sf::kThicknessRange);
  EXPECT_DOUBLE_EQ(thickness.first, 1e-6);  // 1 um in m
  EXPECT_DOUBLE_EQ(thickness.second, 1e6);  // 1 m in um
  // Every bundled case's values are inside (forming cases and the benchmarks' "consistent" sets).
  EXPECT_TRUE(young.first <= 1.2e6 && 4.32e8 <= young.second);
}

}  // namespace
