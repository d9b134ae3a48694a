#include "model/forming_limit.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace sf {

double FormingLimitCurve::major_at(double minor) const {
  if (minor <= points.front()[0]) {
    return points.front()[1];
  }
  if (minor >= points.back()[0]) {
    return points.back()[1];
  }
  const auto above = std::upper_bound(points.begin(), points.end(), minor,
                                      [](double x, const auto& p) { return x < p[0]; });
  const auto& b = *above;
  const auto& a = *(above - 1);
  const double s = (minor - a[0]) / (b[0] - a[0]);
  return a[1] + s * (b[1] - a[1]);
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
