#pragma once
// The forming limit curve (FLC) of a sheet: the major true strain at the onset of localised
// necking against the minor true strain, for proportional strain paths (docs/formability.md).
// Given as points in the case, or estimated from the hardening exponent and the thickness by
// the Keeler-Brazier formula for the plane-strain point FLC0.
#include <array>
#include <string>
#include <vector>

namespace sf {

/// A forming limit curve: (minor, major) true-strain points, minor strictly increasing; linear
/// between the points and held at the end points' major strain beyond them.
struct FormingLimitCurve {
  std::vector<std::array<double, 2>> points;  ///< (minor, major), true strains, -
  std::string source;  ///< where it comes from, for the banner ("the case", "Keeler-Brazier ...")

  bool empty() const { return points.empty(); }
  /// The curve's major true strain at this minor true strain (-).
  double major_at(double minor) const;
};

/// FLC0, the Keeler-Brazier plane-strain forming limit of a low-carbon steel sheet as an
/// engineering major strain in per cent: (23.3 + 14.13 t) n / 0.21, t the thickness in mm and n
/// the hardening exponent (Keeler & Brazier 1977, as quoted by the forming codes' manuals: the
/// original gives 23.3 + 359 t with t in inches; 359 x 0.03937 = 14.13).
double keeler_brazier_flc0_percent(double n, double thickness_mm);

/// The Keeler-Brazier curve in true strains: FLC0 = ln(1 + flc0 / 100) at plane strain; on the
/// left (minor < 0) the line major + minor = FLC0, the shape of Hill's (1952) localised neck
/// along a direction of zero extension (through FLC0 instead of through n); on the right held
/// at FLC0, which is conservative (measured curves of steels rise on the right).
FormingLimitCurve keeler_brazier_curve(double n, double thickness_mm);

}  // namespace sf
