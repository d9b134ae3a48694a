#include "material/anisotropy_fit.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/errors.hpp"

namespace sf {
namespace {

using Vec8 = Eigen::Matrix<double, 8, 1>;
using Mat8 = Eigen::Matrix<double, 8, 8>;

// Unit uniaxial stress at `angle` to the rolling direction: (c^2, s^2, c s).
Vec3 uniaxial_direction(double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  return {c * c, s * s, c * s};
}

// The width strain rate of uniaxial tension at `angle` for the plastic strain direction g
// (engineering shear): s^2 g0 + c^2 g1 - c s g2; the thickness rate is -(g0 + g1).
double width_rate(const Vec3& g, double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  return s * s * g(0) + c * c * g(1) - c * s * g(2);
}

// The Lankford equation d_eps_width - r d_eps_thickness = 0.
double lankford_residual(const Vec3& g, double angle, double r) {
  return width_rate(g, angle) + r * (g(0) + g(1));
}

// The eight equations of the Yld2000-2d fit (Barlat et al. 2003, sect. 4), each O(1).
Vec8 fit_residual(const Yld2000Criterion& c, const Yld2000Data& d) {
  const double pi = std::acos(-1.0);
  const double angles[3] = {0.0, 0.25 * pi, 0.5 * pi};
  const double sigma[3] = {1.0, d.sigma45 / d.sigma0, d.sigma90 / d.sigma0};
  const double r[3] = {d.r0, d.r45, d.r90};
  Vec8 f;
  for (int i = 0; i < 3; ++i) {
    const EquivalentStress e = equivalent_stress(c, sigma[i] * uniaxial_direction(angles[i]));
    f(i) = e.value - 1.0;
    f(4 + i) = lankford_residual(e.gradient, angles[i], r[i]);
  }
  const EquivalentStress b = equivalent_stress(c, (d.sigma_b / d.sigma0) * Vec3(1.0, 1.0, 0.0));
  f(3) = b.value - 1.0;
  f(7) = b.gradient(1) - d.r_b * b.gradient(0);
  return f;
}

std::string fmt_num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

}  // namespace

double uniaxial_yield_ratio(const YieldCriterion& criterion, double angle) {
  return 1.0 / equivalent_stress_value(criterion, uniaxial_direction(angle)) *
         equivalent_stress_value(criterion, Vec3(1.0, 0.0, 0.0));
}

double lankford_coefficient(const YieldCriterion& criterion, double angle) {
  const Vec3 g = equivalent_stress(criterion, uniaxial_direction(angle)).gradient;
  return width_rate(g, angle) / -(g(0) + g(1));
}

double equibiaxial_yield_ratio(const YieldCriterion& criterion) {
  return equivalent_stress_value(criterion, Vec3(1.0, 0.0, 0.0)) /
         equivalent_stress_value(criterion, Vec3(1.0, 1.0, 0.0));
}

double equibiaxial_r_value(const YieldCriterion& criterion) {
  const Vec3 g = equivalent_stress(criterion, Vec3(1.0, 1.0, 0.0)).gradient;
  return g(1) / g(0);
}

Yld2000Criterion fit_yld2000(const Yld2000Data& d, double a, const char* what) {
  const std::string name(what);
  for (const double x : {d.sigma0, d.sigma45, d.sigma90, d.sigma_b, d.r0, d.r45, d.r90, d.r_b}) {
    if (!(x > 0.0) || !std::isfinite(x)) {
      throw InputError(name +
                       ": Yld2000-2d is fitted to yield stresses and r-values that are "
                       "finite and > 0 (sigma0, sigma45, sigma90, sigma_b, r0, r45, r90, "
                       "r_b)");
    }
  }
  Yld2000Criterion c;
  c.a = a;
  Vec8 f = fit_residual(c, d);
  constexpr int kMaxIterations = 100;
  for (int it = 0; it < kMaxIterations && f.norm() > 1e-12; ++it) {
    // Jacobian by central differences (the residual is smooth in alpha; its derivatives only
    // steer the steps, the converged coefficients solve the equations to 1e-12).
    Mat8 J;
    for (int j = 0; j < 8; ++j) {
      const double h = 1e-6 * std::max(1.0, std::abs(c.alpha[j]));
      Yld2000Criterion cp = c, cm = c;
      cp.alpha[j] += h;
      cm.alpha[j] -= h;
      J.col(j) = (fit_residual(cp, d) - fit_residual(cm, d)) / (2.0 * h);
    }
    const Vec8 step = J.fullPivLu().solve(-f);
    if (!step.allFinite()) {
      break;
    }
    // Backtracking: the first of step, step/2, ... that lowers the residual.
    double t = 1.0;
    for (int k = 0; k < 30; ++k, t *= 0.5) {
      Yld2000Criterion trial = c;
      for (int j = 0; j < 8; ++j) {
        trial.alpha[j] += t * step(j);
      }
      const Vec8 ft = fit_residual(trial, d);
      if (ft.allFinite() && ft.norm() < f.norm()) {
        c = trial;
        f = ft;
        break;
      }
    }
  }
  if (!(f.norm() <= 1e-12)) {
    throw InputError(name + ": no Yld2000-2d coefficients (exponent " + fmt_num(a) +
                     ") reproduce these yield stresses and r-values (closest residual " +
                     fmt_num(f.norm()) + "): check the data, or give alpha1..alpha8 directly");
  }
  return c;
}

Yld89Criterion fit_yld89(double r0, double r45, double r90, double M, const char* what) {
  const std::string name(what);
  for (const double r : {r0, r45, r90}) {
    if (!(r > 0.0) || !std::isfinite(r)) {
      throw InputError(name + ": Yld89 is fitted to r0, r45, r90 finite and > 0");
    }
  }
  Yld89Criterion y;
  y.M = M;
  y.a = 2.0 - 2.0 * std::sqrt(r0 * r90 / ((1.0 + r0) * (1.0 + r90)));
  y.c = 2.0 - y.a;
  y.h = std::sqrt(r0 * (1.0 + r90) / ((1.0 + r0) * r90));
  // r45 grows with p: bisection on log p.
  const double pi = std::acos(-1.0);
  const auto miss = [&](double p) {
    Yld89Criterion t = y;
    t.p = p;
    return lankford_coefficient(t, 0.25 * pi) - r45;
  };
  double lo = 1e-3, hi = 1e3;
  if (!(miss(lo) < 0.0 && miss(hi) > 0.0)) {
    throw InputError(name + ": no Yld89 coefficient p reaches r45 = " + fmt_num(r45) +
                     " with r0 = " + fmt_num(r0) + ", r90 = " + fmt_num(r90));
  }
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
    const double mid = std::sqrt(lo * hi);
    (miss(mid) < 0.0 ? lo : hi) = mid;
  }
  y.p = 0.5 * (lo + hi);
  return y;
}

}  // namespace sf
