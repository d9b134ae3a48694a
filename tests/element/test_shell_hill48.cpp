// Hill48 in the shell element: material axes from the rolling direction (compute_material_angles),
// uniaxial tension at 0, 45 and 90 deg to the rolling direction through the element (r-values and
// flow stress against Hill's closed forms), Hill48 with r = 1 against von Mises, and the same
// tension test for Yld2000-2d through the general return (issue 19), quad and triangle.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <type_traits>
#include <variant>

#include "core/errors.hpp"
#include "element/shell_geometry.hpp"
#include "element/shell_material_axes.hpp"
#include "element/shell_test_support.hpp"
#include "material/aa2090_data.hpp"
#include "material/anisotropy_fit.hpp"

namespace sf {
namespace {

using test::kE;
using test::kNu;
using test::run_step;

constexpr double kDeg = std::numbers::pi / 180.0;

QuadConn single_quad() {
  QuadConn q(4, 1);
  q << 0, 1, 2, 3;
  return q;
}

// A square of side a (mm) in the z = 0 plane, turned by beta (rad) about z: its side x21, hence
// its corotational e1, is at beta to global x.
Matrix3X turned_square(double a, double beta) {
  const Mat3 r = test::rotation(Vec3::UnitZ(), beta);
  Matrix3X x(3, 4);
  x.col(0) = Vec3::Zero();
  x.col(1) = r * Vec3(a, 0, 0);
  x.col(2) = r * Vec3(a, a, 0);
  x.col(3) = r * Vec3(0, a, 0);
  return x;
}

// An angle (rad) wrapped into [-pi, pi].
double wrap(double a) {
  return std::remainder(a, 2.0 * std::numbers::pi);
}

TEST(ShellMaterialAxes, AngleFromE1ToTheProjectedRollingDirection) {
  // e1 at 30 deg to x, rolling direction at 75 deg: 45 deg (exact geometry, tolerance 1e-14 rad).
  const Matrix3X x = turned_square(10.0, 30 * kDeg);
  std::vector<double> a =
      compute_material_angles(x, single_quad(), Vec3(std::cos(75 * kDeg), std::sin(75 * kDeg), 0));
  ASSERT_EQ(a.size(), 1u);
  EXPECT_NEAR(a[0], 45 * kDeg, 1e-14);
  // Not unit and with a normal component: only the in-plane part counts; -20 deg -> -50 deg.
  a = compute_material_angles(
      x, single_quad(), 3.0 * Vec3(std::cos(-20 * kDeg), std::sin(-20 * kDeg), 0) + Vec3(0, 0, 7));
  EXPECT_NEAR(a[0], -50 * kDeg, 1e-14);

  // A sheet tilted by 40 deg about global x: rolling direction global y projects on the tilted
  // plane's in-plane y axis (cos 40, sin 40 direction), which e1 (= global x here) sees at +90 deg.
  const Mat3 tilt = test::rotation(Vec3::UnitX(), 40 * kDeg);
  const Matrix3X xt = tilt * turned_square(10.0, 0.0);
  a = compute_material_angles(xt, single_quad(), Vec3::UnitY());
  EXPECT_NEAR(a[0], 90 * kDeg, 1e-14);
}

TEST(ShellMaterialAxes, RollingDirectionNormalToAnElementIsAnErrorNamingIt) {
  // A folded sheet: element 0 in the xy plane, element 1 in the xz plane (normal along y). The
  // rolling direction y lies in element 0 but is normal to element 1.
  Matrix3X x(3, 6);
  x << 0, 10, 10, 0, 20, 20,  //
      0, 0, 10, 10, 0, 10,    //
      0, 0, 0, 0, 0, 0;
  x.col(4) = Vec3(10, 0, 10);
  x.col(5) = Vec3(0, 0, 10);
  QuadConn q(4, 2);
  q << 0, 1,  //
      1, 4,   //
      2, 5,   //
      3, 0;
  EXPECT_NO_THROW(compute_material_angles(x, q, Vec3::UnitX()));
  try {
    compute_material_angles(x, q, Vec3::UnitY());
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("blank element 1 "), std::string::npos) << m;
    EXPECT_NE(m.find("normal"), std::string::npos) << m;
  }
  // 5 deg off the normal of element 1 is still rejected (in-plane part sin 5 deg = 0.087 < 0.1);
  // 7 deg is accepted (0.122).
  const auto off_normal = [](double deg) {
    return Vec3(std::sin(deg * kDeg), std::cos(deg * kDeg), 0.0);
  };
  EXPECT_THROW(compute_material_angles(x, q, off_normal(5.0)), InputError);
  EXPECT_NO_THROW(compute_material_angles(x, q, off_normal(7.0)));
}

// Hill48 steel (r-values of the NUMISHEET'93 steel, REFERENCES.md grade C) with Voce hardening.
const VoceHardening kVoce{180.0, 250.0, 12.5};
const Hill48PlaneStress kHill{kE, kNu, 1.79, 1.51, 2.27, kVoce};
// Hill's closed form k(alpha) = sqrt(G c^4 + F s^4 + H (c^2 - s^2)^2 + 2 N c^2 s^2).
double hill_k(double alpha) {
  const Hill48Coefficients k = hill48_coefficients(kHill.r0, kHill.r45, kHill.r90);
  const double ca = std::cos(alpha), sa = std::sin(alpha);
  return std::sqrt(k.G * std::pow(ca, 4) + k.F * std::pow(sa, 4) +
                   k.H * std::pow(ca * ca - sa * sa, 2) + 2 * k.N * ca * ca * sa * sa);
}

struct TensionResult {
  double r_last;         // width / thickness plastic strain increment ratio, last step
  double max_curve_err;  // max over plastic steps of |sigma k(alpha) - sigma_y(eps_p)| / sigma_y
  double max_lateral;    // max over steps of max |f_y| / max |f_x| (global nodal forces)
  double eps_p;          // final equivalent plastic strain
  double angle;          // the element's material angle, rad
};

// Uniaxial tension along global x of one square element whose e1 is at beta to x, with the
// rolling direction at -alpha to x (so the load is at +alpha to the rolling direction).
// Kinematics, per step: v_I = M (x_I - x_0), M = (I - dt/2 L)^-1 L, so that the velocity gradient
// on the mid-step configuration (where the element takes its strains) is exactly L. L = D + W with
// D = [[d, dxy], [dxy, dyy]] (d fixed) and a spin W chosen so that side x21 keeps its direction
// (L t parallel to t): the element's e1, hence the material axes, stay fixed, and the element sees
// exactly the strain rate D. dyy and dxy are found by Newton (finite-difference Jacobian) so that
// the global lateral stresses syy, sxy vanish (to 1e-11 of sxx): free lateral contraction.
// With `triangle`, the element is the C0 triangle on nodes 0, 1, 2 of the square (its e1 is also
// side x21), node 3 unused.
// `k_of_alpha(alpha)` is the material's equivalent stress of the unit uniaxial stress at alpha to
// the rolling direction (the loading stress's factor k(alpha)). `rate`: the law's Cowper-Symonds
// parameters, by which the expected flow stress is scaled with the step's plastic strain rate.
TensionResult run_tension(const Material& material, const std::function<double(double)>& k_of_alpha,
                          double alpha, double beta, int steps, bool triangle = false,
                          const CowperSymonds& rate = {}) {
  const double a = 10.0;
  const double dt = 1e-6;
  const double d = 200.0;  // 1/s: strain 2e-4 per step
  const Matrix3X x0 = turned_square(a, beta);
  ShellPart part = test::make_part(single_quad(), material);
  if (triangle) {
    part.quads = QuadConn(4, 0);
    part.triangles = TriConn(3, 1);
    part.triangles << 0, 1, 2;
  }
  const Vec3 rd(std::cos(alpha), -std::sin(alpha), 0.0);
  part.material_angle = compute_material_angles(x0, part.quads, part.triangles, rd);
  ShellState st = make_shell_state(1, 5, 1.0);
  size_shell_state_for_material(st, part.materials[0].law);
  Matrix3X x = x0;
  const Vec2 t(std::cos(beta), std::sin(beta));
  const Vec2 n(-t(1), t(0));
  const Matrix3X w = Matrix3X::Zero(3, 4);
  const Mat3 c_full_inv = plane_stress_stiffness(kE, kNu).inverse();

  struct Trial {
    ShellState st;
    Matrix3X x_end, f;
    Vec3 s_global;  // (sxx, syy, sxy) global, mid-surface point
  };
  const auto trial = [&](const Vec2& u) {
    const double dyy = u(0), dxy = u(1);
    Mat2 dm;
    dm << d, dxy, dxy, dyy;
    const double spin = -n.dot(dm * t);
    Mat2 l = dm;
    l(0, 1) -= spin;
    l(1, 0) += spin;
    const Mat2 m = (Mat2::Identity() - 0.5 * dt * l).inverse() * l;
    Matrix3X v = Matrix3X::Zero(3, 4);
    for (int i = 0; i < 4; ++i) {
      v.topRows<2>().col(i) = m * (x.col(i) - x.col(0)).head<2>();
    }
    Trial tr{st, x + dt * v, {}, {}};
    tr.f = run_step(part, tr.x_end, v, w, dt, tr.st).f;
    const int k = 2;  // mid-surface point (all points are equal: no bending)
    tr.s_global = rotate_stress(Vec3(tr.st.sxx[k], tr.st.syy[k], tr.st.sxy[k]), -beta);
    return tr;
  };

  TensionResult out{0, 0, 0, 0, part.material_angle[0]};
  Vec2 u(-0.5 * d, 0.0);
  const double k_alpha = k_of_alpha(alpha);
  const Hardening hardening = std::visit(
      [](const auto& law) -> Hardening {
        if constexpr (std::is_same_v<std::decay_t<decltype(law)>, ElasticPlaneStress>) {
          return LinearHardening{};
        } else {
          return law.hardening;
        }
      },
      material);
  for (int step = 0; step < steps; ++step) {
    Trial tr = trial(u);
    for (int it = 0; it < 30; ++it) {
      const Vec2 r(tr.s_global(1), tr.s_global(2));
      if (r.norm() <= 1e-11 * std::abs(tr.s_global(0))) {
        break;
      }
      Mat2 jac;
      const double h = 1e-6 * d;
      for (int j = 0; j < 2; ++j) {
        Vec2 up = u;
        up(j) += h;
        const Trial tp = trial(up);
        jac.col(j) = (Vec2(tp.s_global(1), tp.s_global(2)) - r) / h;
      }
      u -= jac.lu().solve(r);
      tr = trial(u);
    }
    const Vec3 s_old = rotate_stress(Vec3(st.sxx[2], st.syy[2], st.sxy[2]), -beta);
    const Vec3 d_eps = dt * Vec3(d, u(0), 2.0 * u(1));  // global, engineering shear
    const Vec3 d_ep = d_eps - c_full_inv * (tr.s_global - s_old);
    // Thickness plastic strain from the element's own thickness update (d_ezz = t1/t0 - 1 for
    // equal points) minus its elastic part -nu/E d(sxx + syy).
    const double d_ezz = tr.st.thickness[0] / st.thickness[0] - 1.0;
    const double d_ezz_p =
        d_ezz + kNu / kE * ((tr.s_global(0) + tr.s_global(1)) - (s_old(0) + s_old(1)));
    const bool plastic = tr.st.eps_p[2] > st.eps_p[2];
    if (plastic) {
      out.r_last = d_ep(1) / d_ezz_p;
      const double rate_factor =
          rate.active()
              ? 1.0 + std::pow((tr.st.eps_p[2] - st.eps_p[2]) / (rate.D * dt), 1.0 / rate.q)
              : 1.0;
      const double sy = flow_stress(hardening, tr.st.eps_p[2]) * rate_factor;
      out.max_curve_err = std::max(out.max_curve_err, std::abs(tr.s_global(0) * k_alpha - sy) / sy);
    }
    out.max_lateral = std::max(
        out.max_lateral, tr.f.row(1).cwiseAbs().maxCoeff() / tr.f.row(0).cwiseAbs().maxCoeff());
    st = tr.st;
    x = tr.x_end;
  }
  out.eps_p = st.eps_p[2];
  return out;
}

TEST(ShellHill48, UniaxialTensionThroughTheElementGivesTheLankfordCoefficients) {
  // Exact answers (Hill 1948; Banabic 2010 sect. 3.4): with the load at alpha to the rolling
  // direction, the plastic strain-increment ratio width / thickness is r_alpha, i.e. r0, r45, r90
  // at 0, 45, 90 deg, at every fully plastic backward-Euler step (the flow direction is that of
  // the end-of-step uniaxial stress); the loading stress times
  // k(alpha) = sqrt(G c^4 + F s^4 + H (c^2 - s^2)^2 + 2 N c^2 s^2) equals sigma_y(eps_p) (Voce).
  // Tolerances: r 1e-9 relative (the lateral stresses are zeroed to 1e-11 of sxx and the return
  // to 1e-10 of sigma_y; at a converged return the flow direction is exact, so round-off remains:
  // measured 2.6e-12), flow stress 1e-9 relative (return tolerance 1e-10; measured 1.0e-10). The
  // element's e1 is at 30 deg to x, so the material angle e1 -> RD is -alpha - 30 deg.
  const double beta = 30 * kDeg;
  const double r_expected[3] = {kHill.r0, kHill.r45, kHill.r90};
  for (int i = 0; i < 3; ++i) {
    const double alpha = 45.0 * i * kDeg;
    SCOPED_TRACE("alpha = " + std::to_string(45 * i) + " deg");
    const TensionResult r = run_tension(kHill, hill_k, alpha, beta, 150);
    EXPECT_NEAR(wrap(r.angle - (-alpha - beta)), 0.0, 1e-14);
    EXPECT_NEAR(r.r_last, r_expected[i], 1e-9 * r_expected[i]);
    EXPECT_LT(r.max_curve_err, 1e-9);
    EXPECT_GT(r.eps_p, 0.02);  // 3 % strain: well into the plastic range
    // Lateral nodal forces vanish with the lateral stresses (relative to the axial ones).
    EXPECT_LT(r.max_lateral, 1e-9);
    std::printf(
        "alpha %2d deg: r = %.12f (exact %.2f, rel. err %.1e), flow-stress err %.1e, "
        "eps_p %.4f, lateral/axial force %.1e\n",
        45 * i, r.r_last, r_expected[i], std::abs(r.r_last / r_expected[i] - 1.0), r.max_curve_err,
        r.eps_p, r.max_lateral);
  }
}

TEST(ShellHill48, UniaxialTensionThroughTheTriangleGivesTheLankfordCoefficients) {
  // The same exact answers and tolerances as for the quad above, through the C0 triangle (its
  // material frame is set up and turned by the same code).
  const double beta = 30 * kDeg;
  const double r_expected[3] = {kHill.r0, kHill.r45, kHill.r90};
  for (int i = 0; i < 3; ++i) {
    const double alpha = 45.0 * i * kDeg;
    SCOPED_TRACE("alpha = " + std::to_string(45 * i) + " deg");
    const TensionResult r = run_tension(kHill, hill_k, alpha, beta, 150, true);
    EXPECT_NEAR(wrap(r.angle - (-alpha - beta)), 0.0, 1e-14);
    EXPECT_NEAR(r.r_last, r_expected[i], 1e-9 * r_expected[i]);
    EXPECT_LT(r.max_curve_err, 1e-9);
    EXPECT_GT(r.eps_p, 0.02);
    EXPECT_LT(r.max_lateral, 1e-9);
    std::printf(
        "triangle, alpha %2d deg: r = %.12f (exact %.2f, rel. err %.1e), flow-stress err "
        "%.1e\n",
        45 * i, r.r_last, r_expected[i], std::abs(r.r_last / r_expected[i] - 1.0), r.max_curve_err);
  }
}

// Yld2000-2d fitted to Barlat et al. (2003) Table 2's AA2090-T3 data (docs/references.md), with
// the same Voce hardening, through the general return (material/general_plasticity.hpp).
GeneralPlasticity aa2090() {
  GeneralPlasticity law;
  law.E = kE;
  law.nu = kNu;
  law.criterion = fit_yld2000(test::kAA2090, 8.0, "test");
  law.hardening = kVoce;
  return law;
}

// Uniaxial tension of `law` through the quad and the triangle at 0, 45 and 90 deg to the rolling
// direction, the element's e1 at 30 deg to the load; `check(r, i, label)` tests each result,
// i = 0, 1, 2 the direction. `expected_rate`: the rate dependence the expected flow stress has.
template <class Check>
void tension_at_0_45_90(const GeneralPlasticity& law, const CowperSymonds& expected_rate,
                        Check check) {
  const auto k_of_alpha = [&](double a) {
    const double c = std::cos(a), s = std::sin(a);
    return equivalent_stress_value(law.criterion, Vec3(c * c, s * s, c * s));
  };
  for (const bool triangle : {false, true}) {
    for (int i = 0; i < 3; ++i) {
      const std::string label = std::string(triangle ? "triangle" : "quad") + ", alpha " +
                                std::to_string(45 * i) + " deg";
      SCOPED_TRACE(label);
      check(run_tension(law, k_of_alpha, 45.0 * i * kDeg, 30 * kDeg, 150, triangle, expected_rate),
            i, label);
    }
  }
}

constexpr double kAA2090R[3] = {0.21, 1.58, 0.69};  // r0, r45, r90 (Barlat et al. 2003)

TEST(ShellYld2000, UniaxialTensionThroughTheQuadAndTheTriangleGivesTheFittedRValues) {
  // Exact answers: the r-values and flow-stress ratios Yld2000-2d was fitted to (the fit solves
  // them to 1e-12), reached through the element at 0, 45, 90 deg to the rolling direction with
  // the element's e1 at 30 deg to the load. Tolerances as for Hill48 above (1e-9): the general
  // return converges to 1e-10 of sigma_y, and its flow direction is the normal at the end stress.
  tension_at_0_45_90(aa2090(), {}, [](const TensionResult& r, int i, const std::string& label) {
    EXPECT_NEAR(r.r_last, kAA2090R[i], 1e-9 * kAA2090R[i]);
    EXPECT_LT(r.max_curve_err, 1e-9);
    EXPECT_GT(r.eps_p, 0.02);
    EXPECT_LT(r.max_lateral, 1e-9);
    std::printf("Yld2000-2d %s: r = %.12f (exact %.2f, rel. err %.1e), flow-stress err %.1e\n",
                label.c_str(), r.r_last, kAA2090R[i], std::abs(r.r_last / kAA2090R[i] - 1.0),
                r.max_curve_err);
  });
}

TEST(ShellYld2000, CowperSymondsThroughTheElementScalesTheFlowStressAndKeepsTheRValues) {
  // The element hands the law its step (1e-6 s at 200 /s): the loading stress must follow
  // sigma_y(eps_p) (1 + (d eps_p / (D dt))^(1/q)) to 1e-9 (Cowper & Symonds 1957), about 1.4
  // times the rate-free flow stress here, while the r-values, set by the criterion's normal
  // alone, stay the fitted ones.
  GeneralPlasticity law = aa2090();
  law.rate = {6500.0, 4.0};
  tension_at_0_45_90(law, law.rate, [](const TensionResult& r, int i, const std::string&) {
    EXPECT_NEAR(r.r_last, kAA2090R[i], 1e-9 * kAA2090R[i]);
    EXPECT_LT(r.max_curve_err, 1e-9);
    EXPECT_GT(r.eps_p, 0.02);
  });
  // Expecting the rate-free curve instead must fail by far: the element does hand the law dt.
  tension_at_0_45_90(law, {}, [](const TensionResult& r, int, const std::string&) {
    EXPECT_GT(r.max_curve_err, 0.2);
  });
}

TEST(ShellHill48, IsotropicHill48InTurnedAxesGivesTheVonMisesForces) {
  // Hill48 with r0 = r45 = r90 = 1 is von Mises (P is the same matrix), and von Mises is isotropic,
  // so turning the strain into material axes and the stress back changes nothing but round-off:
  // same nodal forces and moments, stresses, plastic strains and thicknesses. 5-element patch,
  // arbitrary material angles, 12 steps of a random (non-uniform, bending, hourglass) motion with
  // strains ~1e-3 per step (well past yield). Tolerance 1e-12 of the largest value (round-off).
  const Matrix3X x0 = test::patch_nodes();
  const QuadConn q = test::patch_quads();
  const J2PlaneStress j2{kE, kNu, kVoce};
  const Hill48PlaneStress hill{kE, kNu, 1.0, 1.0, 1.0, kVoce};
  const ShellPart p_j2 = test::make_part(q, j2);
  ShellPart p_hill = test::make_part(q, hill);
  p_hill.material_angle = {0.3, -1.2, 2.5, 0.7, -2.9};
  ShellState s_j2 = make_shell_state(5, 5, 1.0);
  ShellState s_hill = s_j2;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double dt = 1e-6;
  Matrix3X x = x0;
  double max_f = 0, max_df = 0, max_m = 0, max_dm = 0, max_s = 0, max_ds = 0, max_deps = 0;
  double max_eps = 0, max_dt = 0;
  for (int step = 0; step < 12; ++step) {
    Matrix3X v(3, 8), w(3, 8);
    for (int i = 0; i < 8; ++i) {
      v.col(i) = Vec3(25000.0 * x(0, i) / 24 + 2000 * u(rng),
                      -10000.0 * x(1, i) / 12 + 2000 * u(rng), 2000 * u(rng));
      w.col(i) = Vec3(200 * u(rng), 200 * u(rng), 0.0);
    }
    const Matrix3X x_end = x + dt * v;
    const auto a = run_step(p_j2, x_end, v, w, dt, s_j2);
    const auto b = run_step(p_hill, x_end, v, w, dt, s_hill);
    max_f = std::max(max_f, a.f.cwiseAbs().maxCoeff());
    max_df = std::max(max_df, (a.f - b.f).cwiseAbs().maxCoeff());
    max_m = std::max(max_m, a.m.cwiseAbs().maxCoeff());
    max_dm = std::max(max_dm, (a.m - b.m).cwiseAbs().maxCoeff());
    for (std::size_t i = 0; i < s_j2.sxx.size(); ++i) {
      max_s =
          std::max({max_s, std::abs(s_j2.sxx[i]), std::abs(s_j2.syy[i]), std::abs(s_j2.sxy[i])});
      max_ds =
          std::max({max_ds, std::abs(s_j2.sxx[i] - s_hill.sxx[i]),
                    std::abs(s_j2.syy[i] - s_hill.syy[i]), std::abs(s_j2.sxy[i] - s_hill.sxy[i])});
      max_eps = std::max(max_eps, s_j2.eps_p[i]);
      max_deps = std::max(max_deps, std::abs(s_j2.eps_p[i] - s_hill.eps_p[i]));
    }
    for (int e = 0; e < 5; ++e) {
      max_dt = std::max(max_dt, std::abs(s_j2.thickness[e] - s_hill.thickness[e]));
    }
    x = x_end;
  }
  EXPECT_GT(max_eps, 5e-3);  // the comparison covers plastic steps
  EXPECT_LT(max_df, 1e-12 * max_f);
  EXPECT_LT(max_dm, 1e-12 * max_m);
  EXPECT_LT(max_ds, 1e-12 * max_s);
  EXPECT_LT(max_deps, 1e-12 * max_eps);
  EXPECT_LT(max_dt, 1e-14);
  std::printf(
      "Hill48(r=1) vs J2: forces %.1e, moments %.1e, stresses %.1e, eps_p %.1e (relative), "
      "thickness %.1e mm; max eps_p %.4f\n",
      max_df / max_f, max_dm / max_m, max_ds / max_s, max_deps / max_eps, max_dt, max_eps);
}

}  // namespace
}  // namespace sf
