#include "contact/round_drawbead.hpp"

#include <fmt/core.h>

#include <cmath>

#include "core/errors.hpp"

namespace sf {
namespace {

void require_positive(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(fmt::format("round drawbead: {} must be a number > 0 (got {})", what, value));
  }
}

void require_not_negative(double value, const char* what) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw InputError(fmt::format("round drawbead: {} must be a number >= 0 (got {})", what, value));
  }
}

}  // namespace

double round_bead_wrap_angle(const RoundBeadGeometry& bead, double thickness) {
  const double R = bead.shoulder_radius + bead.bead_radius + thickness;
  const double a = R + bead.clearance;
  const double b = R - bead.depth;
  // a sin(theta) + b cos(theta) = D sin(theta + psi), D = |(a, b)| >= a >= R: one root in
  // [0, pi/2] (theta = 0 at depth 0).
  const double D = std::hypot(a, b);
  const double theta = std::asin(std::min(1.0, R / D)) - std::atan2(b, a);
  return std::max(0.0, theta);
}

double round_bead_bend_moment(const RoundBeadSheet& sheet, double rho_s, double rho_b, int k) {
  const double rho[6] = {rho_s, rho_s, rho_b, rho_b, rho_s, rho_s};
  double curvature = 0.5 / rho[k];  // 1/mm: half of this bend's
  for (int j = 0; j < k; ++j) {
    curvature += 1.0 / rho[j];
  }
  const double to_equivalent = 2.0 / std::sqrt(3.0);  // plane strain, von Mises
  const int n = 64;
  const double half = 0.5 * sheet.thickness;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double z = half * i / n;
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    sum += w * to_equivalent * sheet.flow_stress(to_equivalent * z * curvature) * z;
  }
  return 2.0 * sum * (half / n) / 3.0;
}

RoundBeadForces round_bead_forces(const RoundBeadGeometry& bead, const RoundBeadSheet& sheet) {
  require_positive(bead.bead_radius, "bead_radius (mm)");
  require_positive(bead.shoulder_radius, "shoulder_radius (mm)");
  require_not_negative(bead.depth, "depth (mm)");
  require_not_negative(bead.clearance, "clearance (mm)");
  require_positive(sheet.thickness, "the sheet's thickness (mm)");
  if (!sheet.flow_stress) {
    throw InputError("round drawbead: the sheet's flow stress is not given");
  }
  require_positive(sheet.flow_stress(0.0), "the sheet's flow stress (MPa)");
  require_not_negative(sheet.friction, "friction");
  RoundBeadForces out;
  out.wrap_angle = round_bead_wrap_angle(bead, sheet.thickness);
  if (!(out.wrap_angle > 0.0)) {
    return out;
  }
  const double rho_s = bead.shoulder_radius + 0.5 * sheet.thickness;  // mm
  const double rho_b = bead.bead_radius + 0.5 * sheet.thickness;
  double dT[6];  // N/mm
  for (int k = 0; k < 6; ++k) {
    dT[k] = round_bead_bend_moment(sheet, rho_s, rho_b, k) / (k < 2 || k > 3 ? rho_s : rho_b);
  }
  const double f = std::exp(sheet.friction * out.wrap_angle);
  const double t1 = dT[0] * f + dT[1];
  const double t2 = (t1 + dT[2]) * f * f + dT[3];
  out.restraining = (t2 + dT[4]) * f + dT[5];
  out.uplift = (t1 + t2) * std::sin(out.wrap_angle);
  return out;
}

}  // namespace sf
