#include "model/rigid_tool_motion.hpp"

#include <cmath>
#include <stdexcept>

namespace sf {

RigidToolMotion::RigidToolMotion(const MotionConfig& config)
    : type_(config.type),
      direction_(Vec3(config.direction[0], config.direction[1], config.direction[2]).normalized()) {
  if (type_ == MotionConfig::Type::force) {
    throw std::logic_error("RigidToolMotion: a force-controlled tool is a ForceControlledTool");
  }
  if (type_ != MotionConfig::Type::fixed) {
    curve_ = LoadCurve(config.curve.times, config.curve.values);
  }
}

double RigidToolMotion::travel(double t) const {
  switch (type_) {
    case MotionConfig::Type::velocity:
      return curve_.integral(t);
    case MotionConfig::Type::displacement:
      return curve_.value(t);
    case MotionConfig::Type::fixed:
    case MotionConfig::Type::force:
      break;
  }
  return 0.0;
}

double RigidToolMotion::speed(double t) const {
  switch (type_) {
    case MotionConfig::Type::velocity:
      return curve_.value(t);
    case MotionConfig::Type::displacement: {
      const double h = 1e-9;  // s; the curve is piecewise linear, so this is its slope
      return (curve_.value(t + h) - curve_.value(t)) / h;
    }
    case MotionConfig::Type::fixed:
    case MotionConfig::Type::force:
      break;
  }
  return 0.0;
}

std::optional<double> RigidToolMotion::time_at_travel(double target) const {
  if (!moves()) {
    return std::nullopt;
  }
  // Bracket: double the upper bound until the travel is reached.
  double low = 0.0;
  double high = 1e-6;
  while (travel(high) < target) {
    low = high;
    high *= 2.0;
    if (high > kTravelSearchEnd) {
      return std::nullopt;
    }
  }
  for (int i = 0; i < 200 && high - low > 1e-12 * high; ++i) {
    const double mid = 0.5 * (low + high);
    (travel(mid) < target ? low : high) = mid;
  }
  return high;
}

}  // namespace sf
