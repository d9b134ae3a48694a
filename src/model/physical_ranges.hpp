#pragma once
// Values no sheet can have: refused when no unit system sheetform accepts makes them physical,
// warned when the case's declared units do not (docs/case-file.md, "Physical ranges"). Derived,
// dimensionless quantities (thickness against the blank's size and its elements, yield stress
// against Young's modulus, tool speed against the sheet's wave speed) are checked without units.
#include <optional>
#include <string>
#include <utility>

#include "casefile/case_config.hpp"
#include "casefile/unit_system.hpp"
#include "model/model.hpp"

namespace sf {

/// The widest range a quantity of a sheet-forming case can physically have, in SI units.
struct PhysicalRange {
  const char* what;     ///< "a Young's modulus"
  Dimension dimension;  ///< of the quantity
  double lo;            ///< SI
  double hi;            ///< SI
  const char* si_unit;  ///< "Pa"
};

/// Polymers (0.1 GPa) to diamond (1.2 TPa).
inline constexpr PhysicalRange kYoungRange{"Young's modulus", {-1, -2, 1}, 1e8, 2e12, "Pa"};
/// Foams and polymers to osmium (22,600 kg/m^3), with room for a scaled density.
inline constexpr PhysicalRange kDensityRange{"density", {-3, 0, 1}, 1e2, 1e5, "kg/m^3"};
/// The plate wave speed sqrt(E / (rho (1 - nu^2))): soft polymers to beryllium (12,900 m/s).
inline constexpr PhysicalRange kWaveSpeedRange{"wave speed", {1, -1, 0}, 1e2, 1e5, "m/s"};
/// A yield stress: lead (5 MPa) to the strongest steels (3 GPa), with a factor of 3 around.
inline constexpr PhysicalRange kYieldRange{"yield stress", {-1, -2, 1}, 1e6, 1e10, "Pa"};
/// A sheet or shell: foil (1 µm) to a 1 m thick shell.
inline constexpr PhysicalRange kThicknessRange{"thickness", {1, 0, 0}, 1e-6, 1.0, "m"};
/// An element size: 1 µm to 10 m.
inline constexpr PhysicalRange kElementSizeRange{"element size", {1, 0, 0}, 1e-6, 10.0, "m"};

/// The range in the case's units, or nullopt when they are "consistent" (no known size).
std::optional<std::pair<double, double>> range_in_units(const PhysicalRange& range,
                                                        const UnitSystem& units);
/// The numbers some accepted unit system makes physical: the range divided by the largest and
/// the smallest size of the quantity's unit among the systems (accepted_unit_systems).
std::pair<double, double> range_in_any_units(const PhysicalRange& range);

/// Refuses (InputError naming the case file, the key, the value and the range) a value of the
/// blank or its material that no accepted unit system makes physical, and a thickness, yield
/// stress or tool speed whose ratio to the blank's size, Young's modulus or wave speed no sheet
/// can have; warns about values outside the physical range in the case's declared units and
/// ratios outside the usual. A static analysis has no density, wave speed or speeds to check.
void check_physical_ranges(const CaseConfig& config, const Model& model);

}  // namespace sf
