#include "model/rigid_tool_motion.hpp"

#include <cmath>
#include <numbers>
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
  if (config.turns()) {
    std::vector<double> radians = config.angle.values;
    for (double& a : radians) {
      a *= std::numbers::pi / 180.0;
    }
    angle_ = LoadCurve(config.angle.times, std::move(radians));
    axis_ = Vec3(config.axis[0], config.axis[1], config.axis[2]).normalized();
    pivot_ = Vec3(config.pivot[0], config.pivot[1], config.pivot[2]);
  }
}

ToolPlacement RigidToolMotion::placement(double t) const {
  if (!turns()) {
    return {Mat3::Identity(), displacement(t)};
  }
  const Mat3 turn = rotation_about(axis_, angle(t));
  return {turn, Vec3(turn * -pivot_ + pivot_ + displacement(t))};
}

double RigidToolMotion::angular_speed(double t) const {
  if (!turns()) {
    return 0.0;
  }
  const double h = 1e-9;  // s; the curve is piecewise linear, so this is its slope
  return (angle_.value(t + h) - angle_.value(t)) / h;
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
