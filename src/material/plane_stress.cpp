#include "material/plane_stress.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

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

// Closed-point return in modal form. With C^-1 and the yield matrix P diagonalised together
// (Q^T C^-1 Q = I, Q^T P Q = diag(lam)), the backward-Euler stress is a scaling of the trial
// stress's modal coordinates y_i by c_i = 1 / (1 + lam_i D), D = d_lambda / sigma_eq(n+1), and
//   phi(D)^2 = sigma_eq^2 = sum_i A_i c_i^2,   A_i = lam_i y_i^2.
// Consistency r(D) = phi(D) - sigma_y(eps_n + D phi(D)) = 0 (d eps_p = d_lambda = D phi by
// plastic-work equivalence, sigma . d_eps^p = d_lambda sigma_eq). With
// S0 = sum A_i c_i^3, S1 = sum A_i lam_i c_i^3: phi' = -S1/phi, d(D phi)/dD = S0/phi > 0, so
// r' = -(S1 + sigma_y' S0)/phi < 0 for a non-decreasing flow stress: one root, bracketed Newton.
struct ModalReturn {
  double D;      // d_lambda / sigma_eq at n+1, 1/MPa
  double eps_p;  // new equivalent plastic strain
};

template <class Law>
ModalReturn solve_consistency(const double (&A)[3], const double (&lam)[3], double phi_tr,
                              double eps_n, FlowStress h, const Law& law, const char* name) {
  double D = 0.0;
  double lo = 0.0;
  double hi = std::numeric_limits<double>::infinity();
  double phi = phi_tr;
  double eps = eps_n;
  double c[3] = {1.0, 1.0, 1.0};
  const FlowStress h_n = h;  // at eps_n
  const double grow = 1.0 / std::max({lam[0], lam[1], lam[2]});
  for (int it = 0; it < 100; ++it) {
    // h = (sigma_y, slope) at eps; the first pass reuses the trial check's evaluation (D = 0).
    const double r = phi - h.stress;
    if (std::abs(r) <= 1e-10 * h.stress) {
      return {D, eps};
    }
    (r > 0.0 ? lo : hi) = D;
    double s0 = 0.0;
    double s1 = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double a3 = A[i] * c[i] * c[i] * c[i];
      s0 += a3;
      s1 += a3 * lam[i];
    }
    const double dr = -(s1 + h.slope * s0) / phi;
    // Newton step; the first one (from D = 0) is replaced by the radial-return estimate
    // D = (phi_tr - sigma_y) / (lam_eff sigma_y + sigma_y' phi_tr), lam_eff = S1/S0, which is the
    // exact root when one mode carries the stress and the hardening is linear, and otherwise
    // saves one or two iterations (the root itself is unchanged: same residual and tolerance).
    double next = it == 0 ? r / (s1 / s0 * h.stress + h.slope * phi) : D - r / dr;
    if (!(next > lo && next < hi)) {  // Newton left the bracket (or is not finite): bisect
      next = std::isfinite(hi) ? 0.5 * (lo + hi) : 2.0 * lo + grow;
    }
    D = next;
    double phi2 = 0.0;
    for (int i = 0; i < 3; ++i) {
      c[i] = 1.0 / (1.0 + lam[i] * D);
      phi2 += A[i] * c[i] * c[i];
    }
    phi = std::sqrt(phi2);
    eps = eps_n + D * phi;
    if constexpr (std::is_same_v<Law, SwiftHardening>) {
      h = law.evaluate_near(eps, eps_n, h_n);  // no pow for the small steps of a return
    } else {
      h = law.evaluate(eps);
    }
  }
  throw InstabilityError(std::string(name) +
                         ": return mapping did not converge (trial equivalent stress " +
                         std::to_string(phi_tr) + " MPa)");
}

template <class Hard>
ModalReturn solve_consistency_visit(const double (&A)[3], const double (&lam)[3], double phi_tr,
                                    double eps_n, FlowStress h, const Hard& hardening,
                                    const char* name) {
  return std::visit(
      [&](const auto& law) { return solve_consistency(A, lam, phi_tr, eps_n, h, law, name); },
      hardening);
}

Vec3 elastic_trial(double E, double nu, const Vec3& s, const Vec3& d) {
  const double f = E / (1.0 - nu * nu);
  return {s(0) + f * (d(0) + nu * d(1)), s(1) + f * (nu * d(0) + d(1)),
          s(2) + 0.5 * f * (1.0 - nu) * d(2)};
}

}  // namespace

