// The formability judgement (model/formability.hpp, model/forming_limit.hpp): the forming limit
// curve's interpolation, the Keeler-Brazier curve against its published formula, the margin's
// sign, each zone of the forming limit diagram and their precedence, and each part's curve from
// the case.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "model/formability.hpp"

namespace sf {
namespace {

TEST(FormingLimitCurve, InterpolatesLinearlyAndHoldsItsEnds) {
  FormingLimitCurve curve;
  curve.points = {{-0.4, 0.6}, {0.0, 0.25}, {0.3, 0.4}};
  EXPECT_DOUBLE_EQ(curve.major_at(-0.2), 0.425);
  EXPECT_DOUBLE_EQ(curve.major_at(0.0), 0.25);
  EXPECT_DOUBLE_EQ(curve.major_at(0.15), 0.325);
  EXPECT_DOUBLE_EQ(curve.major_at(-1.0), 0.6);  // held beyond the first point
  EXPECT_DOUBLE_EQ(curve.major_at(0.9), 0.4);   // and beyond the last
}

TEST(FormingLimitCurve, KeelerBrazierPlaneStrainPointIsThePublishedFormula) {
  // Keeler & Brazier (1977) in inches: FLC0 = (23.3 + 359 t) n / 0.21 per cent (engineering);
  // 14.13 per mm is 359 per inch rounded, so the two agree to 359 - 14.13 x 25.4 = 0.098 per
  // inch of thickness.
  for (double t_inch : {0.02, 0.04, 0.08}) {
    for (double n : {0.15, 0.21, 0.25}) {
      EXPECT_NEAR(keeler_brazier_flc0_percent(n, 25.4 * t_inch), (23.3 + 359.0 * t_inch) * n / 0.21,
                  0.0981 * t_inch * n / 0.21)
          << "t " << t_inch << " in, n " << n;
    }
  }
  // As a true strain: the curve's lowest point is at plane strain, ln(1 + FLC0 / 100).
  const double flc0 = std::log1p((23.3 + 14.13 * 1.0) * 0.2 / 0.21 / 100.0);
  const FormingLimitCurve curve = keeler_brazier_curve(0.2, 1.0);
  EXPECT_NEAR(curve.major_at(0.0), flc0, 1e-15);
  // Left: major + minor = FLC0 (Hill's localised neck); right: held at FLC0.
  for (double minor : {-0.05, -0.2, -0.45}) {
    EXPECT_NEAR(curve.major_at(minor) + minor, flc0, 1e-15) << minor;
  }
  for (double minor : {0.05, 0.3, 0.6}) {
    EXPECT_DOUBLE_EQ(curve.major_at(minor), flc0) << minor;
  }
}

TEST(Formability, MarginIsPositiveBelowTheCurveAndNaNWithoutOne) {
  FormingLimitCurve curve;
  curve.points = {{-0.4, 0.6}, {0.0, 0.25}, {0.3, 0.4}};
  EXPECT_DOUBLE_EQ(flc_margin(curve, 0.2, 0.0), 0.05);
  EXPECT_DOUBLE_EQ(flc_margin(curve, 0.5, -0.2), 0.425 - 0.5);
  EXPECT_TRUE(std::isnan(flc_margin(FormingLimitCurve{}, 0.2, 0.0)));
}

TEST(Formability, EachZoneAndTheGraverWins) {
  const FormabilityConfig th;  // defaults: margin 0.1, stretch 0.02, thickening 0.01, 30 %
  const double none = std::numeric_limits<double>::quiet_NaN();
  using Z = FormabilityZone;
  EXPECT_EQ(formability_zone(0.10, 0.02, 0.15, 10.0, th), Z::safe);
  EXPECT_EQ(formability_zone(0.01, 0.005, 0.30, 1.0, th), Z::insufficient_stretching);
  EXPECT_EQ(formability_zone(0.05, -0.08, 0.40, -3.0, th), Z::wrinkling_tendency);
  EXPECT_EQ(formability_zone(0.20, 0.0, 0.05, 15.0, th), Z::risk_of_cracks);
  EXPECT_EQ(formability_zone(0.25, 0.1, 0.12, 31.0, th), Z::severe_thinning);
  EXPECT_EQ(formability_zone(0.40, 0.1, -0.01, 35.0, th), Z::cracks);
  // Precedence: cracks over severe thinning, severe thinning over risk, risk over wrinkling.
  EXPECT_EQ(formability_zone(0.40, 0.0, -0.01, 50.0, th), Z::cracks);
  EXPECT_EQ(formability_zone(0.30, 0.0, 0.05, 30.0, th), Z::severe_thinning);
  EXPECT_EQ(formability_zone(0.30, -0.35, 0.05, 0.0, th), Z::risk_of_cracks);
  // The thresholds' edges: margin exactly 0 is at risk, not cracked; thickening exactly at the
  // threshold is not yet wrinkling.
  EXPECT_EQ(formability_zone(0.2, 0.0, 0.0, 0.0, th), Z::risk_of_cracks);
  FormabilityConfig binary = th;  // thresholds that binary fractions hit exactly
  binary.wrinkle_thickening = 0.25;
  EXPECT_EQ(formability_zone(0.25, -0.5, 0.5, 0.0, binary), Z::safe);
  EXPECT_EQ(formability_zone(0.25, -0.5 - 1e-12, 0.5, 0.0, binary), Z::wrinkling_tendency);
  // Without a curve no element cracks or is at risk; thinning and wrinkles still show.
  EXPECT_EQ(formability_zone(0.9, 0.0, none, 10.0, th), Z::safe);
  EXPECT_EQ(formability_zone(0.9, 0.0, none, 40.0, th), Z::severe_thinning);
  // The thresholds are the case's.
  FormabilityConfig strict = th;
  strict.safety_margin = 0.2;
  EXPECT_EQ(formability_zone(0.10, 0.02, 0.15, 10.0, strict), Z::risk_of_cracks);
  EXPECT_EQ(zone_name(Z::risk_of_cracks), "risk of cracks");
}

TEST(Formability, EachPartTakesItsMaterialsCurve) {
  CaseConfig config;
  MaterialConfig steel;
  steel.name = "steel";
  steel.hardening.law = HardeningConfig::Law::swift;
  steel.hardening.swift_n = 0.22;
  MaterialConfig measured = steel;
  measured.name = "measured";
  measured.forming_limit_curve = {{-0.3, 0.5}, {0.0, 0.2}, {0.3, 0.35}};
  MaterialConfig voce = steel;
  voce.name = "voce";
  voce.hardening.law = HardeningConfig::Law::voce;
  config.materials = {steel, measured, voce};
  config.blank.parts = {{.name = "a", .group = "a", .thickness = 0.8, .material = "steel"},
                        {.name = "b", .group = "b", .thickness = 1.5, .material = "measured"},
                        {.name = "c", .group = "c", .thickness = 1.0, .material = "voce"}};
  config.formability.safety_margin = 0.05;
  const FormabilityPlan plan = make_formability_plan(config);
  ASSERT_EQ(plan.part_curves.size(), 3u);
  EXPECT_NEAR(plan.part_curves[0].major_at(0.0),
              std::log1p(keeler_brazier_flc0_percent(0.22, 0.8) / 100.0), 1e-15);
  EXPECT_NE(plan.part_curves[0].source.find("Keeler-Brazier"), std::string::npos);
  EXPECT_EQ(plan.part_curves[1].points, measured.forming_limit_curve);
  EXPECT_TRUE(plan.part_curves[2].empty());  // Voce has no n, the case no curve
  EXPECT_DOUBLE_EQ(plan.thresholds.safety_margin, 0.05);
}

}  // namespace
}  // namespace sf
