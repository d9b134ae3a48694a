#include "material/material_failure.hpp"

#include "core/errors.hpp"

namespace sf {

std::string MaterialFailure::message() const {
  const std::string name(law);
  switch (kind) {
    case Kind::none:
      return name + ": no failure";
    case Kind::non_finite_trial_stress:
      return name + ": non-finite trial stress";
    case Kind::return_not_converged:
      return name + ": return mapping did not converge (trial equivalent stress " +
             std::to_string(values[0]) + " MPa)";
    case Kind::general_return_not_converged:
      return name + ": the return mapping did not converge (trial stress " +
             std::to_string(values[0]) + ", " + std::to_string(values[1]) + ", " +
             std::to_string(values[2]) + " MPa; residual " + std::to_string(values[3]) + " MPa)";
  }
  return name;
}

void throw_if_failed(const MaterialFailure& failure) {
  if (failure.failed()) {
    throw InstabilityError(failure.message());
  }
}

}  // namespace sf
