#include "contact/coulomb_friction.hpp"

#include <fmt/core.h>

#include <cmath>

#include "core/errors.hpp"

namespace sf {

double FrictionParameters::coefficient(double slip_speed) const {
  return dynamic_coefficient +
         (static_coefficient - dynamic_coefficient) * std::exp(-decay * std::abs(slip_speed));
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
}

FrictionStep coulomb_friction_update(const FrictionParameters& law, Vec3& stored_force,
                                     const Vec3& normal, const Vec3& increment, double dt,
                                     double normal_force, double k_t) {
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
  // 3. Return mapping onto the Coulomb limit.
  const double slip_speed = dt > 0 ? du_t.norm() / dt : 0.0;
  const double limit = law.coefficient(slip_speed) * normal_force;
  const double trial_length = trial.norm();
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
