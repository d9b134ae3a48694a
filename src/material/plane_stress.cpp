#include "material/plane_stress.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "core/errors.hpp"

namespace sf {

Mat3 plane_stress_stiffness(double E, double nu) {
  const double f = E / (1.0 - nu * nu);
  Mat3 c;
  c << f, f * nu, 0.0, f * nu, f, 0.0, 0.0, 0.0, 0.5 * f * (1.0 - nu);
  return c;
}

double von_mises_plane_stress(const Vec3& s) {
  return std::sqrt(s(0) * s(0) - s(0) * s(1) + s(1) * s(1) + 3.0 * s(2) * s(2));
}

double plane_stress_wave_speed(double E, double nu, double rho) {
  return std::sqrt(E / (rho * (1.0 - nu * nu)));
}

namespace {

// Through-thickness strain increment from plane stress and plastic incompressibility:
// d_ezz = d_ezz^e + d_ezz^p with d_ezz^e = -nu/E d(sxx + syy) and d_ezz^p = -(d_exx^p + d_eyy^p),
// d_exx^p + d_eyy^p = d_exx + d_eyy - (1 - nu)/E d(sxx + syy); hence
// d_ezz = -(d_exx + d_eyy) + (1 - 2 nu)/E d(sxx + syy). Exact for the elastic step too.
double through_thickness_increment(double E, double nu, const Vec3& d_strain, const Vec3& s_old,
                                   const Vec3& s_new) {
  const double d_trace = (s_new(0) + s_new(1)) - (s_old(0) + s_old(1));
  return -(d_strain(0) + d_strain(1)) + (1.0 - 2.0 * nu) / E * d_trace;
}

}  // namespace

PlaneStressUpdate ElasticPlaneStress::update(const State& old, const Vec3& d_strain) const {
  const double f = E / (1.0 - nu * nu);
  Vec3 s = old.stress;
  s(0) += f * (d_strain(0) + nu * d_strain(1));
  s(1) += f * (nu * d_strain(0) + d_strain(1));
  s(2) += 0.5 * f * (1.0 - nu) * d_strain(2);
  return {s, old.eps_p, through_thickness_increment(E, nu, d_strain, old.stress, s), false};
}

PlaneStressUpdate J2PlaneStress::update(const State& old, const Vec3& d_strain) const {
  // Elastic predictor.
  const double f = E / (1.0 - nu * nu);
  Vec3 tr = old.stress;
  tr(0) += f * (d_strain(0) + nu * d_strain(1));
  tr(1) += f * (nu * d_strain(0) + d_strain(1));
  tr(2) += 0.5 * f * (1.0 - nu) * d_strain(2);

  const double sy_old = flow_stress(hardening, old.eps_p);
  const double svm_tr = von_mises_plane_stress(tr);
  if (!std::isfinite(svm_tr)) {
    throw InstabilityError("J2 plane stress: non-finite trial stress");
  }
  if (svm_tr <= sy_old) {
    return {tr, old.eps_p, through_thickness_increment(E, nu, d_strain, old.stress, tr), false};
  }

  // Plastic corrector (Simo & Hughes 1998, sect. 3.4, plane-stress return mapping; Simo & Taylor
  // 1986). With the projection P = 1/3 [[2,-1,0],[-1,2,0],[0,0,6]], the yield function is f = 1/2
  // s^T P s - 1/3 sigma_y^2 and the backward-Euler stress is s = (C^-1 + dgamma P)^-1 C^-1 s_tr. C
  // and P share the eigenvectors (1,1,0)/sqrt2, (-1,1,0)/sqrt2, (0,0,1) with eigenvalues (E/(1-nu),
  // 2mu, mu) and (1/3, 1, 2), so
  //   p = (sxx + syy)/2 = p_tr / (1 + a dgamma),  a = E / (3 (1 - nu)),
  //   q = (sxx - syy)/2 = q_tr / (1 + b dgamma),  sxy = sxy_tr / (1 + b dgamma),  b = 2 mu.
  // fbar^2 = s^T P s = (2/3) p^2 + 2 q^2 + 2 sxy^2 = A/(1 + a dg)^2 + B/(1 + b dg)^2, and the
  // equivalent plastic strain grows by sqrt(2/3) dgamma fbar (plastic-work equivalence).
  // Consistency: r(dg) = sqrt(3/2) fbar(dg) - sigma_y(eps_n + sqrt(2/3) dg fbar(dg)) = 0,
  // solved by Newton (r is strictly decreasing) safeguarded by bisection.
  const double mu = 0.5 * E / (1.0 + nu);
  const double a = E / (3.0 * (1.0 - nu));
  const double b = 2.0 * mu;
  const double p_tr = 0.5 * (tr(0) + tr(1));
  const double q_tr = 0.5 * (tr(0) - tr(1));
  const double A = (2.0 / 3.0) * p_tr * p_tr;
  const double B = 2.0 * (q_tr * q_tr + tr(2) * tr(2));
  const double s32 = std::sqrt(1.5);
  const double s23 = std::sqrt(2.0 / 3.0);

  double dg = 0.0;
  double lo = 0.0;
  double hi = std::numeric_limits<double>::infinity();
  double eps_p = old.eps_p;
  bool converged = false;
  for (int it = 0; it < 100; ++it) {
    const double ca = 1.0 / (1.0 + a * dg);
    const double cb = 1.0 / (1.0 + b * dg);
    const double fbar = std::sqrt(A * ca * ca + B * cb * cb);
    const double dfbar = -(A * a * ca * ca * ca + B * b * cb * cb * cb) / fbar;
    eps_p = old.eps_p + s23 * dg * fbar;
    const FlowStress hard = evaluate_hardening(hardening, eps_p);
    const double sy = hard.stress;
    const double r = s32 * fbar - sy;
    if (std::abs(r) <= 1e-10 * sy) {
      converged = true;
      break;
    }
    if (r > 0.0) {
      lo = dg;
    } else {
      hi = dg;
    }
    const double dr = s32 * dfbar - hard.slope * s23 * (fbar + dg * dfbar);
    double next = dg - r / dr;
    if (!(next > lo && next < hi)) {  // Newton left the bracket (or is not finite): bisect
      next = std::isfinite(hi) ? 0.5 * (lo + hi) : 2.0 * lo + 1.0 / b;
    }
    dg = next;
  }
  if (!converged) {
    throw InstabilityError("J2 plane stress: return mapping did not converge (trial von Mises " +
                           std::to_string(svm_tr) + " MPa)");
  }
  const double ca = 1.0 / (1.0 + a * dg);
  const double cb = 1.0 / (1.0 + b * dg);
  const Vec3 s(p_tr * ca + q_tr * cb, p_tr * ca - q_tr * cb, tr(2) * cb);
  return {s, eps_p, through_thickness_increment(E, nu, d_strain, old.stress, s), true};
}

double young_modulus(const Material& material) {
  return std::visit([](const auto& m) { return m.E; }, material);
}

double poisson_ratio(const Material& material) {
  return std::visit([](const auto& m) { return m.nu; }, material);
}

void check_material(const Material& material, const char* what) {
  const double E = young_modulus(material);
  const double nu = poisson_ratio(material);
  if (!(E > 0.0) || !std::isfinite(E) || !(nu > -1.0) || !(nu < 0.5)) {
    throw InputError(std::string(what) +
                     ": needs Young's modulus > 0 and -1 < Poisson's ratio < 0.5 (got E = " +
                     std::to_string(E) + ", nu = " + std::to_string(nu) + ")");
  }
  if (const auto* j2 = std::get_if<J2PlaneStress>(&material)) {
    check_hardening(j2->hardening, what);
  }
}

}  // namespace sf
