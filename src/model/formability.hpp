#pragma once
// The formability a die engineer reads after a run (docs/formability.md): each element's zone
// of the forming limit diagram from its major and minor true strains, its margin to the forming
// limit curve and its thinning, judged by the case's [formability] thresholds.
#include <string_view>
#include <vector>

#include "casefile/case_config.hpp"
#include "model/forming_limit.hpp"

namespace sf {

/// The zones, numbered so that a larger number is the graver finding (each element gets the
/// gravest that applies): the `formability_zone` result field.
enum class FormabilityZone : int {
  safe = 0,
  insufficient_stretching = 1,  ///< major < insufficient_stretch
  wrinkling_tendency = 2,       ///< -(major + minor) > wrinkle_thickening
  risk_of_cracks = 3,           ///< 0 <= margin < safety_margin
  severe_thinning = 4,          ///< thinning >= severe_thinning per cent
  cracks = 5,                   ///< margin < 0: above the FLC
};
inline constexpr int kFormabilityZoneCount = 6;

/// "cracks", "risk of cracks", ...
std::string_view zone_name(FormabilityZone zone);

/// What judges the blank's formability: the thresholds and each blank part's FLC (empty for a
/// part whose material has neither a curve nor a Swift exponent: no margin, no crack zones).
struct FormabilityPlan {
  FormabilityConfig thresholds;
  std::vector<FormingLimitCurve> part_curves;  ///< per blank part, in the blank's order
};

/// The margin of a strain state to a curve: the curve's major strain at `minor` minus `major`
/// (true strains, -): > 0 below the curve (the safe side), < 0 above it. NaN without a curve.
double flc_margin(const FormingLimitCurve& curve, double major, double minor);

/// The zone of an element with these true strains (-), margin (-, NaN: no curve) and thinning
/// (per cent of the initial thickness).
FormabilityZone formability_zone(double major, double minor, double margin, double thinning_percent,
                                 const FormabilityConfig& thresholds);

/// The plan of a case: each blank part's curve from its material's forming_limit_curve, else the
/// Keeler-Brazier curve when the material hardens by the Swift law (n > 0) at the part's
/// thickness, else none.
FormabilityPlan make_formability_plan(const CaseConfig& config);

}  // namespace sf
