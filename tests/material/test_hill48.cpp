// Hill48 plane stress: single-point drivers against the closed forms of Hill (1948).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/errors.hpp"
#include "material/plane_stress.hpp"

namespace sf {
namespace {

// NUMISHEET'93 materials (REFERENCES.md, grade C; realistic inputs, not gated against tests).
const SwiftHardening kAluSwift{576.79, 0.01658, 0.3593};
const Hill48PlaneStress kAlu{71000.0, 0.33, 0.71, 0.58, 0.70, kAluSwift};
const Hill48PlaneStress kSteel{206000.0, 0.3,  1.79,
                               1.51,     2.27, SwiftHardening{565.32, 0.007117, 0.2589}};
const double kPi = 3.14159265358979323846;

struct DriverStep {
  PlaneStressUpdate up;  // in material axes
  Vec3 d_eps_load;       // strain increment in the loading frame
};

// Uniaxial stress along a direction at `angle` to the rolling direction: the loading-frame strain
// increment (d_e, e2, g12) with e2, g12 found by Newton (finite-difference Jacobian) so that the
// loading-frame syy and sxy vanish (to 1e-12 of sxx).
DriverStep uniaxial_step(const Hill48PlaneStress& m, const PlaneStressState& s, double angle,
                         double d_e, Vec2& guess) {
  const auto run = [&](const Vec2& x) {
    const Vec3 d_load(d_e, x(0), x(1));
    const PlaneStressUpdate up = m.update(s, rotate_strain(d_load, -angle));
    return DriverStep{up, d_load};
  };
  const auto res = [&](const DriverStep& r) {
    const Vec3 sl = rotate_stress(r.up.stress, angle);
    return Vec2(sl(1), sl(2));
  };
  DriverStep r = run(guess);
  for (int it = 0; it < 50; ++it) {
    const Vec2 f = res(r);
    const double scale = std::abs(rotate_stress(r.up.stress, angle)(0));
    if (f.norm() <= 1e-12 * scale) {
      break;
    }
    Mat2 J;
    const double h = 1e-7 * std::abs(d_e);
    for (int j = 0; j < 2; ++j) {
      Vec2 xp = guess;
      xp(j) += h;
      J.col(j) = (res(run(xp)) - f) / h;
    }
    guess -= J.lu().solve(f);
    r = run(guess);
  }
  return r;
}

struct UniaxialResult {
  double r_value;        // d eps_width^p / d eps_thickness^p of the last (fully plastic) step
  double max_curve_err;  // max |sigma_load - sigma_y(eps_p)| / sigma_y, plastic steps
  double first_yield;    // loading stress at first yield, MPa
  double work_sum;       // sum of d_plastic_work, MPa
  double work_direct;    // sum of sigma_mid . d_eps^p, d_eps^p = d_eps - C^-1 d_sigma, MPa
  double eps_p;
};

UniaxialResult run_uniaxial(const Hill48PlaneStress& m, double angle, int steps, double d_e) {
  PlaneStressState s;
  Vec2 guess(-m.nu * d_e, 0.0);
  UniaxialResult out{0, 0, 0, 0, 0, 0};
  const Mat3 c_inv = plane_stress_stiffness(m.E, m.nu).inverse();
  for (int i = 0; i < steps; ++i) {
    const DriverStep st = uniaxial_step(m, s, angle, d_e, guess);
    const Vec3 sl = rotate_stress(st.up.stress, angle);
    const Vec3 sl_old = rotate_stress(s.stress, angle);
    // Plastic strain increment in the loading frame (isotropic elasticity: C^-1 in any frame).
    const Vec3 dp = st.d_eps_load - c_inv * (sl - sl_old);
    out.work_sum += st.up.d_plastic_work;
    out.work_direct += 0.5 * (sl + sl_old).dot(dp);
    if (st.up.plastic) {
      if (out.first_yield == 0.0) {
        out.first_yield = sl(0);
      }
      const double sy = flow_stress(m.hardening, st.up.eps_p);
      out.max_curve_err = std::max(out.max_curve_err, std::abs(sl(0) - sy) / sy);
      out.r_value = dp(1) / (-(dp(0) + dp(1)));
    }
    s = {st.up.stress, st.up.eps_p};
  }
  out.eps_p = s.eps_p;
  return out;
}

TEST(Hill48, CoefficientsAndYieldStressRatio) {
  // Hill (1948); Banabic, Sheet Metal Forming Processes (Springer 2010) sect. 3.4: r0 = H/G,
  // r90 = H/F, r45 = N/(F + G) - 1/2, and with G + H = 1 uniaxial tension at 90 deg yields at
  // sigma0 / sqrt(F + H) = sigma0 sqrt(r90 (1 + r0) / (r0 (1 + r90))). Tolerance 1e-14 (round-off).
  for (const Hill48PlaneStress& m : {kAlu, kSteel}) {
    const Hill48Coefficients k = hill48_coefficients(m.r0, m.r45, m.r90);
    EXPECT_NEAR(k.G + k.H, 1.0, 1e-14);
    EXPECT_NEAR(k.H / k.G, m.r0, 1e-14);
    EXPECT_NEAR(k.H / k.F, m.r90, 1e-14);
    EXPECT_NEAR(k.N / (k.F + k.G) - 0.5, m.r45, 1e-14);
    const double ratio = std::sqrt(m.r90 * (1 + m.r0) / (m.r0 * (1 + m.r90)));
    EXPECT_NEAR(hill48_equivalent_stress(k, Vec3(0.0, ratio, 0.0)), 1.0, 1e-14);
  }
  EXPECT_THROW(check_material(Material{Hill48PlaneStress{71000, 0.33, 0.7, 0.0, 0.7}}, "m"),
               InputError);
  EXPECT_NO_THROW(check_material(Material{kAlu}, "alu"));
}

TEST(Hill48, RotationsAreInverseAndPreserveInvariants) {
  // Tensor transformation rules; tolerance 1e-12 relative (round-off).
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 100; ++i) {
    const Vec3 e(u(rng), u(rng), u(rng));
    const Vec3 s(300 * u(rng), 300 * u(rng), 300 * u(rng));
    const double a = 4.0 * u(rng);
    const Vec3 er = rotate_strain(e, a);
    const Vec3 sr = rotate_stress(s, a);
    EXPECT_LT((rotate_strain(er, -a) - e).norm(), 1e-12 * e.norm());
    EXPECT_LT((rotate_stress(sr, -a) - s).norm(), 1e-12 * s.norm());
    EXPECT_NEAR(er(0) + er(1), e(0) + e(1), 1e-12);
    EXPECT_NEAR(er(0) * er(1) - 0.25 * er(2) * er(2), e(0) * e(1) - 0.25 * e(2) * e(2), 1e-12);
    EXPECT_NEAR(sr(0) * sr(1) - sr(2) * sr(2), s(0) * s(1) - s(2) * s(2), 1e-12 * 9e4);
    EXPECT_NEAR(sr.dot(er), s.dot(e), 1e-12 * 300);  // work with engineering shear
  }
  // Uniaxial stress 1 along x, seen in axes at 30 deg: (cos^2, sin^2, -sin cos).
  const Vec3 s30 = rotate_stress(Vec3(1, 0, 0), kPi / 6);
  EXPECT_NEAR(s30(0), 0.75, 1e-15);
  EXPECT_NEAR(s30(1), 0.25, 1e-15);
  EXPECT_NEAR(s30(2), -std::sqrt(3.0) / 4, 1e-15);
  // Pure shear strain gxy = 2 seen at 45 deg: principal strains (1, -1), no shear.
  const Vec3 e45 = rotate_strain(Vec3(0, 0, 2), kPi / 4);
  EXPECT_NEAR(e45(0), 1.0, 1e-15);
  EXPECT_NEAR(e45(1), -1.0, 1e-15);
  EXPECT_NEAR(e45(2), 0.0, 1e-15);
}

TEST(Hill48, UniaxialDriverReproducesRValuesHardeningAndYieldRatio) {
  // Hill (1948) associated flow: the plastic strain ratio of uniaxial tension at 0/45/90 deg is
  // r0/r45/r90 (tolerance 1e-6); along RD sigma = sigma_y(eps_p) (1e-8 relative, the return's 1e-10
  // tolerance plus the driver's 1e-12); first yield at 90 deg / at 0 deg = sqrt(r90 (1 + r0) /
  // (r0 (1 + r90))) (1e-6, limited by the first plastic step's hardening: the step starts elastic
  // and ends with eps_p > 0, so it is checked against sigma_y(eps_p) of that step).
  for (const Hill48PlaneStress& m : {kAlu, kSteel}) {
    const double r[3] = {m.r0, m.r45, m.r90};
    for (int k = 0; k < 3; ++k) {
      const UniaxialResult res = run_uniaxial(m, k * kPi / 4, 60, 1e-3);
      EXPECT_GT(res.eps_p, 0.04);
      EXPECT_NEAR(res.r_value, r[k], 1e-6) << k;
      std::printf("angle %d: r = %.10f (expected %.2f), curve err %.2e\n", 45 * k, res.r_value,
                  r[k], res.max_curve_err);
      if (k == 0) {
        EXPECT_LT(res.max_curve_err, 1e-8);
      }
    }
    // Yield stress at 90 deg: sigma_load = ratio * sigma_y(eps_p) along the whole plastic curve.
    const double ratio = std::sqrt(m.r90 * (1 + m.r0) / (m.r0 * (1 + m.r90)));
    PlaneStressState s;
    Vec2 guess(-m.nu * 1e-3, 0.0);
    double max_err = 0.0;
    for (int i = 0; i < 40; ++i) {
      const DriverStep st = uniaxial_step(m, s, kPi / 2, 1e-3, guess);
      if (st.up.plastic) {
        const double s90 = rotate_stress(st.up.stress, kPi / 2)(0);
        max_err =
            std::max(max_err, std::abs(s90 / flow_stress(m.hardening, st.up.eps_p) / ratio - 1.0));
      }
      s = {st.up.stress, st.up.eps_p};
    }
    EXPECT_LT(max_err, 1e-8);
    std::printf("sigma90/sigma0: max rel err %.2e (ratio %.6f)\n", max_err, ratio);
  }
}

TEST(Hill48, IsotropicEqualsJ2OnRandomPaths) {
  // r0 = r45 = r90 = 1 gives F = G = H = 1/2, N = 3/2: von Mises. Random strain paths of 30 steps;
  // tolerance 1e-10 relative on stress and 1e-10 absolute on eps_p (both returns converge to
  // 1e-10).
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Hill48PlaneStress h{206000.0, 0.3, 1.0, 1.0, 1.0, kSteel.hardening};
  const J2PlaneStress j{206000.0, 0.3, kSteel.hardening};
  double max_err = 0.0;
  for (int path = 0; path < 20; ++path) {
    PlaneStressState sh;
    PlaneStressState sj;
    for (int i = 0; i < 30; ++i) {
      const Vec3 d = 4e-3 * Vec3(u(rng), u(rng), u(rng));
      const PlaneStressUpdate uh = h.update(sh, d);
      const PlaneStressUpdate uj = j.update(sj, d);
      max_err = std::max(max_err, (uh.stress - uj.stress).norm() / uj.stress.norm());
      EXPECT_NEAR(uh.eps_p, uj.eps_p, 1e-10);
      EXPECT_EQ(uh.plastic, uj.plastic);
      EXPECT_NEAR(uh.d_plastic_work, uj.d_plastic_work, 1e-10 * std::max(1.0, uj.d_plastic_work));
      sh = {uh.stress, uh.eps_p};
      sj = {uj.stress, uj.eps_p};
    }
  }
  EXPECT_LT(max_err, 1e-10);
  std::printf("Hill48(r=1) vs J2: max rel stress difference %.2e\n", max_err);
}

TEST(Hill48, LargeStepResidualIncompressibilityAndNormality) {
  // Large mixed step from a prestressed, prehardened state. |f|/sigma_y < 1e-10 (consistency);
  // plastic d_ezz^p = -d_lambda (G sxx + F syy) / sigma_eq from the 3-D Hill gradient equals
  // d_ezz - elastic part (incompressibility, 1e-12 absolute); d_eps^p = d_eps - C^-1 d_sigma is
  // parallel to P sigma (normality, 1e-8); d_plastic_work = sigma_mid . d_eps^p (1e-8 relative).
  PlaneStressState s;
  s.stress = Vec3(150.0, -80.0, 60.0);
  s.eps_p = 0.02;
  const Vec3 d(0.03, -0.01, 0.05);
  for (const Hill48PlaneStress& m : {kAlu, kSteel}) {
    const Hill48Coefficients k = hill48_coefficients(m.r0, m.r45, m.r90);
    const PlaneStressUpdate up = m.update(s, d);
    ASSERT_TRUE(up.plastic);
    const double sy = flow_stress(m.hardening, up.eps_p);
    const double seq = hill48_equivalent_stress(k, up.stress);
    EXPECT_LT(std::abs(seq - sy) / sy, 1e-10);
    const double dl = up.eps_p - s.eps_p;
    const double dezz_p = -dl * (k.G * up.stress(0) + k.F * up.stress(1)) / seq;
    const double dezz_e = -m.nu / m.E * (up.stress(0) + up.stress(1) - s.stress(0) - s.stress(1));
    EXPECT_NEAR(up.d_ezz - dezz_e, dezz_p, 1e-12);
    const Vec3 dp = d - plane_stress_stiffness(m.E, m.nu).inverse() * (up.stress - s.stress);
    EXPECT_NEAR(dp(0) + dp(1) + dezz_p, 0.0, 1e-12);
    Mat3 P;
    P << k.G + k.H, -k.H, 0, -k.H, k.F + k.H, 0, 0, 0, 2 * k.N;
    const Vec3 n = P * up.stress;
    EXPECT_LT((dp - dp.dot(n) / n.dot(n) * n).norm() / dp.norm(), 1e-8);
    EXPECT_NEAR(dp.dot(n) / n.norm() / (dl / seq * n.norm()), 1.0, 1e-8);
    EXPECT_NEAR(up.d_plastic_work / (0.5 * (s.stress + up.stress).dot(dp)), 1.0, 1e-8);
    std::printf("large step: |f|/sigma_y = %.2e\n", std::abs(seq - sy) / sy);
  }
  // Elastic step: no plastic work, Hooke.
  const PlaneStressUpdate el = kAlu.update(PlaneStressState{}, Vec3(1e-4, 0, 0));
  EXPECT_FALSE(el.plastic);
  EXPECT_EQ(el.d_plastic_work, 0.0);
}

TEST(Hill48, PlasticWorkAlongRollingDirection) {
  // Uniaxial tension along RD: sum of d_plastic_work = sum sigma_mid . d_eps^p (from the driver's
  // strains, 1e-10 relative) = integral of sigma_y d eps_p = K/(n+1) ((eps0+e)^(n+1) - eps0^(n+1))
  // (Swift; 1e-6 relative: trapezoidal error h^2/12 (sigma_y'(0) - sigma_y'(e)) ~ 2e-6 MPa for
  // h = 1e-4, plus the first elastic-plastic step, made small by starting at 0.999999 sigma_y0).
  const Hill48PlaneStress& m = kAlu;
  const SwiftHardening& sw = kAluSwift;
  PlaneStressState s;
  Vec2 guess(-m.nu * 1e-4, 0.0);
  double work = 0.0;
  double direct = 0.0;
  const Mat3 c_inv = plane_stress_stiffness(m.E, m.nu).inverse();
  const double e_yield = 0.999999 * sw.flow_stress(0.0) / m.E;
  for (int i = 0; i < 2001; ++i) {
    const double d_e = i == 0 ? e_yield : 1e-4;
    const DriverStep st = uniaxial_step(m, s, 0.0, d_e, guess);
    const Vec3 dp = st.d_eps_load - c_inv * (st.up.stress - s.stress);
    work += st.up.d_plastic_work;
    direct += 0.5 * (st.up.stress + s.stress).dot(dp);
    s = {st.up.stress, st.up.eps_p};
  }
  const double e = s.eps_p;
  const double exact =
      sw.K / (sw.n + 1) * (std::pow(sw.eps0 + e, sw.n + 1) - std::pow(sw.eps0, sw.n + 1));
  EXPECT_GT(e, 0.19);
  EXPECT_NEAR(work / direct, 1.0, 1e-10);
  EXPECT_NEAR(work / exact, 1.0, 1e-6);
  std::printf("plastic work %.10g MPa, integral %.10g, sum sigma.dp %.10g\n", work, exact, direct);
}

}  // namespace
}  // namespace sf
