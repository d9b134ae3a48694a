#pragma once
// Isotropic hardening laws: flow stress as a function of the equivalent plastic strain.
#include <variant>

namespace sf {

/// Flow stress and its slope at one plastic strain.
struct FlowStress {
  double stress;  ///< MPa
  double slope;   ///< d stress / d eps_p, MPa
};

/// Swift (1952) hardening: sigma_y = K (eps0 + eps_p)^n. Needs K > 0, eps0 > 0, n >= 0 (eps0 > 0
/// keeps the initial yield stress K eps0^n and the slope finite).
struct SwiftHardening {
  double K = 0.0;     ///< MPa
  double eps0 = 0.0;  ///< -
  double n = 0.0;     ///< -

  /// Flow stress (MPa) at equivalent plastic strain eps_p (-).
  double flow_stress(double eps_p) const;
  /// d flow_stress / d eps_p (MPa).
  double slope(double eps_p) const;
  /// Both at once (one pow): slope = n sigma_y / (eps0 + eps_p).
  FlowStress evaluate(double eps_p) const {
    const double s = flow_stress(eps_p);
    return {s, n * s / (eps0 + eps_p)};
  }
};

/// Linear hardening: sigma_y = sigma_y0 + H eps_p (H = 0: perfect plasticity).
struct LinearHardening {
  double sigma_y0 = 0.0;  ///< MPa, initial yield stress
  double H = 0.0;         ///< MPa, plastic hardening modulus

  double flow_stress(double eps_p) const { return sigma_y0 + H * eps_p; }
  double slope(double /*eps_p*/) const { return H; }
  FlowStress evaluate(double eps_p) const { return {flow_stress(eps_p), H}; }
};

/// A hardening law, chosen once per material.
using Hardening = std::variant<SwiftHardening, LinearHardening>;

/// Flow stress (MPa) of any hardening law at eps_p (-).
double flow_stress(const Hardening& hardening, double eps_p);
/// Hardening slope d sigma_y / d eps_p (MPa) of any hardening law at eps_p (-).
double hardening_slope(const Hardening& hardening, double eps_p);
/// Flow stress and slope of any hardening law at eps_p (-).
inline FlowStress evaluate_hardening(const Hardening& hardening, double eps_p) {
  return std::visit([eps_p](const auto& h) { return h.evaluate(eps_p); }, hardening);
}
/// Throws InputError (naming `what`) unless the parameters are physically admissible.
void check_hardening(const Hardening& hardening, const char* what);

}  // namespace sf
