// Voce, Ludwik, Hockett-Sherby, Swift-Voce and tabulated hardening, the hardening-table reader,
// and J2 with a tabulated Swift curve, with Ludwik from the virgin state and with the combined
// laws.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <variant>

#include "core/errors.hpp"
#include "material/plane_stress.hpp"
#include "material/plane_stress_batch.hpp"
#include "material/plane_stress_kernels.hpp"

namespace sf {
namespace {

// Writes `text` to a file in the test's temporary directory and returns its path.
std::filesystem::path write_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("sf_test_hardening_" + name);
  std::ofstream(path) << text;
  return path;
}

// Message of the InputError `f` throws ("" if none).
template <class F>
std::string input_error(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Hardening, VoceAgainstClosedForm) {
  // Closed form sigma0 + Q (1 - exp(-b e)), slope Q b exp(-b e); tolerance 1e-13 relative (round-
  // off); slope also against a central difference (h = 1e-6, O(h^2) error ~ 1e-9 relative).
  const VoceHardening v{200.0, 150.0, 12.0};
  for (const double e : {0.0, 0.01, 0.1, 0.5}) {
    const double s = 200.0 + 150.0 * (1.0 - std::exp(-12.0 * e));
    EXPECT_NEAR(flow_stress(Hardening{v}, e) / s, 1.0, 1e-13);
    EXPECT_NEAR(hardening_slope(Hardening{v}, e) / (1800.0 * std::exp(-12.0 * e)), 1.0, 1e-13);
    const double h = 1e-6;
    const double fd = (v.flow_stress(e + h) - v.flow_stress(e - h)) / (2 * h);
    EXPECT_NEAR(v.slope(e) / fd, 1.0, 1e-8);
  }
  EXPECT_THROW(check_hardening(Hardening{VoceHardening{200.0, -1.0, 12.0}}, "m"), InputError);
  EXPECT_THROW(check_hardening(Hardening{VoceHardening{200.0, 10.0, 0.0}}, "m"), InputError);
  EXPECT_NO_THROW(check_hardening(Hardening{v}, "m"));
}

TEST(Hardening, LudwikAgainstClosedForm) {
  // sigma_y = A + B e^n, slope n B e^(n-1) (Ludwik 1909); the plate deck's law (issue 16):
  // A 200 MPa, B 500 MPa, n 0.3. Tolerance 1e-13 relative (round-off); the slope also against a
  // central difference (h = 1e-7 e, O(h^2) error ~ 1e-13, cancellation ~ 1e-9 relative).
  const LudwikHardening l{200.0, 500.0, 0.3};
  for (const double e : {1e-6, 1e-4, 0.01, 0.1, 0.5}) {
    const double s = 200.0 + 500.0 * std::pow(e, 0.3);
    EXPECT_NEAR(flow_stress(Hardening{l}, e) / s, 1.0, 1e-13);
    EXPECT_NEAR(hardening_slope(Hardening{l}, e) / (150.0 * std::pow(e, -0.7)), 1.0, 1e-13);
    const double h = 1e-7 * e;
    const double fd = (l.flow_stress(e + h) - l.flow_stress(e - h)) / (2 * h);
    EXPECT_NEAR(l.slope(e) / fd, 1.0, 1e-7);
  }
  // At e = 0: the initial yield stress A; the slope is infinite for n < 1, B for n = 1.
  EXPECT_EQ(l.flow_stress(0.0), 200.0);
  EXPECT_EQ(l.slope(0.0), std::numeric_limits<double>::infinity());
  EXPECT_EQ((LudwikHardening{200.0, 500.0, 1.0}.slope(0.0)), 500.0);
  EXPECT_EQ((LudwikHardening{200.0, 0.0, 0.3}.slope(0.0)), 0.0);  // perfectly plastic
  EXPECT_NO_THROW(check_hardening(Hardening{l}, "m"));
  for (const LudwikHardening& bad :
       {LudwikHardening{0.0, 500.0, 0.3}, LudwikHardening{200.0, -1.0, 0.3},
        LudwikHardening{200.0, 500.0, 0.0}, LudwikHardening{200.0, 500.0, 1.5}}) {
    EXPECT_NE(input_error([&] { check_hardening(Hardening{bad}, "m"); }).find("Ludwik hardening"),
              std::string::npos);
  }
}

TEST(Hardening, HockettSherbyAgainstClosedForm) {
  // sigma_y = sigma_s - (sigma_s - sigma_i) exp(-N e^p) (Hockett & Sherby 1975), slope
  // (sigma_s - sigma_i) N p e^(p-1) exp(-N e^p); 1e-13 against the formulas, the slope also
  // against a central difference (1e-7). p = 1 is Voce's law
  // with sigma0 = sigma_i, Q = sigma_s - sigma_i, b = N, to round-off.
  const HockettSherbyHardening h{420.0, 150.0, 6.0, 0.7};
  const VoceHardening voce{150.0, 270.0, 6.0};
  const HockettSherbyHardening h1{420.0, 150.0, 6.0, 1.0};
  for (const double e : {1e-6, 1e-4, 0.01, 0.1, 0.5}) {
    const double x = std::exp(-6.0 * std::pow(e, 0.7));
    EXPECT_NEAR(h.flow_stress(e) / (420.0 - 270.0 * x), 1.0, 1e-13);
    EXPECT_NEAR(h.slope(e) / (270.0 * 6.0 * 0.7 * std::pow(e, -0.3) * x), 1.0, 1e-13);
    // h = 1e-5 e: truncation (p-1)(p-2)/6 (h/e)^2 ~ 1e-11, cancellation ~ 1e-8 at e = 1e-6.
    const double step = 1e-5 * e;
    const double fd = (h.flow_stress(e + step) - h.flow_stress(e - step)) / (2 * step);
    EXPECT_NEAR(h.slope(e) / fd, 1.0, 1e-7);
    EXPECT_NEAR(h1.flow_stress(e) / voce.flow_stress(e), 1.0, 1e-14);
    EXPECT_NEAR(h1.slope(e) / voce.slope(e), 1.0, 1e-13);
  }
  EXPECT_EQ(h.flow_stress(0.0), 150.0);
  EXPECT_EQ(h.slope(0.0), std::numeric_limits<double>::infinity());
  EXPECT_EQ(h1.slope(0.0), 270.0 * 6.0);
  EXPECT_NO_THROW(check_hardening(Hardening{h}, "m"));
  for (const HockettSherbyHardening& bad : {HockettSherbyHardening{100.0, 150.0, 6.0, 1.0},
                                            HockettSherbyHardening{420.0, 0.0, 6.0, 1.0},
                                            HockettSherbyHardening{420.0, 150.0, 0.0, 1.0},
                                            HockettSherbyHardening{420.0, 150.0, 6.0, 1.5}}) {
    EXPECT_NE(
        input_error([&] { check_hardening(Hardening{bad}, "m"); }).find("Hockett-Sherby hardening"),
        std::string::npos);
  }
}

TEST(Hardening, SwiftVoceIsTheWeightedSum) {
  // w Swift + (1 - w) Voce, exactly; w = 1 is Swift, w = 0 Voce.
  const SwiftHardening swift{576.79, 0.01658, 0.3593};
  const VoceHardening voce{180.0, 250.0, 12.5};
  for (const double w : {0.0, 0.3, 1.0}) {
    const SwiftVoceHardening sv{w, swift, voce};
    for (const double e : {0.0, 1e-4, 0.05, 0.4}) {
      EXPECT_NEAR(sv.flow_stress(e), w * swift.flow_stress(e) + (1 - w) * voce.flow_stress(e),
                  1e-12 * 600);
      EXPECT_NEAR(sv.slope(e), w * swift.slope(e) + (1 - w) * voce.slope(e), 1e-12 * 1e4);
    }
  }
  EXPECT_NO_THROW(check_hardening(Hardening{SwiftVoceHardening{0.3, swift, voce}}, "m"));
  EXPECT_NE(input_error([&] {
              check_hardening(Hardening{SwiftVoceHardening{1.2, swift, voce}}, "m");
            }).find("Swift-Voce"),
            std::string::npos);
  EXPECT_NE(input_error([&] {
              check_hardening(Hardening{SwiftVoceHardening{0.5, swift, VoceHardening{}}}, "m");
            }).find("Voce hardening"),
            std::string::npos);
}

TEST(Hardening, J2WithHockettSherbyAndSwiftVoceStaysOnTheCurve) {
  // The closed-form J2 return with the two laws (instantiated for them): after every plastic
  // step of a mixed strain path the von Mises stress equals the flow stress to 1e-9.
  for (const Hardening& law :
       {Hardening{HockettSherbyHardening{420.0, 150.0, 6.0, 0.7}},
        Hardening{SwiftVoceHardening{0.4, SwiftHardening{576.79, 0.01658, 0.3593},
                                     VoceHardening{180.0, 250.0, 12.5}}}}) {
    const J2PlaneStress j2{210000.0, 0.3, law};
    PlaneStressState state;
    for (int i = 0; i < 100; ++i) {
      const PlaneStressUpdate u = j2.update(state, Vec3(2e-4, -1e-4, 2e-5));
      const Vec3& s = u.stress;
      const double mises = std::sqrt(s(0) * s(0) - s(0) * s(1) + s(1) * s(1) + 3.0 * s(2) * s(2));
      if (u.eps_p > state.eps_p) {
        EXPECT_NEAR(mises / flow_stress(law, u.eps_p), 1.0, 1e-9) << "step " << i;
      }
      state = {u.stress, u.eps_p};
    }
    EXPECT_GT(state.eps_p, 0.01);
  }
}

TEST(Hardening, J2WithLudwikFromTheVirginStateStaysOnTheCurve) {
  // The first plastic step starts where the slope is infinite (e = 0, n < 1): the return
  // mapping's bracketed Newton must still land on the curve. A mixed strain path of 100 steps:
  // after every plastic step the von Mises stress equals A + B eps_p^n to 1e-9 relative (the
  // return's tolerance 1e-10 plus round-off), and eps_p grows.
  const LudwikHardening l{200.0, 500.0, 0.3};
  const J2PlaneStress j2{210000.0, 0.3, l};
  PlaneStressState state;
  for (int i = 0; i < 100; ++i) {
    const PlaneStressUpdate u = j2.update(state, Vec3(2e-4, -1e-4, 2e-5));
    const Vec3& s = u.stress;
    const double mises = std::sqrt(s(0) * s(0) - s(0) * s(1) + s(1) * s(1) + 3.0 * s(2) * s(2));
    if (u.eps_p > state.eps_p) {
      EXPECT_NEAR(mises / l.flow_stress(u.eps_p), 1.0, 1e-9) << "step " << i;
    } else {
      EXPECT_LE(mises, l.flow_stress(u.eps_p) * (1.0 + 1e-12)) << "step " << i;
    }
    state = {u.stress, u.eps_p};
  }
  EXPECT_GT(state.eps_p, 0.01);
}

TEST(Hardening, TabulatedInterpolatesAndExtrapolates) {
  // Piecewise linear through the points; last slope beyond the table; exact to 1e-12 MPa.
  const TabulatedHardening t{{0.0, 0.1, 0.3}, {200.0, 300.0, 340.0}};
  EXPECT_NEAR(t.flow_stress(0.0), 200.0, 1e-12);
  EXPECT_NEAR(t.flow_stress(0.05), 250.0, 1e-12);
  EXPECT_NEAR(t.slope(0.05), 1000.0, 1e-9);
  EXPECT_NEAR(t.flow_stress(0.1), 300.0, 1e-12);
  EXPECT_NEAR(t.slope(0.1), 200.0, 1e-9);  // right-hand segment at a breakpoint
  EXPECT_NEAR(t.flow_stress(0.2), 320.0, 1e-12);
  EXPECT_NEAR(t.flow_stress(0.5), 380.0, 1e-12);  // extrapolated with slope 200
  EXPECT_NEAR(t.slope(0.5), 200.0, 1e-9);
  EXPECT_NEAR(TabulatedHardening({{0.0}, {250.0}}).flow_stress(0.3), 250.0, 0.0);
  EXPECT_NO_THROW(check_hardening(Hardening{t}, "m"));
}

TEST(Hardening, TabulatedValidationNamesTheRow) {
  const auto msg = [](std::vector<double> e, std::vector<double> s) {
    return input_error([&] { check_hardening(Hardening{TabulatedHardening{e, s}}, "alu"); });
  };
  EXPECT_NE(msg({0.0, 0.2, 0.1}, {200, 300, 310}).find("row 3"), std::string::npos);
  EXPECT_NE(msg({0.0, 0.1, 0.2}, {200, 300, 290}).find("row 3"), std::string::npos);
  EXPECT_NE(msg({0.01, 0.1}, {200, 300}).find("row 1"), std::string::npos);
  EXPECT_NE(msg({0.0, 0.1, 0.1}, {200, 300, 300}).find("row 3"), std::string::npos);
  EXPECT_NE(msg({0.0, 0.1}, {200}), "");
  EXPECT_EQ(msg({0.0, 0.1, 0.2}, {200, 300, 300}), "");  // flat segment is allowed
}

TEST(Hardening, CsvReaderReadsCommentsAndHeader) {
  const auto path = write_file("good.csv",
                               "# NUMISHEET-like curve\n"
                               "plastic_strain, true_stress_MPa\n"
                               "0, 200   # first point\n"
                               "\n"
                               "0.1;300\n"
                               "0.3 340\n");
  const TabulatedHardening t = read_hardening_csv(path);
  ASSERT_EQ(t.eps_p.size(), 3u);
  EXPECT_EQ(t.eps_p[1], 0.1);
  EXPECT_EQ(t.stress[2], 340.0);
}

TEST(Hardening, CsvReaderErrorsNameFileAndLine) {
  const auto bad_number = write_file("bad_number.csv", "eps,stress\n0,200\n0.1,3x0\n");
  std::string m = input_error([&] { read_hardening_csv(bad_number); });
  EXPECT_NE(m.find("bad_number.csv"), std::string::npos) << m;
  EXPECT_NE(m.find("line 3"), std::string::npos) << m;

  const auto decreasing = write_file("decreasing.csv", "# c\n0,200\n0.2,300\n0.1,310\n");
  m = input_error([&] { read_hardening_csv(decreasing); });
  EXPECT_NE(m.find("decreasing.csv"), std::string::npos) << m;
  EXPECT_NE(m.find("line 4"), std::string::npos) << m;

  const auto second_header = write_file("two_headers.csv", "eps,stress\nmore,words\n0,200\n");
  m = input_error([&] { read_hardening_csv(second_header); });
  EXPECT_NE(m.find("line 2"), std::string::npos) << m;

  const auto three_columns = write_file("three.csv", "0,200\n0.1,300,1\n");
  m = input_error([&] { read_hardening_csv(three_columns); });
  EXPECT_NE(m.find("line 2"), std::string::npos) << m;

  m = input_error([&] { read_hardening_csv("/nonexistent/curve.csv"); });
  EXPECT_NE(m.find("curve.csv"), std::string::npos) << m;
}

TEST(Hardening, J2WithDenseTabulatedSwiftMatchesSwift) {
  // NUMISHEET'93 aluminium Swift curve (REFERENCES.md, grade C), sampled at spacing h = 1e-4 on
  // [0, 0.5]. Linear-interpolation error bound: |e| <= h^2/8 max|sigma''| on each segment; the
  // largest |sigma''| = n (1 - n) K eps0^(n-2) (at eps_p = 0) = 1.1e5 MPa gives 1.4e-4 MPa, i.e.
  // 1.05e-6 relative to sigma_y(0) = 132 MPa. A mixed strain path of 100 steps then checks the
  // stress against J2 with Swift with tolerance 2 x that bound (relative; the factor 2 covers the
  // error carried from step to step) and eps_p to 5e-7 absolute.
  const SwiftHardening swift{576.79, 0.01658, 0.3593};
  TabulatedHardening table;
  for (int i = 0; i <= 5000; ++i) {
    table.eps_p.push_back(1e-4 * i);
    table.stress.push_back(swift.flow_stress(1e-4 * i));
  }
  const double bound = 1e-8 / 8 * 0.3593 * (1 - 0.3593) * 576.79 * std::pow(0.01658, 0.3593 - 2);
  const double tol = 2.0 * bound / swift.flow_stress(0.0);
  EXPECT_LT(tol, 2.2e-6);
  const J2PlaneStress a{71000.0, 0.33, swift};
  const J2PlaneStress b{71000.0, 0.33, table};
  PlaneStressState sa;
  PlaneStressState sb;
  double max_err = 0.0;
  for (int i = 0; i < 100; ++i) {
    const Vec3 d(2e-3, -1e-3, 2e-4);
    const PlaneStressUpdate ua = a.update(sa, d);
    const PlaneStressUpdate ub = b.update(sb, d);
    max_err = std::max(max_err, (ua.stress - ub.stress).norm() / ua.stress.norm());
    EXPECT_NEAR(ua.eps_p, ub.eps_p, 5e-7);
    sa = {ua.stress, ua.eps_p};
    sb = {ub.stress, ub.eps_p};
  }
  EXPECT_GT(sa.eps_p, 0.15);
  EXPECT_LT(max_err, tol);
  std::printf("tabulated vs Swift: max rel stress difference %.3e (bound %.3e)\n", max_err,
              bound / swift.flow_stress(0.0));
}

}  // namespace
}  // namespace sf