PlaneStressUpdate ElasticPlaneStress::update(const State& old, const Vec3& d_strain) const {
  const Vec3 s = elastic_trial(E, nu, old.stress, d_strain);
  return {s, old.eps_p, through_thickness_increment(E, nu, d_strain, old.stress, s), false};
}

PlaneStressUpdate J2PlaneStress::update(const State& old, const Vec3& d_strain) const {
  // Elastic predictor and trial check with one flow-stress evaluation (value and slope together;
  // the slope is reused by the first Newton step). Squares are compared: no sqrt when elastic.
  const Vec3 tr = elastic_trial(E, nu, old.stress, d_strain);
  const double p_tr = 0.5 * (tr(0) + tr(1));
  const double q_tr = 0.5 * (tr(0) - tr(1));
  // sigma_vm^2 = p^2 + 3 q^2 + 3 sxy^2 with p = (sxx + syy)/2, q = (sxx - syy)/2.
  const double A[3] = {p_tr * p_tr, 3.0 * (q_tr * q_tr + tr(2) * tr(2)), 0.0};
  const double vm2 = A[0] + A[1];
  if (!std::isfinite(vm2)) {
    throw InstabilityError("J2 plane stress: non-finite trial stress");
  }
  const FlowStress h0 = evaluate_hardening(hardening, old.eps_p);
  if (vm2 <= h0.stress * h0.stress) {
    return {tr, old.eps_p, through_thickness_increment(E, nu, d_strain, old.stress, tr), false};
  }

  // Plastic corrector (Simo & Taylor 1986; Simo & Hughes 1998 sect. 3.4). With the Hill-normalised
  // J2 matrix P = [[1, -1/2, 0], [-1/2, 1, 0], [0, 0, 3]] (s^T P s = sigma_vm^2), C and P share the
  // eigenvectors (1,1,0)/sqrt2, (1,-1,0)/sqrt2, (0,0,1): modal stiffness ratios
  // lam = (E / (2 (1 - nu)), 3 mu, 3 mu), so p = p_tr c1, q = q_tr c2, sxy = sxy_tr c2.
  const double mu = 0.5 * E / (1.0 + nu);
  const double lam[3] = {0.5 * E / (1.0 - nu), 3.0 * mu, 3.0 * mu};
  const ModalReturn ret =
      solve_consistency_visit(A, lam, std::sqrt(vm2), old.eps_p, h0, hardening, "J2 plane stress");
  const double c1 = 1.0 / (1.0 + lam[0] * ret.D);
  const double c2 = 1.0 / (1.0 + lam[1] * ret.D);
  const Vec3 s(p_tr * c1 + q_tr * c2, p_tr * c1 - q_tr * c2, tr(2) * c2);
  // d_eps^p = D P s (engineering shear); plastic work with the mid-step stress.
  const Vec3 dp = ret.D * Vec3(s(0) - 0.5 * s(1), s(1) - 0.5 * s(0), 3.0 * s(2));
  const double work = 0.5 * (old.stress + s).dot(dp);
  return {s, ret.eps_p, through_thickness_increment(E, nu, d_strain, old.stress, s), true, work};
}

Hill48Coefficients hill48_coefficients(double r0, double r45, double r90) {
  const double G = 1.0 / (1.0 + r0);
  const double H = r0 / (1.0 + r0);
  const double F = r0 / (r90 * (1.0 + r0));
  const double N = (r0 + r90) * (1.0 + 2.0 * r45) / (2.0 * r90 * (1.0 + r0));
  return {F, G, H, N};
}

double hill48_equivalent_stress(const Hill48Coefficients& c, const Vec3& s) {
  const double d = s(0) - s(1);
  return std::sqrt(c.G * s(0) * s(0) + c.F * s(1) * s(1) + c.H * d * d + 2.0 * c.N * s(2) * s(2));
}

