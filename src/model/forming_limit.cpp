#include "model/forming_limit.hpp"

#include <fmt/core.h>

#include <cmath>

#include "core/piecewise_linear.hpp"

namespace sf {

double FormingLimitCurve::major_at(double minor) const {
  return piecewise_linear(points, minor);
}

double keeler_brazier_flc0_percent(double n, double thickness_mm) {
  return (23.3 + 14.13 * thickness_mm) * n / 0.21;
}

FormingLimitCurve keeler_brazier_curve(double n, double thickness_mm) {
  const double flc0 = std::log1p(keeler_brazier_flc0_percent(n, thickness_mm) / 100.0);
  FormingLimitCurve curve;
  // The left line major + minor = FLC0 down to minor = -1 (beyond any sheet's strain), the
  // right side flat.
  curve.points = {{-1.0, flc0 + 1.0}, {0.0, flc0}, {1.0, flc0}};
  curve.source = fmt::format(
      "Keeler-Brazier from n = {:.4g} and t = {:.4g} mm: FLC0 = {:.4g} (true strain; left "
      "major + minor = FLC0, right held at FLC0)",
      n, thickness_mm, flc0);
  return curve;
}

}  // namespace sf