// The pow-free evaluation used inside the return mapping equals the closed form: truncation of
// the binomial series below |C(n,6)| x^6 for |x| <= 1e-2, i.e. < 1e-13 relative (tolerance 1e-13);
// beyond |x| = 1e-2 it falls back to the closed form (exact).
TEST(Hardening, SwiftEvaluateNearEqualsTheClosedForm) {
  for (double n : {0.0, 0.26, 0.5, 1.0}) {
    const sf::SwiftHardening swift{565.0, 0.007, n};
    for (double eps_ref : {0.0, 0.05, 0.4}) {
      const sf::FlowStress at_ref = swift.evaluate(eps_ref);
      for (double x : {-1e-2, -1e-4, 0.0, 1e-7, 1e-4, 3e-3, 1e-2, 5e-2}) {
        const double eps = eps_ref + x * (swift.eps0 + eps_ref);
        const sf::FlowStress near = swift.evaluate_near(eps, eps_ref, at_ref);
        const sf::FlowStress exact = swift.evaluate(eps);
        EXPECT_NEAR(near.stress, exact.stress, 1e-13 * exact.stress) << "n " << n << " x " << x;
        EXPECT_NEAR(near.slope, exact.slope, 1e-13 * std::abs(exact.slope) + 1e-300);
      }
    }
  }
}

