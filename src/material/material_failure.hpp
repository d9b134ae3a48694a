#pragma once
// What stops a material update, returned as a code instead of thrown: the element loop records it
// as its element's failure (element/element_failure.hpp), and the single-point updates, outside
// the loop, throw it as an InstabilityError with the same text.
#include <array>
#include <string>

namespace sf {

struct MaterialFailure {
  enum class Kind {
    none,
    non_finite_trial_stress,
    /// the modal return (J2, Hill48) did not converge; values[0]: the trial equivalent stress
    return_not_converged,
    /// the general return (Barlat's criteria, kinematic hardening) did not converge; values: the
    /// trial stress (xx, yy, xy) and the last residual
    general_return_not_converged,
  };
  Kind kind = Kind::none;
  const char* law = "";            ///< the law's name, e.g. "J2 plane stress"
  std::array<double, 4> values{};  ///< MPa, see Kind

  bool failed() const { return kind != Kind::none; }
  /// The text, e.g. "J2 plane stress: non-finite trial stress".
  std::string message() const;
};

/// Throws InstabilityError(failure.message()) when failure.failed().
void throw_if_failed(const MaterialFailure& failure);

}  // namespace sf
