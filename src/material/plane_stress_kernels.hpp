#pragma once
// The inline pieces of the plane-stress laws' point update: the elastic predictor, the
// through-thickness strain, and per law (J2, Hill48) its constants and the steps around the modal
// return (trial measure, modal weights, returned stress, plastic strain). The constants are
// formed once per law (not per point); every expression is the one the update has always used,
// so the results are the same to the bit. The update itself: plane_stress_batch.hpp.
#include <cmath>

#include "core/types.hpp"
#include "material/plane_stress.hpp"

namespace sf {

/// Elastic predictor: s + C d (plane stress, engineering shear).
inline Vec3 elastic_trial(double E, double nu, const Vec3& s, const Vec3& d) {
  const double f = E / (1.0 - nu * nu);
  return {s(0) + f * (d(0) + nu * d(1)), s(1) + f * (nu * d(0) + d(1)),
          s(2) + 0.5 * f * (1.0 - nu) * d(2)};
}

/// Through-thickness strain increment from plane stress and plastic incompressibility:
/// d_ezz = d_ezz^e + d_ezz^p with d_ezz^e = -nu/E d(sxx + syy) and d_ezz^p = -(d_exx^p +
/// d_eyy^p), d_exx^p + d_eyy^p = d_exx + d_eyy - (1 - nu)/E d(sxx + syy); hence
/// d_ezz = -(d_exx + d_eyy) + (1 - 2 nu)/E d(sxx + syy). Exact for the elastic step too.
inline double through_thickness_increment(double E, double nu, const Vec3& d_strain,
                                          const Vec3& s_old, const Vec3& s_new) {
  const double d_trace = (s_new(0) + s_new(1)) - (s_old(0) + s_old(1));
  return -(d_strain(0) + d_strain(1)) + (1.0 - 2.0 * nu) / E * d_trace;
}

/// Linear elasticity: the predictor is the update.
struct ElasticKernel {
  static constexpr bool kMaterialAxes = false;
  double E;
  double nu;
  explicit ElasticKernel(const ElasticPlaneStress& law) : E(law.E), nu(law.nu) {}
};

/// J2 (Simo & Taylor 1986; Simo & Hughes 1998 sect. 3.4). With the Hill-normalised J2 matrix
/// P = [[1, -1/2, 0], [-1/2, 1, 0], [0, 0, 3]] (s^T P s = sigma_vm^2), C and P share the
/// eigenvectors (1,1,0)/sqrt2, (1,-1,0)/sqrt2, (0,0,1): modal stiffness ratios
/// lam = (E / (2 (1 - nu)), 3 mu, 3 mu), so p = p_tr c1, q = q_tr c2, sxy = sxy_tr c2.
struct J2Kernel {
  static constexpr bool kMaterialAxes = false;
  static constexpr int kModes = 2;  // the shear shares the second mode's ratio
  static constexpr const char* kName = "J2 plane stress";
  double E;
  double nu;
  const Hardening* hardening;
  double lam[3];

  explicit J2Kernel(const J2PlaneStress& law) : E(law.E), nu(law.nu), hardening(&law.hardening) {
    const double mu = 0.5 * E / (1.0 + nu);
    lam[0] = 0.5 * E / (1.0 - nu);
    lam[1] = 3.0 * mu;
    lam[2] = 3.0 * mu;
  }
  /// sigma_vm^2 = p^2 + 3 q^2 + 3 sxy^2 with p = (sxx + syy)/2, q = (sxx - syy)/2: the sum of
  /// the modal weights.
  double measure(const Vec3& tr) const {
    double A[3];
    weights(tr, A);
    return A[0] + A[1];
  }
  /// Modal weights of the trial stress.
  void weights(const Vec3& tr, double (&A)[3]) const {
    const double p_tr = 0.5 * (tr(0) + tr(1));
    const double q_tr = 0.5 * (tr(0) - tr(1));
    A[0] = p_tr * p_tr;
    A[1] = 3.0 * (q_tr * q_tr + tr(2) * tr(2));
    A[2] = 0.0;
  }
  Vec3 returned_stress(const Vec3& tr, double D) const {
    const double p_tr = 0.5 * (tr(0) + tr(1));
    const double q_tr = 0.5 * (tr(0) - tr(1));
    const double c1 = 1.0 / (1.0 + lam[0] * D);
    const double c2 = 1.0 / (1.0 + lam[1] * D);
    return {p_tr * c1 + q_tr * c2, p_tr * c1 - q_tr * c2, tr(2) * c2};
  }
  /// d_eps^p = D P s (engineering shear).
  Vec3 plastic_strain(const Vec3& s, double D) const {
    return D * Vec3(s(0) - 0.5 * s(1), s(1) - 0.5 * s(0), 3.0 * s(2));
  }
};

/// Hill48: the J2 return generalised to the Hill matrix P = [[G + H, -H, 0], [-H, F + H, 0],
/// [0, 0, 2N]] (s^T P s = sigma_eq^2). Normal components in the orthonormal basis u = (1,1)/sqrt2,
/// v = (1,-1)/sqrt2, where C = diag(ku^2, kv^2), ku^2 = E/(1-nu), kv^2 = E/(1+nu). M = L Pu L
/// (L = diag(ku, kv)) = V diag(lam1, lam2) V^T gives Q = L V with Q^T C^-1 Q = I,
/// Q^T P Q = diag(lam). Shear: lam3 = 2 N mu.
struct Hill48Kernel {
  static constexpr bool kMaterialAxes = true;  // works in the rolling-direction axes
  static constexpr int kModes = 3;
  static constexpr const char* kName = "Hill48 plane stress";
  double E;
  double nu;
  const Hardening* hardening;
  Hill48Coefficients k;
  double a, d;    // G + H, F + H
  double ku, kv;  // sqrt(E / (1 -+ nu))
  double cs, sn;  // eigenvectors (cs, sn), (-sn, cs) of M
  double lam[3];
  double r2;  // sqrt(1/2)

