#pragma once
// A piecewise-linear function through points (x_k, y_k), x strictly increasing: linear between
// the points and held at the first and last values beyond them. One rule for the load curves,
// the friction tables and the forming limit curves.
#include <array>
#include <cstddef>
#include <span>

namespace sf {

/// y at `at` for n >= 1 points read by x(k) and y(k). A NaN `at` gives the first value. No
/// allocation.
template <class XAt, class YAt>
double piecewise_linear(std::size_t n, XAt x, YAt y, double at) {
  if (!(at > x(0))) {
    return y(0);
  }
  if (!(at < x(n - 1))) {
    return y(n - 1);
  }
  std::size_t lo = 0, hi = n - 1;  // x(lo) <= at < x(hi), until they are neighbours
  while (hi - lo > 1) {
    const std::size_t mid = lo + (hi - lo) / 2;
    (x(mid) <= at ? lo : hi) = mid;
  }
  const double s = (at - x(lo)) / (x(hi) - x(lo));
  return y(lo) + s * (y(hi) - y(lo));
}

/// The same through abscissae x and values y (the same length, at least 1).
inline double piecewise_linear(std::span<const double> x, std::span<const double> y, double at) {
  return piecewise_linear(
      x.size(), [&](std::size_t k) { return x[k]; }, [&](std::size_t k) { return y[k]; }, at);
}

/// The same through (x, y) points.
inline double piecewise_linear(std::span<const std::array<double, 2>> points, double at) {
  return piecewise_linear(
      points.size(), [&](std::size_t k) { return points[k][0]; },
      [&](std::size_t k) { return points[k][1]; }, at);
}

}  // namespace sf