PlaneStressUpdate Hill48PlaneStress::update(const State& old, const Vec3& d_strain) const {
  const Hill48Coefficients k = hill48_coefficients(r0, r45, r90);
  const Vec3 tr = elastic_trial(E, nu, old.stress, d_strain);
  const double eq2_tr = [&] {
    const double d = tr(0) - tr(1);
    return k.G * tr(0) * tr(0) + k.F * tr(1) * tr(1) + k.H * d * d + 2.0 * k.N * tr(2) * tr(2);
  }();
  if (!std::isfinite(eq2_tr)) {
    throw InstabilityError("Hill48 plane stress: non-finite trial stress");
  }
  const FlowStress h0 = evaluate_hardening(hardening, old.eps_p);
  if (eq2_tr <= h0.stress * h0.stress) {
    return {tr, old.eps_p, through_thickness_increment(E, nu, d_strain, old.stress, tr), false};
  }

  // Plastic corrector: the J2 closed-point return generalised to the Hill matrix
  // P = [[G + H, -H, 0], [-H, F + H, 0], [0, 0, 2N]] (s^T P s = sigma_eq^2). Normal components in
  // the orthonormal basis u = (1,1)/sqrt2, v = (1,-1)/sqrt2, where C = diag(ku^2, kv^2),
  // ku^2 = E/(1-nu), kv^2 = E/(1+nu). M = L Pu L (L = diag(ku, kv)) = V diag(lam1, lam2) V^T gives
  // Q = L V with Q^T C^-1 Q = I, Q^T P Q = diag(lam). Shear: lam3 = 2 N mu.
  const double a = k.G + k.H;
  const double d = k.F + k.H;
  const double pu = 0.5 * (a + d) - k.H;  // u^T P u
  const double pv = 0.5 * (a + d) + k.H;  // v^T P v
  const double puv = 0.5 * (a - d);       // u^T P v
  const double ku = std::sqrt(E / (1.0 - nu));
  const double kv = std::sqrt(E / (1.0 + nu));
  const double m11 = ku * ku * pu;
  const double m22 = kv * kv * pv;
  const double m12 = ku * kv * puv;
  const double mean = 0.5 * (m11 + m22);
  const double half = 0.5 * (m11 - m22);
  const double rad = std::hypot(half, m12);
  // Eigenvectors (cs, sn) and (-sn, cs) of M from the double angle, without trigonometry and
  // without cancellation (the larger of cos, sin is taken from its square root).
  double cs = 1.0;
  double sn = 0.0;
  if (rad > 0.0) {
    const double c2t = half / rad;
    const double s2t = m12 / rad;
    if (c2t >= 0.0) {
      cs = std::sqrt(0.5 * (1.0 + c2t));
      sn = s2t / (2.0 * cs);
    } else {
      sn = std::copysign(std::sqrt(0.5 * (1.0 - c2t)), s2t);
      cs = s2t / (2.0 * sn);
    }
  }
  const double mu = 0.5 * E / (1.0 + nu);
  const double lam[3] = {mean + rad, mean - rad, 2.0 * k.N * mu};
  const double r2 = std::sqrt(0.5);
  const double wu = r2 * (tr(0) + tr(1)) / ku;
  const double wv = r2 * (tr(0) - tr(1)) / kv;
  const double y1 = cs * wu + sn * wv;
  const double y2 = -sn * wu + cs * wv;
  const double A[3] = {lam[0] * y1 * y1, lam[1] * y2 * y2, 2.0 * k.N * tr(2) * tr(2)};
  const ModalReturn ret = solve_consistency_visit(A, lam, std::sqrt(eq2_tr), old.eps_p, h0,
                                                  hardening, "Hill48 plane stress");
  const double z1 = y1 / (1.0 + lam[0] * ret.D);
  const double z2 = y2 / (1.0 + lam[1] * ret.D);
  const double su = ku * (cs * z1 - sn * z2);
  const double sv = kv * (sn * z1 + cs * z2);
  const Vec3 s(r2 * (su + sv), r2 * (su - sv), tr(2) / (1.0 + lam[2] * ret.D));
  // d_eps^p = D P s (engineering shear); plastic work with the mid-step stress.
  const Vec3 dp = ret.D * Vec3(a * s(0) - k.H * s(1), d * s(1) - k.H * s(0), 2.0 * k.N * s(2));
  const double work = 0.5 * (old.stress + s).dot(dp);
  return {s, ret.eps_p, through_thickness_increment(E, nu, d_strain, old.stress, s), true, work};
}

Vec3 rotate_strain(const Vec3& e, double angle) {
  return rotate_strain(e, std::cos(angle), std::sin(angle));
}

Vec3 rotate_stress(const Vec3& t, double angle) {
  return rotate_stress(t, std::cos(angle), std::sin(angle));
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
  if (const auto* h = std::get_if<Hill48PlaneStress>(&material)) {
    for (const double r : {h->r0, h->r45, h->r90}) {
      if (!(r > 0.0) || !std::isfinite(r)) {
        throw InputError(std::string(what) + ": Hill48 needs r0, r45, r90 > 0 (got " +
                         std::to_string(h->r0) + ", " + std::to_string(h->r45) + ", " +
                         std::to_string(h->r90) + ")");
      }
    }
    check_hardening(h->hardening, what);
  }
}

}  // namespace sf
