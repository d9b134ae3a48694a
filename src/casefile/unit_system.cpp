#include "casefile/unit_system.hpp"

#include <fmt/core.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace sf {
namespace {

/// A unit's name and its size in SI units (m, s, kg, N, Pa).
struct NamedUnit {
  std::string_view name;
  double si;
};

constexpr std::array<NamedUnit, 4> kLengths{{{"m", 1.0}, {"cm", 1e-2}, {"mm", 1e-3}, {"um", 1e-6}}};
constexpr std::array<NamedUnit, 3> kTimes{{{"s", 1.0}, {"ms", 1e-3}, {"us", 1e-6}}};
constexpr std::array<NamedUnit, 4> kMasses{
    {{"kg", 1.0}, {"g", 1e-3}, {"mg", 1e-6}, {"tonne", 1e3}}};
constexpr std::array<NamedUnit, 5> kForces{
    {{"N", 1.0}, {"kN", 1e3}, {"MN", 1e6}, {"mN", 1e-3}, {"dyn", 1e-5}}};
constexpr std::array<NamedUnit, 5> kStresses{
    {{"Pa", 1.0}, {"kPa", 1e3}, {"MPa", 1e6}, {"GPa", 1e9}, {"Ba", 0.1}}};

template <std::size_t N>
std::string list_names(const std::array<NamedUnit, N>& units) {
  std::string text;
  for (const NamedUnit& u : units) {
    text += fmt::format("{}{}", text.empty() ? "" : ", ", u.name);
  }
  return text;
}

template <std::size_t N>
const NamedUnit& find_unit(std::string_view name, const std::array<NamedUnit, N>& units,
                           std::string_view quantity) {
  for (const NamedUnit& u : units) {
    if (u.name == name) {
      return u;
    }
  }
  throw std::invalid_argument(
      fmt::format("unknown {} unit \"{}\" (accepted: {})", quantity, name, list_names(units)));
}

bool same_size(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::abs(b);
}

/// The accepted name of a unit of this size, or its size in SI units when none has it.
template <std::size_t N>
std::string name_of_size(double si, const std::array<NamedUnit, N>& units,
                         std::string_view si_unit) {
  for (const NamedUnit& u : units) {
    if (same_size(u.si, si)) {
      return std::string(u.name);
    }
  }
  return fmt::format("{:g} {} (no accepted name)", si, si_unit);
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i == text.size() || text[i] == separator) {
      parts.push_back(text.substr(start, i - start));
      start = i + 1;
    }
  }
  return parts;
}

}  // namespace

UnitSystem parse_unit_system(std::string_view text) {
  if (text == "consistent") {
    // A benchmark's data in no named system (MacNeal-Harder's problems): symbols of dimension.
    return UnitSystem{"[L]", "[T]", "[M]", "[F]", "[F/L^2]"};
  }
  const std::vector<std::string_view> parts = split(text, '-');
  if (parts.size() != 5) {
    throw std::invalid_argument(
        fmt::format("expected five units LENGTH-TIME-MASS-FORCE-STRESS separated by '-' (e.g. "
                    "\"mm-s-tonne-N-MPa\" or \"m-s-kg-N-Pa\"), or \"consistent\", got {} part{}",
                    parts.size(), parts.size() == 1 ? "" : "s"));
  }
  const NamedUnit& length = find_unit(parts[0], kLengths, "length");
  const NamedUnit& time = find_unit(parts[1], kTimes, "time");
  const NamedUnit& mass = find_unit(parts[2], kMasses, "mass");
  const NamedUnit& force = find_unit(parts[3], kForces, "force");
  const NamedUnit& stress = find_unit(parts[4], kStresses, "stress");
  const double implied_force = mass.si * length.si / (time.si * time.si);
  if (!same_size(force.si, implied_force)) {
    throw std::invalid_argument(fmt::format(
        "inconsistent units: {} x {} / {}^2 is {}, not {} (force = mass x length / time^2)",
        mass.name, length.name, time.name, name_of_size(implied_force, kForces, "N"), force.name));
  }
  const double implied_stress = force.si / (length.si * length.si);
  if (!same_size(stress.si, implied_stress)) {
    throw std::invalid_argument(fmt::format(
        "inconsistent units: {} / {}^2 is {}, not {} (stress = force / length^2)", force.name,
        length.name, name_of_size(implied_stress, kStresses, "Pa"), stress.name));
  }
  return UnitSystem{std::string(length.name),
                    std::string(time.name),
                    std::string(mass.name),
                    std::string(force.name),
                    std::string(stress.name),
                    length.si,
                    time.si,
                    mass.si};
}

double UnitSystem::si_size(const Dimension& d) const {
  if (!named()) {
    return 0.0;
  }
  return std::pow(length_si, d.length) * std::pow(time_si, d.time) * std::pow(mass_si, d.mass);
}

const std::vector<UnitSystem>& accepted_unit_systems() {
  static const std::vector<UnitSystem> systems = [] {
    std::vector<UnitSystem> out;
    for (const NamedUnit& l : kLengths) {
      for (const NamedUnit& t : kTimes) {
        for (const NamedUnit& m : kMasses) {
          for (const NamedUnit& f : kForces) {
            for (const NamedUnit& s : kStresses) {
              try {
                out.push_back(parse_unit_system(
                    fmt::format("{}-{}-{}-{}-{}", l.name, t.name, m.name, f.name, s.name)));
              } catch (const std::invalid_argument&) {
                // not consistent: not a system a case can declare
              }
            }
          }
        }
      }
    }
    return out;
  }();
  return systems;
}

}  // namespace sf
