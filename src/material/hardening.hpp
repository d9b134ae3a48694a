#pragma once
// Isotropic hardening laws: flow stress (MPa) as a function of the equivalent plastic strain (-).
#include <cmath>
#include <filesystem>
#include <variant>
#include <vector>

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
  /// The same as evaluate(eps_p), from a known evaluation `at_ref` at eps_ref, without `pow` when
  /// the step is small: sigma_y(eps_p) = sigma_y(eps_ref) (1 + x)^n, x = (eps_p - eps_ref) /
  /// (eps0 + eps_ref), by its binomial series to x^5 for |x| <= 1e-2 (truncation below
  /// |C(n,6)| x^6 < 1e-13 relative for 0 <= n <= 1; a return-mapping step is far smaller).
  FlowStress evaluate_near(double eps_p, double eps_ref, const FlowStress& at_ref) const {
    const double x = near_ratio(eps_p, eps_ref);
    if (!(std::abs(x) <= kNearRange)) {
      return evaluate(eps_p);
    }
    const double s = near_stress(x, at_ref.stress);
    return {s, n * s / (eps0 + eps_p)};
  }
  /// The largest |x| of evaluate_near's series.
  static constexpr double kNearRange = 1e-2;
  /// x = (eps_p - eps_ref) / (eps0 + eps_ref) of evaluate_near. T: double, or a SIMD vector of
  /// doubles (the same operations lane by lane).
  template <class T>
  T near_ratio(const T& eps_p, const T& eps_ref) const {
    return (eps_p - eps_ref) / (eps0 + eps_ref);
  }
  /// sigma_y(eps_ref) (1 + x)^n by the series of evaluate_near (|x| <= kNearRange).
  template <class T>
  T near_stress(const T& x, const T& stress_ref) const {
    const double c1 = n;
    const double c2 = c1 * (n - 1.0) / 2.0;
    const double c3 = c2 * (n - 2.0) / 3.0;
    const double c4 = c3 * (n - 3.0) / 4.0;
    const double c5 = c4 * (n - 4.0) / 5.0;
    return stress_ref * (1.0 + x * (c1 + x * (c2 + x * (c3 + x * (c4 + x * c5)))));
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

/// Voce (1948) saturation hardening: sigma_y = sigma0 + Q (1 - exp(-b eps_p)), slope
/// Q b exp(-b eps_p). Needs sigma0 > 0, Q >= 0, b > 0.
struct VoceHardening {
  double sigma0 = 0.0;  ///< MPa, initial yield stress
  double Q = 0.0;       ///< MPa, saturation increase (sigma_y -> sigma0 + Q)
  double b = 0.0;       ///< -, saturation rate

  double flow_stress(double eps_p) const { return evaluate(eps_p).stress; }
  double slope(double eps_p) const { return evaluate(eps_p).slope; }
  /// Both at once (one exp).
  FlowStress evaluate(double eps_p) const;
};

/// Ludwik (1909) hardening, also written Hollomon with an offset: sigma_y = A + B eps_p^n. Needs
/// A > 0, B >= 0, 0 < n <= 1. For n < 1 the slope n B eps_p^(n-1) is infinite at eps_p = 0
/// (returned as +inf; the return mapping's bracketed Newton then bisects its first step).
struct LudwikHardening {
  double A = 0.0;  ///< MPa, initial yield stress
  double B = 0.0;  ///< MPa, hardening coefficient
  double n = 0.0;  ///< -, hardening exponent

  double flow_stress(double eps_p) const { return evaluate(eps_p).stress; }
  double slope(double eps_p) const { return evaluate(eps_p).slope; }
  /// Both at once (one pow).
  FlowStress evaluate(double eps_p) const;
};

/// Hockett & Sherby (1975) saturation hardening: sigma_y = sigma_s - (sigma_s - sigma_i)
/// exp(-N eps_p^p). Needs sigma_s >= sigma_i > 0, N > 0, 0 < p <= 1 (p = 1 is Voce's form with
/// sigma0 = sigma_i, Q = sigma_s - sigma_i, b = N; for p < 1 the slope is infinite at eps_p = 0,
/// returned as +inf like Ludwik's).
struct HockettSherbyHardening {
  double sigma_s = 0.0;  ///< MPa, saturation stress
  double sigma_i = 0.0;  ///< MPa, initial yield stress
  double N = 0.0;        ///< -, rate
  double p = 1.0;        ///< -, exponent of eps_p

  double flow_stress(double eps_p) const { return evaluate(eps_p).stress; }
  double slope(double eps_p) const { return evaluate(eps_p).slope; }
  /// Both at once.
  FlowStress evaluate(double eps_p) const;
};

/// Swift-Voce combined hardening: sigma_y = w Swift(eps_p) + (1 - w) Voce(eps_p), 0 <= w <= 1
/// (the weight is the Swift part's; the Swift law keeps hardening where Voce saturates).
struct SwiftVoceHardening {
  double weight = 0.5;  ///< -, the Swift part's weight w
  SwiftHardening swift;
  VoceHardening voce;

  double flow_stress(double eps_p) const { return evaluate(eps_p).stress; }
  double slope(double eps_p) const { return evaluate(eps_p).slope; }
  /// Both at once.
  FlowStress evaluate(double eps_p) const {
    const FlowStress a = swift.evaluate(eps_p);
    const FlowStress b = voce.evaluate(eps_p);
    return {weight * a.stress + (1.0 - weight) * b.stress,
            weight * a.slope + (1.0 - weight) * b.slope};
  }
};

/// Tabulated hardening: points (eps_p[i], stress[i]) of true stress (MPa) against equivalent
/// plastic strain (-), interpolated linearly and extrapolated beyond the last point with the last
/// segment's slope (a single point: perfect plasticity). Valid tables (check_hardening): at least
/// one point, eps_p[0] = 0, eps_p strictly increasing, stress > 0 and non-decreasing, all finite.
/// At a breakpoint the slope is the one of the segment to its right.
struct TabulatedHardening {
  std::vector<double> eps_p;   ///< -, equivalent plastic strain of each point
  std::vector<double> stress;  ///< MPa, true flow stress of each point

  double flow_stress(double e) const { return evaluate(e).stress; }
  double slope(double e) const { return evaluate(e).slope; }
  /// Both at once (binary search, no allocation).
  FlowStress evaluate(double e) const;
};

/// A hardening law, chosen once per material.
using Hardening = std::variant<SwiftHardening, LinearHardening, VoceHardening, LudwikHardening,
                               TabulatedHardening, HockettSherbyHardening, SwiftVoceHardening>;

/// Flow stress (MPa) of any hardening law at eps_p (-).
double flow_stress(const Hardening& hardening, double eps_p);
/// Hardening slope d sigma_y / d eps_p (MPa) of any hardening law at eps_p (-).
double hardening_slope(const Hardening& hardening, double eps_p);
/// Flow stress and slope of any hardening law at eps_p (-).
inline FlowStress evaluate_hardening(const Hardening& hardening, double eps_p) {
  return std::visit([eps_p](const auto& h) { return h.evaluate(eps_p); }, hardening);
}
/// Throws InputError (naming `what`, and the row of a table, 1-based) unless the parameters are
/// physically admissible.
void check_hardening(const Hardening& hardening, const char* what);

/// Reads a hardening table: two columns per line, equivalent plastic strain (-) and true stress
/// (MPa), separated by a comma, semicolon or white space; '#' starts a comment; one header line
/// (the first non-comment line, if it is not numeric) is allowed. Throws InputError naming the
/// file and line for an unreadable file, a bad row, or a table check_hardening would reject.
TabulatedHardening read_hardening_csv(const std::filesystem::path& path);

}  // namespace sf
