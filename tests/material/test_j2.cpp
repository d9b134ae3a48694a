// Single-point checks of the plane-stress materials against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/errors.hpp"
#include "material/plane_stress.hpp"

namespace sf {
namespace {

// NUMISHEET'93 mild steel (REFERENCES.md, grade C; only used as realistic numbers here).
const SwiftHardening kSwift{565.32, 0.007117, 0.2589};
const J2PlaneStress kSteel{206000.0, 0.3, kSwift};
const J2PlaneStress kLinear{210000.0, 0.3, LinearHardening{250.0, 1000.0}};

// Scalar root by bisection (independent of the return mapping): f(lo) and f(hi) differ in sign.
double bisect(const std::function<double(double)>& f, double lo, double hi) {
  double flo = f(lo);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    const double fm = f(mid);
    if ((fm > 0.0) == (flo > 0.0)) {
      lo = mid;
      flo = fm;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

// Uniaxial stress driver: strain increment d_exx, d_eyy found by the secant method so that the new
// syy vanishes (sxy stays 0 with no shear increment).
PlaneStressUpdate uniaxial_step(const J2PlaneStress& m, const PlaneStressState& s, double d_exx,
                                double& d_eyy) {
  double e0 = d_eyy;
  double e1 = d_eyy - 1e-3 * std::abs(d_exx) - 1e-12;
  double r0 = m.update(s, Vec3(d_exx, e0, 0.0)).stress(1);
  PlaneStressUpdate up = m.update(s, Vec3(d_exx, e1, 0.0));
  for (int it = 0; it < 100 && std::abs(up.stress(1)) > 1e-13 * std::abs(up.stress(0)); ++it) {
    const double r1 = up.stress(1);
    const double e2 = e1 - r1 * (e1 - e0) / (r1 - r0);
    e0 = e1;
    r0 = r1;
    e1 = e2;
    up = m.update(s, Vec3(d_exx, e1, 0.0));
  }
  d_eyy = e1;
  return up;
}

TEST(Hardening, SwiftAndLinearValuesAndSlopes) {
  // Closed forms; slope against a central difference (h = 1e-6, error O(h^2) ~ 1e-9 relative).
  EXPECT_DOUBLE_EQ(flow_stress(Hardening{kSwift}, 0.1), 565.32 * std::pow(0.107117, 0.2589));
  EXPECT_DOUBLE_EQ(flow_stress(Hardening{LinearHardening{250.0, 1000.0}}, 0.1), 350.0);
  const double h = 1e-6;
  const double fd = (kSwift.flow_stress(0.1 + h) - kSwift.flow_stress(0.1 - h)) / (2 * h);
  EXPECT_NEAR(kSwift.slope(0.1) / fd, 1.0, 1e-8);
  EXPECT_THROW(check_hardening(Hardening{SwiftHardening{500.0, 0.0, 0.2}}, "m"), InputError);
  EXPECT_THROW(check_material(Material{ElasticPlaneStress{210000.0, 0.5}}, "m"), InputError);
  EXPECT_NO_THROW(check_material(Material{kSteel}, "steel"));
}

TEST(ElasticPlaneStress, MatchesHooke) {
  // Hooke's law in plane stress, exact to round-off (tolerance 1e-12 relative).
  const ElasticPlaneStress m{210000.0, 0.3};
  const Vec3 d(1e-3, -2e-4, 5e-4);
  const PlaneStressUpdate up = m.update(PlaneStressState{}, d);
  const double f = 210000.0 / (1 - 0.09);
  EXPECT_NEAR(up.stress(0), f * (1e-3 - 0.3 * 2e-4), 1e-12 * f * 1e-3);
  EXPECT_NEAR(up.stress(1), f * (-2e-4 + 0.3e-3), 1e-12 * f * 1e-3);
  EXPECT_NEAR(up.stress(2), 210000.0 / 2.6 * 5e-4, 1e-12 * f * 1e-3);
  // ezz = -nu/E (sxx + syy) = -nu/(1-nu) (exx + eyy).
  EXPECT_NEAR(up.d_ezz, -0.3 / 0.7 * (1e-3 - 2e-4), 1e-15);
}

TEST(J2PlaneStress, ElasticStepIsHookeExactly) {
  // Below yield the J2 update is Hooke's law; compare with the elastic material, tolerance 0.
  const Vec3 d(4e-4, 1e-4, -3e-4);
  const PlaneStressUpdate a = kSteel.update(PlaneStressState{}, d);
  const PlaneStressUpdate b = ElasticPlaneStress{206000.0, 0.3}.update(PlaneStressState{}, d);
  EXPECT_FALSE(a.plastic);
  EXPECT_EQ(a.stress, b.stress);
  EXPECT_EQ(a.eps_p, 0.0);
  EXPECT_EQ(a.d_ezz, b.d_ezz);
}

TEST(J2PlaneStress, UniaxialDriverFollowsHardeningCurveAndLankford) {
  // Source: 1-D von Mises plasticity; sigma = flow_stress(eps_p) (tolerance 1e-8 relative), and
  // the plastic strain ratio d_eyy^p / d_exx^p = -1/2 (normality, P s with s = (sigma, 0, 0)),
  // tolerance 1e-8. 200 steps of 5e-4 to exx = 0.1.
  for (const J2PlaneStress& m : {kSteel, kLinear}) {
    PlaneStressState s;
    double d_eyy = -0.3 * 5e-4;
    double max_err = 0.0;
    double max_ratio_err = 0.0;
    for (int step = 0; step < 200; ++step) {
      const PlaneStressUpdate up = uniaxial_step(m, s, 5e-4, d_eyy);
      const double sy = flow_stress(m.hardening, up.eps_p);
      if (up.plastic) {
        max_err = std::max(max_err, std::abs(up.stress(0) - sy) / sy);
        const Vec3 ds = up.stress - s.stress;
        const double dexx_p = 5e-4 - (ds(0) - m.nu * ds(1)) / m.E;
        const double deyy_p = d_eyy - (ds(1) - m.nu * ds(0)) / m.E;
        if (up.eps_p - s.eps_p > 1e-4) {  // fully plastic step
          max_ratio_err = std::max(max_ratio_err, std::abs(deyy_p / dexx_p + 0.5));
        }
      }
      s.stress = up.stress;
      s.eps_p = up.eps_p;
    }
    EXPECT_GT(s.eps_p, 0.09);
    EXPECT_LT(max_err, 1e-8);
    EXPECT_LT(max_ratio_err, 1e-8);
    std::printf("uniaxial: max |sigma - sigma_y|/sigma_y = %.3e, max |ratio + 0.5| = %.3e\n",
                max_err, max_ratio_err);
  }
}

TEST(J2PlaneStress, EquibiaxialClosedForm) {
  // Equibiaxial strain exx = eyy = e: s = sigma_y(eps_p), eps_p = 2 (e - s (1 - nu) / E), solved
  // here by bisection. The return is radial, so one step and 50 steps must both hit it
  // (tolerance 1e-9 relative, set by the 1e-10 return-mapping tolerance).
  const double e = 0.05;
  for (const J2PlaneStress& m : {kSteel, kLinear}) {
    const double s_exact = bisect(
        [&](double s) { return s - flow_stress(m.hardening, 2.0 * (e - s * (1 - m.nu) / m.E)); },
        0.0, e * m.E / (1 - m.nu));
    for (int n : {1, 50}) {
      PlaneStressState st;
      for (int i = 0; i < n; ++i) {
        const PlaneStressUpdate up = m.update(st, Vec3(e / n, e / n, 0.0));
        st.stress = up.stress;
        st.eps_p = up.eps_p;
      }
      EXPECT_NEAR(st.stress(0) / s_exact, 1.0, 1e-9) << n;
      EXPECT_NEAR(st.stress(1) / s_exact, 1.0, 1e-9) << n;
      EXPECT_NEAR(st.eps_p, 2.0 * (e - s_exact * (1 - m.nu) / m.E), 1e-9) << n;
      std::printf("equibiaxial n=%d: rel err %.3e\n", n, std::abs(st.stress(0) / s_exact - 1));
    }
  }
}

TEST(J2PlaneStress, PureShearClosedForm) {
  // Simple shear gxy = g: tau = mu (g - g_p), sqrt(3) tau = sigma_y(g_p / sqrt(3)) (von Mises),
  // solved by bisection; one and 40 steps, tolerance 1e-9 relative; sxx = syy = 0 exactly.
  const double g = 0.08;
  for (const J2PlaneStress& m : {kSteel, kLinear}) {
    const double mu = 0.5 * m.E / (1 + m.nu);
    const double tau = bisect(
        [&](double t) {
          return std::sqrt(3.0) * t - flow_stress(m.hardening, (g - t / mu) / std::sqrt(3.0));
        },
        0.0, mu * g);
    for (int n : {1, 40}) {
      PlaneStressState st;
      for (int i = 0; i < n; ++i) {
        const PlaneStressUpdate up = m.update(st, Vec3(0.0, 0.0, g / n));
        st.stress = up.stress;
        st.eps_p = up.eps_p;
      }
      EXPECT_NEAR(st.stress(2) / tau, 1.0, 1e-9) << n;
      EXPECT_EQ(st.stress(0), 0.0);
      EXPECT_EQ(st.stress(1), 0.0);
      EXPECT_NEAR(st.eps_p, (g - tau / mu) / std::sqrt(3.0), 1e-9) << n;
      std::printf("shear n=%d: rel err %.3e\n", n, std::abs(st.stress(2) / tau - 1));
    }
  }
}

TEST(J2PlaneStress, LargeStepResidualAndNormality) {
  // A large mixed step from a prestressed, prehardened state. Checks: |f| / sigma_y < 1e-10 with
  // f = sigma_vm - sigma_y (Simo & Hughes 3.4 consistency), the plastic strain increment
  // d_eps - C^-1 d_sigma is parallel to P sigma_{n+1} (backward-Euler normality, 1e-8), and its
  // work-equivalent norm equals d eps_p (1e-8).
  PlaneStressState s;
  s.stress = Vec3(150.0, -80.0, 60.0);
  s.eps_p = 0.02;
  const Vec3 d(0.03, -0.01, 0.05);
  for (const J2PlaneStress& m : {kSteel, kLinear}) {
    const PlaneStressUpdate up = m.update(s, d);
    ASSERT_TRUE(up.plastic);
    const double sy = flow_stress(m.hardening, up.eps_p);
    const double res = std::abs(von_mises_plane_stress(up.stress) - sy) / sy;
    EXPECT_LT(res, 1e-10);
    const Vec3 dp = d - plane_stress_stiffness(m.E, m.nu).inverse() * (up.stress - s.stress);
    Mat3 P;
    P << 2, -1, 0, -1, 2, 0, 0, 0, 6;
    P /= 3.0;
    const Vec3 n = P * up.stress;
    EXPECT_LT((dp - dp.dot(n) / n.dot(n) * n).norm() / dp.norm(), 1e-8);
    // Equivalent plastic strain increment from plastic work: s . dp = sigma_y d eps_p.
    EXPECT_NEAR(up.stress.dot(dp) / sy / (up.eps_p - s.eps_p), 1.0, 1e-8);
    std::printf("large step: |f|/sigma_y = %.3e\n", res);
  }
}

TEST(J2PlaneStress, ThroughThicknessStrainConservesVolumeInPlasticFlow) {
  // Perfect plasticity, uniaxial flow at constant stress: d(sxx + syy) = 0, so d_ezz must be
  // -(d_exx + d_eyy) (plastic incompressibility), tolerance 1e-15 absolute on 1e-3 increments.
  const J2PlaneStress m{210000.0, 0.3, LinearHardening{250.0, 0.0}};
  PlaneStressState s;
  double d_eyy = -0.3e-3;
  for (int i = 0; i < 10; ++i) {
    const PlaneStressUpdate up = uniaxial_step(m, s, 1e-3, d_eyy);
    if (i >= 3) {  // fully plastic
      EXPECT_NEAR(1e-3 + d_eyy + up.d_ezz, 0.0, 1e-15) << i;
      EXPECT_NEAR(d_eyy, -0.5e-3, 1e-12) << i;
    }
    s.stress = up.stress;
    s.eps_p = up.eps_p;
  }
  // Elastic-plastic general step: elastic volume change (1 - 2 nu)/E d(sxx + syy) only.
  const PlaneStressUpdate up = kSteel.update(PlaneStressState{}, Vec3(0.02, 0.005, 0.01));
  EXPECT_NEAR(0.025 + up.d_ezz, (1 - 0.6) / 206000.0 * (up.stress(0) + up.stress(1)), 1e-15);
}

}  // namespace
}  // namespace sf
