#include "material/hardening.hpp"

#include <cmath>
#include <string>

#include "core/errors.hpp"

namespace sf {

double SwiftHardening::flow_stress(double eps_p) const {
  return K * std::pow(eps0 + eps_p, n);
}

double SwiftHardening::slope(double eps_p) const {
  return n == 0.0 ? 0.0 : n * K * std::pow(eps0 + eps_p, n - 1.0);
}

double flow_stress(const Hardening& hardening, double eps_p) {
  return std::visit([eps_p](const auto& h) { return h.flow_stress(eps_p); }, hardening);
}

double hardening_slope(const Hardening& hardening, double eps_p) {
  return std::visit([eps_p](const auto& h) { return h.slope(eps_p); }, hardening);
}

void check_hardening(const Hardening& hardening, const char* what) {
  const std::string name(what);
  if (const auto* s = std::get_if<SwiftHardening>(&hardening)) {
    if (!(s->K > 0.0) || !(s->eps0 > 0.0) || !(s->n >= 0.0) || !std::isfinite(s->K) ||
        !std::isfinite(s->eps0) || !std::isfinite(s->n)) {
      throw InputError(name + ": Swift hardening needs K > 0, eps0 > 0 and n >= 0 (got K = " +
                       std::to_string(s->K) + ", eps0 = " + std::to_string(s->eps0) +
                       ", n = " + std::to_string(s->n) + ")");
    }
  } else {
    const auto& l = std::get<LinearHardening>(hardening);
    if (!(l.sigma_y0 > 0.0) || !(l.H >= 0.0) || !std::isfinite(l.sigma_y0) || !std::isfinite(l.H)) {
      throw InputError(name + ": linear hardening needs yield stress > 0 and modulus >= 0 (got " +
                       std::to_string(l.sigma_y0) + ", " + std::to_string(l.H) + ")");
    }
  }
}

}  // namespace sf
