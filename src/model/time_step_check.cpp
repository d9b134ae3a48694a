#include "model/time_step_check.hpp"

#include <fmt/core.h>

#include <cmath>
#include <limits>
#include <string>

#include "casefile/unit_system.hpp"
#include "core/errors.hpp"
#include "model/physical_ranges.hpp"

namespace sf {
namespace {

// A step an explicit run can advance by: positive, finite and not subnormal (a subnormal step
// is lost against any time above 1e-292 s and has no precision of its own).
bool usable_step(double dt) {
  return dt >= std::numeric_limits<double>::min() && std::isfinite(dt);
}

// "young = 1e+300 MPa" and, when the case's units are named and the value is outside the
// physical range there, what that range is.
std::string value_and_range(const char* key, double value, const std::string& unit,
                            const PhysicalRange& range, const UnitSystem& units) {
  std::string text = fmt::format("{} = {:g} {}", key, value, unit);
  if (const auto r = range_in_units(range, units);
      r && !(value >= r->first && value <= r->second)) {
    text += fmt::format(" (a {} is {:g} to {:g} {} in these units)", range.what, r->first,
                        r->second, unit);
  }
  return text;
}

[[noreturn]] void refuse_wave_speed(const CaseConfig& config, const MaterialConfig& m, double c,
                                    double dt) {
  const UnitSystem units = parse_unit_system(config.units);
  throw InputError(fmt::format(
      "{}: materials.{}: {}, {} and poisson = {:g} give a plate wave speed sqrt(E / (rho (1 - "
      "nu^2))) of {:g} {} and a critical time step of {:g} {}: an explicit run cannot advance "
      "by it; expected young and density whose wave speed is a positive finite number and whose "
      "step is a positive normal number (metals: 2e3 to 1.3e4 m/s; units = \"{}\")",
      config.file.string(), m.name,
      value_and_range("young", m.young, units.stress, kYoungRange, units),
      value_and_range("density", m.density, units.density(), kDensityRange, units), m.poisson, c,
      units.velocity(), dt, units.time, config.units));
}

[[noreturn]] void refuse_element(const CaseConfig& config, const StableStep& step, double c) {
  const UnitSystem units = parse_unit_system(config.units);
  const MeshSourceConfig& mesh = config.blank.mesh;
  throw InputError(fmt::format(
      "{}: blank.mesh: element {} of {} has a characteristic length of {:g} {} (its area over its "
      "longest side), which at the wave speed {:g} {} gives a critical time step of {:g} {}: an "
      "explicit run cannot advance by it; expected elements of a positive size{}",
      config.file.string(), step.element, mesh.file.string(), step.dt * c, units.length, c,
      units.velocity(), step.dt, units.time,
      mesh.element_size > 0.0
          ? fmt::format(" (blank.element_size = {:g} {})", mesh.element_size, units.length)
          : std::string()));
}

}  // namespace

void check_critical_time_step(const CaseConfig& config, const Blank& blank,
                              const StableStep& physical) {
  if (usable_step(physical.dt)) {
    return;
  }
  // The limiting element's material (its part's).
  const int part = physical.element >= 0 ? material_index(blank.part, physical.element) : 0;
  const double c = material_wave_speed(blank.part.materials[static_cast<std::size_t>(part)]);
  // The element's length L = dt c is a mesh's length whenever c is usable; otherwise (or when
  // L is an ordinary length) the material made the step.
  const double length = physical.dt * c;
  const bool material = !usable_step(c) || usable_step(length);
  if (material) {
    const BlankPartConfig p = config.blank_parts()[static_cast<std::size_t>(part)];
    refuse_wave_speed(config, config.material_named(p.material), c, physical.dt);
  }
  refuse_element(config, physical, c);
}

void check_scaled_time_step(const CaseConfig& config, const Model& model) {
  const double dt = model.time.time_step;
  if (usable_step(dt)) {
    return;
  }
  throw InputError(fmt::format(
      "{}: the time step after mass scaling is {:g} s (control.mass_scaling_dt = {:g} s, "
      "control.time_step_safety = {:g}): an explicit run cannot advance by it; expected a "
      "positive normal step",
      config.file.string(), dt, config.control.mass_scaling_dt, config.control.time_step_safety));
}

}  // namespace sf
