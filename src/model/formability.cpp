#include "model/formability.hpp"

#include <cmath>
#include <limits>

namespace sf {

std::string_view zone_name(FormabilityZone zone) {
  switch (zone) {
    case FormabilityZone::safe:
      return "safe";
    case FormabilityZone::insufficient_stretching:
      return "insufficient stretching";
    case FormabilityZone::wrinkling_tendency:
      return "wrinkling tendency";
    case FormabilityZone::risk_of_cracks:
      return "risk of cracks";
    case FormabilityZone::severe_thinning:
      return "severe thinning";
    case FormabilityZone::cracks:
      return "cracks";
  }
  return "unknown";
}

double flc_margin(const FormingLimitCurve& curve, double major, double minor) {
  if (curve.empty()) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return curve.major_at(minor) - major;
}

FormabilityZone formability_zone(double major, double minor, double margin, double thinning_percent,
                                 const FormabilityConfig& thresholds) {
  const bool has_curve = !std::isnan(margin);
  if (has_curve && margin < 0.0) {
    return FormabilityZone::cracks;
  }
  if (thinning_percent >= thresholds.severe_thinning) {
    return FormabilityZone::severe_thinning;
  }
  if (has_curve && margin < thresholds.safety_margin) {
    return FormabilityZone::risk_of_cracks;
  }
  if (-(major + minor) > thresholds.wrinkle_thickening) {
    return FormabilityZone::wrinkling_tendency;
  }
  if (major < thresholds.insufficient_stretch) {
    return FormabilityZone::insufficient_stretching;
  }
  return FormabilityZone::safe;
}

FormabilityPlan make_formability_plan(const CaseConfig& config) {
  FormabilityPlan plan;
  plan.thresholds = config.formability;
  for (const BlankPartConfig& part : config.blank_parts()) {
    const MaterialConfig& material = config.material_named(part.material);
    FormingLimitCurve curve;
    if (!material.forming_limit_curve.empty()) {
      curve.points = material.forming_limit_curve;
      curve.source = "the case (materials." + material.name + ".forming_limit_curve)";
    } else if (material.hardening.law == HardeningConfig::Law::swift &&
               material.hardening.swift_n > 0.0) {
      curve = keeler_brazier_curve(material.hardening.swift_n, part.thickness);
    }
    plan.part_curves.push_back(std::move(curve));
  }
  return plan;
}

}  // namespace sf
