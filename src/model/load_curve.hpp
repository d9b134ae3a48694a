#pragma once
// A piecewise-linear function of time, held constant beyond its last point.
#include <vector>

namespace sf {

class LoadCurve {
 public:
  LoadCurve() = default;
  /// times (s) strictly increasing, values in the driven quantity's unit; at least one point.
  LoadCurve(std::vector<double> times, std::vector<double> values);

  /// The value at time t (s): linear between points, the first value before the first point and
  /// the last value after the last one.
  double value(double t) const;
  /// The exact integral of value() from 0 to t (value-unit x s).
  double integral(double t) const;
  bool empty() const { return times_.empty(); }
  /// The points' abscissae and values.
  const std::vector<double>& times() const { return times_; }
  const std::vector<double>& values() const { return values_; }

 private:
  std::vector<double> times_;
  std::vector<double> values_;
};

}  // namespace sf