  explicit Hill48Kernel(const Hill48PlaneStress& law)
      : E(law.E), nu(law.nu), hardening(&law.hardening) {
    k = hill48_coefficients(law.r0, law.r45, law.r90);
    a = k.G + k.H;
    d = k.F + k.H;
    const double pu = 0.5 * (a + d) - k.H;  // u^T P u
    const double pv = 0.5 * (a + d) + k.H;  // v^T P v
    const double puv = 0.5 * (a - d);       // u^T P v
    ku = std::sqrt(E / (1.0 - nu));
    kv = std::sqrt(E / (1.0 + nu));
    const double m11 = ku * ku * pu;
    const double m22 = kv * kv * pv;
    const double m12 = ku * kv * puv;
    const double mean = 0.5 * (m11 + m22);
    const double half = 0.5 * (m11 - m22);
    const double rad = std::hypot(half, m12);
    // From the double angle, without trigonometry and without cancellation (the larger of cos,
    // sin is taken from its square root).
    cs = 1.0;
    sn = 0.0;
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
    lam[0] = mean + rad;
    lam[1] = mean - rad;
    lam[2] = 2.0 * k.N * mu;
    r2 = std::sqrt(0.5);
  }
  /// sigma_eq^2 (Hill48, material axes).
  double measure(const Vec3& tr) const {
    const double dd = tr(0) - tr(1);
    return k.G * tr(0) * tr(0) + k.F * tr(1) * tr(1) + k.H * dd * dd + 2.0 * k.N * tr(2) * tr(2);
  }
  /// Modal weights of the trial stress.
  void weights(const Vec3& tr, double (&A)[3]) const {
    const double y1 = modal_u(tr);
    const double y2 = modal_v(tr);
    A[0] = lam[0] * y1 * y1;
    A[1] = lam[1] * y2 * y2;
    A[2] = 2.0 * k.N * tr(2) * tr(2);
  }
  Vec3 returned_stress(const Vec3& tr, double D) const {
    const double z1 = modal_u(tr) / (1.0 + lam[0] * D);
    const double z2 = modal_v(tr) / (1.0 + lam[1] * D);
    const double su = ku * (cs * z1 - sn * z2);
    const double sv = kv * (sn * z1 + cs * z2);
    return {r2 * (su + sv), r2 * (su - sv), tr(2) / (1.0 + lam[2] * D)};
  }
  /// d_eps^p = D P s (engineering shear).
  Vec3 plastic_strain(const Vec3& s, double D) const {
    return D * Vec3(a * s(0) - k.H * s(1), d * s(1) - k.H * s(0), 2.0 * k.N * s(2));
  }

 private:
  double wu(const Vec3& tr) const { return r2 * (tr(0) + tr(1)) / ku; }
  double wv(const Vec3& tr) const { return r2 * (tr(0) - tr(1)) / kv; }
  double modal_u(const Vec3& tr) const { return cs * wu(tr) + sn * wv(tr); }
  double modal_v(const Vec3& tr) const { return -sn * wu(tr) + cs * wv(tr); }
};

/// The kernel of a law, formed once per element loop. `rate_dt`: the step's duration (s) for a
/// rate-dependent law, 0 for a rate-free update (the static steps' pseudo-time); only
/// GeneralPlasticity is rate-dependent.
inline ElasticKernel point_kernel(const ElasticPlaneStress& law, double /*rate_dt*/) {
  return ElasticKernel(law);
}
inline J2Kernel point_kernel(const J2PlaneStress& law, double /*rate_dt*/) {
  return J2Kernel(law);
}
inline Hill48Kernel point_kernel(const Hill48PlaneStress& law, double /*rate_dt*/) {
  return Hill48Kernel(law);
}
inline GeneralKernel point_kernel(const GeneralPlasticity& law, double rate_dt) {
  return GeneralKernel{&law, rate_dt};
}

}  // namespace sf
