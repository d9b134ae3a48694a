#pragma once
// The building blocks of Barlat's plane-stress yield functions (Yld89, Yld2000-2d), with their
// first and second derivatives. Both are sums of |X1 +- X2|-type terms of the principal values
// X1, X2 = m +- R of a linearly transformed stress X = (Xxx, Xyy, Xxy) (tensor shear), with
// m = (Xxx + Xyy) / 2 and R = sqrt(s), s = ((Xxx - Xyy) / 2)^2 + Xxy^2. Written in (m, s) the
// terms are smooth where the principal values coincide (R = 0), which the principal values
// themselves are not: the limits at small R are taken from Taylor series, so the derivatives stay
// accurate there.
#include <algorithm>
#include <cmath>

#include "core/types.hpp"

namespace sf {

/// A function of (m, s) with its first and second partial derivatives.
struct InvariantTerm {
  double value = 0.0;
  double d_m = 0.0, d_s = 0.0;
  double d_mm = 0.0, d_ms = 0.0, d_ss = 0.0;
};

/// The k-th derivative of h(u) = |u|^a (a >= 2): a (a - 1) ... (a - k + 1) |u|^(a - k) sgn(u)^k.
inline double power_derivative(double u, double a, int k) {
  double c = 1.0;
  for (int j = 0; j < k; ++j) {
    c *= a - j;
  }
  if (c == 0.0) {
    return 0.0;
  }
  const double m = std::pow(std::abs(u), a - k);
  return (k % 2 == 1 && u < 0.0) ? -c * m : c * m;
}

/// The values alone of the two terms below (the yield checks need no derivatives).
inline double symmetric_power_pair_value(double m, double s, double k, double a) {
  const double R = std::sqrt(std::max(s, 0.0));
  return std::pow(std::abs(k * m + R), a) + std::pow(std::abs(k * m - R), a);
}
inline double principal_difference_power_value(double s, double a) {
  return s > 0.0 ? std::pow(2.0, a) * std::pow(s, 0.5 * a) : 0.0;
}

/// P(m, s) = |k m + R|^a + |k m - R|^a, R = sqrt(s) (Yld2000-2d's phi'' with k = 3 and Yld89's
/// first two terms with k = 1). P is even in R, hence smooth in s. For R below 5e-3 |k m| the
/// divided differences of the derivatives are replaced by their Taylor series in R (two terms:
/// truncation and round-off both below about 1e-10 relative).
inline InvariantTerm symmetric_power_pair(double m, double s, double k, double a) {
  const double R = std::sqrt(std::max(s, 0.0));
  const double c = k * m;
  const double up = c + R;
  const double um = c - R;
  InvariantTerm t;
  t.value = symmetric_power_pair_value(m, s, k, a);
  const double h1p = power_derivative(up, a, 1);
  const double h1m = power_derivative(um, a, 1);
  const double h2p = power_derivative(up, a, 2);
  const double h2m = power_derivative(um, a, 2);
  t.d_m = k * (h1p + h1m);
  t.d_mm = k * k * (h2p + h2m);
  if (R < 5e-3 * std::abs(c)) {
    const double R2 = R * R;
    t.d_s = power_derivative(c, a, 2) + power_derivative(c, a, 4) * R2 / 6.0;
    t.d_ms = k * (power_derivative(c, a, 3) + power_derivative(c, a, 5) * R2 / 6.0);
    t.d_ss = power_derivative(c, a, 4) / 6.0 + power_derivative(c, a, 6) * R2 / 60.0;
  } else {
    t.d_s = (h1p - h1m) / (2.0 * R);
    t.d_ms = k * (h2p - h2m) / (2.0 * R);
    t.d_ss = (R * (h2p + h2m) - (h1p - h1m)) / (4.0 * R * R * R);
  }
  return t;
}

/// Q(s) = |2 R|^a = 2^a s^(a/2) (Yld2000-2d's phi' = |X1 - X2|^a, Yld89's |2 K2|^M); a >= 2. At
/// s = 0 the second derivative is infinite for 2 < a < 4 and is returned as 0 (it only steers
/// Newton's steps; the function and its gradient are exact).
inline InvariantTerm principal_difference_power(double s, double a) {
  InvariantTerm t;
  const double f = std::pow(2.0, a);
  t.value = principal_difference_power_value(s, a);
  if (s > 0.0) {
    t.d_s = f * 0.5 * a * std::pow(s, 0.5 * a - 1.0);
    t.d_ss = f * 0.5 * a * (0.5 * a - 1.0) * std::pow(s, 0.5 * a - 2.0);
  } else {
    t.d_s = a == 2.0 ? f : 0.0;
    t.d_ss = a == 4.0 ? f * 2.0 : 0.0;
  }
  return t;
}

/// Value, gradient and Hessian with respect to X = (Xxx, Xyy, Xxy) of a term given in (m, s).
struct TermInX {
  double value;
  Vec3 gradient;
  Mat3 hessian;
};

inline TermInX term_in_x(const InvariantTerm& t, const Vec3& X) {
  const Vec3 m_x(0.5, 0.5, 0.0);
  const double half_diff = 0.5 * (X(0) - X(1));
  const Vec3 s_x(half_diff, -half_diff, 2.0 * X(2));
  Mat3 s_xx;
  s_xx << 0.5, -0.5, 0.0, -0.5, 0.5, 0.0, 0.0, 0.0, 2.0;
  TermInX r;
  r.value = t.value;
  r.gradient = t.d_m * m_x + t.d_s * s_x;
  r.hessian = t.d_mm * m_x * m_x.transpose() +
              t.d_ms * (m_x * s_x.transpose() + s_x * m_x.transpose()) +
              t.d_ss * s_x * s_x.transpose() + t.d_s * s_xx;
  return r;
}

/// m and s of X.
inline double invariant_m(const Vec3& X) {
  return 0.5 * (X(0) + X(1));
}
inline double invariant_s(const Vec3& X) {
  const double h = 0.5 * (X(0) - X(1));
  return h * h + X(2) * X(2);
}

}  // namespace sf
