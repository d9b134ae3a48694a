#include "model/load_curve.hpp"

#include "core/piecewise_linear.hpp"

#include <algorithm>
#include <stdexcept>

namespace sf {

LoadCurve::LoadCurve(std::vector<double> times, std::vector<double> values)
    : times_(std::move(times)), values_(std::move(values)) {
  if (times_.empty() || times_.size() != values_.size()) {
    throw std::invalid_argument("LoadCurve: needs matching, non-empty times and values");
  }
}

double LoadCurve::value(double t) const {
  if (times_.empty()) {
    return 0.0;
  }
  return piecewise_linear(times_, values_, t);
}

double LoadCurve::integral(double t) const {
  if (times_.empty() || t <= 0.0) {
    return 0.0;
  }
  // Segments: [0, t0] at the first value, then the trapezoids, then the last value held.
  double sum = 0.0;
  double previous_time = 0.0;
  double previous_value = value(0.0);
  for (std::size_t i = 0; i < times_.size(); ++i) {
    if (times_[i] <= 0.0) {
      continue;
    }
    const double end = std::min(times_[i], t);
    const double end_value = value(end);
    sum += 0.5 * (previous_value + end_value) * (end - previous_time);
    previous_time = end;
    previous_value = end_value;
    if (times_[i] >= t) {
      return sum;
    }
  }
  return sum + previous_value * (t - previous_time);
}

}  // namespace sf