// The flow stress a yielding point keeps for its next check (FlowStressCache) is the one its
// return converged on, with no further evaluation: for a Swift law the binomial series from the
// step's start, within its truncation bound of the closed form (1e-13 relative, as above); for
// the other laws the law's own value, bit for bit. 60 mixed steps of 5 points at different
// strains, every point yielding from the second step on; the cache is what the next step
// reads, so the stresses must also stay on the curve (the return's tolerance, 1e-9).
TEST(Hardening, TheStoredFlowStressIsTheLawsAtThePointsStrain) {
  for (const sf::Hardening& law : {sf::Hardening{sf::SwiftHardening{565.0, 0.007, 0.26}},
                                   sf::Hardening{sf::VoceHardening{180.0, 250.0, 12.5}}}) {
    const bool swift = std::holds_alternative<sf::SwiftHardening>(law);
    const sf::J2PlaneStress j2{210000.0, 0.3, law};
    const sf::J2Kernel kernel(j2);
    constexpr int kPoints = 5;
    sf::Vec3 stress[kPoints], strain[kPoints];
    double eps_p[kPoints], cached[kPoints], cached_at[kPoints];
    for (int p = 0; p < kPoints; ++p) {
      stress[p].setZero();
      strain[p] = (1.0 + 0.3 * p) * sf::Vec3(2e-4, -1e-4 + 3e-5 * p, 2e-5);
      eps_p[p] = 0.0;
      cached_at[p] = std::numeric_limits<double>::quiet_NaN();
    }
    int checked = 0;
    for (int step = 0; step < 60; ++step) {
      sf::PlaneStressUpdate up[kPoints];
      sf::MaterialFailure failure;
      ASSERT_TRUE(sf::update_points(kernel, kPoints, stress, eps_p, strain,
                                    sf::FlowStressCache{cached, cached_at}, up, failure));
      for (int p = 0; p < kPoints; ++p) {
        if (up[p].eps_p > eps_p[p]) {
          ASSERT_EQ(cached_at[p], up[p].eps_p);
          const double exact = sf::flow_stress(law, up[p].eps_p);
          if (swift) {
            EXPECT_NEAR(cached[p], exact, 1e-13 * exact) << "step " << step << " point " << p;
          } else {
            EXPECT_EQ(cached[p], exact) << "step " << step << " point " << p;
          }
          const sf::Vec3& s = up[p].stress;
          const double mises =
              std::sqrt(s(0) * s(0) - s(0) * s(1) + s(1) * s(1) + 3.0 * s(2) * s(2));
          EXPECT_NEAR(mises / exact, 1.0, 1e-9) << "step " << step << " point " << p;
          ++checked;
        }
        stress[p] = up[p].stress;
        eps_p[p] = up[p].eps_p;
      }
    }
    EXPECT_GT(checked, 50 * kPoints);
  }
}
