#include "contact/coulomb_friction.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "core/piecewise_linear.hpp"

namespace sf {

double FrictionTable::operator()(double at) const {
  return piecewise_linear(x, y, at);
}

void FrictionTable::validate(std::string_view tool, std::string_view name) const {
  if (x.size() != y.size() || x.size() < 2) {
    throw InputError(
        fmt::format("contact with tool '{}': friction {} table: needs at least 2 points (got {} "
                    "abscissae, {} values)",
                    tool, name, x.size(), y.size()));
  }
  for (std::size_t k = 0; k < x.size(); ++k) {
    const bool increasing = k == 0 || x[k] > x[k - 1];
    if (!std::isfinite(x[k]) || !std::isfinite(y[k]) || x[k] < 0 || y[k] < 0 || !increasing) {
      throw InputError(
          fmt::format("contact with tool '{}': friction {} table: point {} ({}, {}) must be "
                      "finite and >= 0, its abscissa above the one before",
                      tool, name, k, x[k], y[k]));
    }
  }
}

double FrictionParameters::coefficient(double slip_speed) const {
  return dynamic_coefficient +
         (static_coefficient - dynamic_coefficient) * std::exp(-decay * std::abs(slip_speed));
}

namespace {

// The table's value at `at`, flagging in *beyond the end `at` lies beyond.
double table_value(const FrictionTable& table, double at, TableEnd below, TableEnd above,
                   unsigned* beyond) {
  if (beyond) {
    if (at < table.x.front()) {
      *beyond |= 1u << static_cast<unsigned>(below);
    } else if (at > table.x.back()) {
      *beyond |= 1u << static_cast<unsigned>(above);
    }
  }
  return table(at);
}

}  // namespace

double FrictionParameters::coefficient(double pressure, double slip_speed, unsigned* beyond) const {
  const double speed = std::abs(slip_speed);
  double mu = 0.0;
  if (pressure_table.empty()) {
    mu = coefficient(speed);
    if (pressure_exponent != 1.0) {
      mu *= std::pow(pressure / reference_pressure, pressure_exponent - 1.0);
    }
  } else {
    mu = table_value(pressure_table, pressure, TableEnd::pressure_below, TableEnd::pressure_above,
                     beyond);
  }
  if (!speed_table.empty()) {
    mu *= table_value(speed_table, speed, TableEnd::speed_below, TableEnd::speed_above, beyond);
  }
  return mu;
}

double FrictionParameters::direction_factor(const Vec3& normal, const Vec3& t) const {
  const Vec3 along = rolling_direction - normal.dot(rolling_direction) * normal;
  const double length = along.norm();
  if (!(length >= 1e-6)) {
    return 0.5 * (1.0 + across_ratio);
  }
  const double c = along.dot(t) / length;
  const double c2 = std::min(c * c, 1.0);
  return 1.0 / std::sqrt(c2 + (1.0 - c2) / (across_ratio * across_ratio));
}

void FrictionParameters::validate(std::string_view tool) const {
  const bool ok = std::isfinite(static_coefficient) && std::isfinite(dynamic_coefficient) &&
                  std::isfinite(decay) && dynamic_coefficient >= 0 &&
                  dynamic_coefficient <= static_coefficient && decay >= 0 &&
                  tangential_stiffness_ratio > 0 && tangential_stiffness_ratio <= 1;
  if (!ok) {
    throw InputError(fmt::format(
        "contact with tool '{}': friction needs 0 <= dynamic <= static coefficient, decay >= 0 "
        "s/mm and a tangential "
        "stiffness ratio in (0, 1] (got static {}, dynamic {}, decay {} s/mm, ratio {})",
        tool, static_coefficient, dynamic_coefficient, decay, tangential_stiffness_ratio));
  }
  const bool power_ok =
      std::isfinite(pressure_exponent) && pressure_exponent > 0 &&
      (pressure_exponent == 1.0 || (std::isfinite(reference_pressure) && reference_pressure > 0));
  if (!power_ok) {
    throw InputError(fmt::format(
        "contact with tool '{}': the friction power law needs an exponent n > 0 and, when n != 1, "
        "a reference pressure p0 > 0 MPa (got n = {}, p0 = {} MPa)",
        tool, pressure_exponent, reference_pressure));
  }
  if (!pressure_table.empty()) {
    pressure_table.validate(tool, "pressure");
    if (static_coefficient != 0 || dynamic_coefficient != 0 || decay != 0 ||
        pressure_exponent != 1.0) {
      throw InputError(fmt::format(
          "contact with tool '{}': a friction pressure table gives the coefficient itself: the "
          "Coulomb coefficients, decay and power law must not be given with it",
          tool));
    }
  }
  if (!speed_table.empty()) {
    speed_table.validate(tool, "speed");
  }
  if (!(std::isfinite(across_ratio) && across_ratio > 0) ||
      !(std::abs(rolling_direction.norm() - 1.0) < 1e-12)) {
    throw InputError(fmt::format(
        "contact with tool '{}': orthotropic friction needs a ratio across / along > 0 and a unit "
        "rolling direction (got {} and length {})",
        tool, across_ratio, rolling_direction.norm()));
  }
}

std::string friction_table_warning(const FrictionParameters& law, TableEnd end,
                                   std::string_view where, double time, long cycle) {
  const bool pressure = end == TableEnd::pressure_below || end == TableEnd::pressure_above;
  const bool below = end == TableEnd::pressure_below || end == TableEnd::speed_below;
  const FrictionTable& table = pressure ? law.pressure_table : law.speed_table;
  const double at = below ? table.x.front() : table.x.back();
  const double held = below ? table.y.front() : table.y.back();
  return fmt::format(
      "{}: friction_{}_table: a contact node met a {} {} its {} point ({} {}) at t = {:.6e} s, "
      "cycle {}; beyond it the table's end value {} = {} is held constant (said once a run)\n",
      where, pressure ? "pressure" : "speed", pressure ? "pressure" : "slip speed",
      below ? "below" : "above", below ? "first" : "last", at, pressure ? "MPa" : "mm/s", time,
      cycle, pressure ? "mu" : "factor", held);
}

FrictionStep coulomb_friction_update(const FrictionParameters& law, Vec3& stored_force,
                                     const Vec3& normal, const Vec3& increment, double dt,
                                     double normal_force, double k_t, double pressure) {
  FrictionStep out;
  // 1. The stored force rotated into the current tangent plane (same length).
  const double stored_length = stored_force.norm();
  Vec3 rotated = stored_force - normal.dot(stored_force) * normal;
  const double projected_length = rotated.norm();
  if (projected_length > 1e-12 * stored_length) {
    rotated *= stored_length / projected_length;
  } else {
    rotated.setZero();  // the normal turned by 90 degrees: no tangential memory left
  }
  // 2. Elastic trial.
  const Vec3 du_t = increment - normal.dot(increment) * normal;
  const Vec3 trial = rotated - k_t * du_t;
  // 3. Return mapping onto the limit: along the trial force (radial return).
  const double slip_speed = dt > 0 ? du_t.norm() / dt : 0.0;
  const double trial_length = trial.norm();
  double limit = 0.0;
  if (normal_force > 0) {
    limit = law.coefficient(pressure, slip_speed, &out.beyond) * normal_force;
    if (law.across_ratio != 1.0 && trial_length > 0) {
      limit *= law.direction_factor(normal, trial / trial_length);
    }
  }
  if (trial_length <= limit) {
    out.force = trial;
  } else {
    out.sliding = true;
    out.force = trial_length > 0 ? Vec3((limit / trial_length) * trial) : Vec3::Zero();
    out.slip = (trial_length - limit) / k_t;
    out.work = limit * out.slip;
  }
  stored_force = out.force;
  return out;
}

}  // namespace sf
