#pragma once
// The prescribed rigid motion of a tool: a translation along a fixed direction, given as a
// velocity or a displacement curve over time. (A force-controlled tool is a ForceControlledTool;
// its RigidToolMotion is fixed.)
#include <optional>

#include "casefile/case_config.hpp"
#include "core/types.hpp"
#include "model/load_curve.hpp"

namespace sf {

class RigidToolMotion {
 public:
  RigidToolMotion() = default;
  explicit RigidToolMotion(const MotionConfig& config);

  bool moves() const { return type_ != MotionConfig::Type::fixed; }
  /// Travel along the direction at time t (mm).
  double travel(double t) const;
  /// Speed along the direction at time t (mm/s); for a displacement curve, the slope.
  double speed(double t) const;
  Vec3 displacement(double t) const { return travel(t) * direction_; }
  const Vec3& direction() const { return direction_; }
  /// The earliest time (s) at which the travel reaches `target` (mm), found by bisection on the
  /// monotone travel to 1e-12 relative; nullopt if it does not within kTravelSearchEnd (a fixed
  /// tool, a held speed of zero, a displacement curve that stops short).
  std::optional<double> time_at_travel(double target) const;
  /// s, how far time_at_travel looks.
  static constexpr double kTravelSearchEnd = 1e6;

 private:
  MotionConfig::Type type_ = MotionConfig::Type::fixed;
  Vec3 direction_ = Vec3(0.0, 0.0, -1.0);
  LoadCurve curve_;
};

}  // namespace sf
