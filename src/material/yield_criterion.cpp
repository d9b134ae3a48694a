#include "material/yield_criterion.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "material/plane_stress.hpp"
#include "material/two_invariant_form.hpp"

namespace sf {
namespace {

// sigma_eq = sqrt(s^T P s) of a quadratic criterion (von Mises, Hill48).
EquivalentStress quadratic(const Mat3& P, const Vec3& s) {
  EquivalentStress r;
  const Vec3 Ps = P * s;
  r.value = std::sqrt(std::max(s.dot(Ps), 0.0));
  if (r.value > 0.0) {
    r.gradient = Ps / r.value;
    r.hessian = (P - r.gradient * r.gradient.transpose()) / r.value;
  }
  return r;
}

Mat3 hill_matrix(const Hill48Coefficients& k) {
  Mat3 P;
  P << k.G + k.H, -k.H, 0.0, -k.H, k.F + k.H, 0.0, 0.0, 0.0, 2.0 * k.N;
  return P;
}

// phi(s) = sum over terms of the term's function of X = L s: value, gradient and Hessian in s.
struct PhiSum {
  double value = 0.0;
  Vec3 gradient = Vec3::Zero();
  Mat3 hessian = Mat3::Zero();

  void add(const InvariantTerm& t, const Mat3& L, const Vec3& X, double weight) {
    const TermInX x = term_in_x(t, X);
    value += weight * x.value;
    gradient += weight * (L.transpose() * x.gradient);
    hessian += weight * (L.transpose() * x.hessian * L);
  }
};

// sigma_eq = (phi / 2)^(1/a) from phi = 2 sigma_eq^a and its derivatives.
EquivalentStress from_phi(const PhiSum& phi, double a) {
  EquivalentStress r;
  if (!(phi.value > 0.0)) {
    return r;
  }
  r.value = std::pow(0.5 * phi.value, 1.0 / a);
  const double f = r.value / (a * phi.value);
  r.gradient = f * phi.gradient;
  r.hessian =
      f * (phi.hessian + (1.0 / a - 1.0) / phi.value * phi.gradient * phi.gradient.transpose());
  return r;
}

Mat3 yld2000_l1(const std::array<double, 8>& al) {
  Mat3 L;
  L << 2.0 * al[0], -al[0], 0.0, -al[1], 2.0 * al[1], 0.0, 0.0, 0.0, 3.0 * al[6];
  return L / 3.0;
}

Mat3 yld2000_l2(const std::array<double, 8>& al) {
  const double a3 = al[2], a4 = al[3], a5 = al[4], a6 = al[5];
  Mat3 L;
  L << -2.0 * a3 + 2.0 * a4 + 8.0 * a5 - 2.0 * a6, a3 - 4.0 * a4 - 4.0 * a5 + 4.0 * a6, 0.0,
      4.0 * a3 - 4.0 * a4 - 4.0 * a5 + a6, -2.0 * a3 + 8.0 * a4 + 2.0 * a5 - 2.0 * a6, 0.0, 0.0,
      0.0, 9.0 * al[7];
  return L / 9.0;
}

EquivalentStress yld2000(const Yld2000Criterion& c, const Vec3& s) {
  const Mat3 L1 = yld2000_l1(c.alpha);
  const Mat3 L2 = yld2000_l2(c.alpha);
  const Vec3 X1 = L1 * s;
  const Vec3 X2 = L2 * s;
  PhiSum phi;
  phi.add(principal_difference_power(invariant_s(X1), c.a), L1, X1, 1.0);
  phi.add(symmetric_power_pair(invariant_m(X2), invariant_s(X2), 3.0, c.a), L2, X2, 1.0);
  return from_phi(phi, c.a);
}

EquivalentStress yld89(const Yld89Criterion& c, const Vec3& s) {
  Mat3 L = Mat3::Zero();
  L(0, 0) = 1.0;
  L(1, 1) = c.h;
  L(2, 2) = c.p;
  const Vec3 X = L * s;
  const double m = invariant_m(X);
  const double sq = invariant_s(X);
  PhiSum phi;
  phi.add(symmetric_power_pair(m, sq, 1.0, c.M), L, X, c.a);
  phi.add(principal_difference_power(sq, c.M), L, X, c.c);
  return from_phi(phi, c.M);
}

}  // namespace

EquivalentStress equivalent_stress(const YieldCriterion& criterion, const Vec3& stress) {
  struct Visitor {
    const Vec3& s;
    EquivalentStress operator()(const VonMisesCriterion&) const {
      return quadratic(hill_matrix(hill48_coefficients(1.0, 1.0, 1.0)), s);
    }
    EquivalentStress operator()(const Hill48Criterion& c) const {
      return quadratic(hill_matrix(c.k), s);
    }
    EquivalentStress operator()(const Yld2000Criterion& c) const { return yld2000(c, s); }
    EquivalentStress operator()(const Yld89Criterion& c) const { return yld89(c, s); }
  };
  return std::visit(Visitor{stress}, criterion);
}

double equivalent_stress_value(const YieldCriterion& criterion, const Vec3& s) {
  struct Visitor {
    const Vec3& s;
    double operator()(const VonMisesCriterion&) const {
      return std::sqrt(std::max(s(0) * s(0) - s(0) * s(1) + s(1) * s(1) + 3.0 * s(2) * s(2), 0.0));
    }
    double operator()(const Hill48Criterion& c) const {
      return std::sqrt(std::max(s.dot(hill_matrix(c.k) * s), 0.0));
    }
    double operator()(const Yld2000Criterion& c) const {
      const Vec3 X1 = yld2000_l1(c.alpha) * s;
      const Vec3 X2 = yld2000_l2(c.alpha) * s;
      const double phi = principal_difference_power_value(invariant_s(X1), c.a) +
                         symmetric_power_pair_value(invariant_m(X2), invariant_s(X2), 3.0, c.a);
      return std::pow(0.5 * phi, 1.0 / c.a);
    }
    double operator()(const Yld89Criterion& c) const {
      const Vec3 X(s(0), c.h * s(1), c.p * s(2));
      const double f = c.a * symmetric_power_pair_value(invariant_m(X), invariant_s(X), 1.0, c.M) +
                       c.c * principal_difference_power_value(invariant_s(X), c.M);
      return std::pow(0.5 * f, 1.0 / c.M);
    }
  };
  return std::visit(Visitor{s}, criterion);
}

const char* criterion_name(const YieldCriterion& criterion) {
  struct Visitor {
    const char* operator()(const VonMisesCriterion&) const { return "von Mises"; }
    const char* operator()(const Hill48Criterion&) const { return "Hill48"; }
    const char* operator()(const Yld2000Criterion&) const { return "Yld2000-2d"; }
    const char* operator()(const Yld89Criterion&) const { return "Yld89"; }
  };
  return std::visit(Visitor{}, criterion);
}

namespace {

void check_parameters(const YieldCriterion& criterion, const std::string& name) {
  if (const auto* y = std::get_if<Yld2000Criterion>(&criterion)) {
    for (const double a : y->alpha) {
      if (!std::isfinite(a)) {
        throw InputError(name + ": Yld2000-2d coefficients alpha1..alpha8 must be finite");
      }
    }
    if (!(y->a >= 2.0) || !std::isfinite(y->a)) {
      throw InputError(name + ": the Yld2000-2d exponent must be >= 2 (got " +
                       std::to_string(y->a) + "; 8 for aluminium, 6 for steel)");
    }
  } else if (const auto* b = std::get_if<Yld89Criterion>(&criterion)) {
    if (!(b->a >= 0.0) || !(b->c >= 0.0) || !(b->h > 0.0) || !(b->p > 0.0) ||
        !std::isfinite(b->a + b->c + b->h + b->p)) {
      throw InputError(name + ": Yld89 needs a >= 0, c >= 0, h > 0 and p > 0 (got a = " +
                       std::to_string(b->a) + ", c = " + std::to_string(b->c) +
                       ", h = " + std::to_string(b->h) + ", p = " + std::to_string(b->p) + ")");
    }
    if (!(b->M >= 2.0) || !std::isfinite(b->M)) {
      throw InputError(name + ": the Yld89 exponent M must be >= 2 (got " + std::to_string(b->M) +
                       "; 8 for aluminium, 6 for steel)");
    }
  }
}

}  // namespace

void check_yield_criterion(const YieldCriterion& criterion, const char* what) {
  const std::string name(what);
  check_parameters(criterion, name);
  // Positive in every direction and convex (the Hessian of a convex, degree-one homogeneous
  // function is positive semi-definite), on a sample of stress directions.
  constexpr int kAzimuths = 48;
  constexpr int kPolars = 24;
  const double pi = std::acos(-1.0);
  // The grid holds the pure shear (polar 0), the in-plane directions (polar pi/2) and among them
  // uniaxial and equibiaxial tension, where a degenerate criterion vanishes first.
  for (int i = 0; i <= kPolars; ++i) {
    const double polar = pi * i / kPolars;
    for (int j = 0; j < kAzimuths; ++j) {
      const double azimuth = 2.0 * pi * j / kAzimuths;
      const Vec3 s(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                   std::cos(polar));
      const EquivalentStress e = equivalent_stress(criterion, s);
      if (!(e.value > 1e-8) || !std::isfinite(e.value)) {
        throw InputError(name + ": the " + std::string(criterion_name(criterion)) +
                         " equivalent stress is not positive for the stress direction (" +
                         std::to_string(s(0)) + ", " + std::to_string(s(1)) + ", " +
                         std::to_string(s(2)) + "): check its coefficients");
      }
      const double smallest = Eigen::SelfAdjointEigenSolver<Mat3>(e.hessian).eigenvalues()(0);
      if (smallest < -1e-8 * e.hessian.norm()) {
        throw InputError(name + ": the " + std::string(criterion_name(criterion)) +
                         " yield surface is not convex near the stress direction (" +
                         std::to_string(s(0)) + ", " + std::to_string(s(1)) + ", " +
                         std::to_string(s(2)) + "): check its coefficients");
      }
    }
  }
}

}  // namespace sf
