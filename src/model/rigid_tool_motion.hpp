#pragma once
// The prescribed rigid motion of a tool: a translation along a fixed direction, given as a
// velocity or a displacement curve over time, and a turn about an axis through a pivot, given as
// an angle curve (a flanging steel, a cam). (A force-controlled tool is a ForceControlledTool;
// its RigidToolMotion is fixed.)
#include <optional>

#include "casefile/case_config.hpp"
#include "contact/tool_placement.hpp"
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
  bool turns() const { return !angle_.empty(); }
  /// rad, the turn about axis() at time t (0 for a tool that does not turn).
  double angle(double t) const { return turns() ? angle_.value(t) : 0.0; }
  /// rad/s, the rate of the turn at time t (the angle curve's slope).
  double angular_speed(double t) const;
  const Vec3& axis() const { return axis_; }    ///< unit, in the mesh's coordinates
  const Vec3& pivot() const { return pivot_; }  ///< mm, a point of the axis, as meshed
  /// Where the tool moving by this motion from time 0, as meshed, stands at t: turned about the
  /// axis through the pivot, then moved by the travel.
  ToolPlacement placement(double t) const;
  /// Moves the pivot with a mesh moved by `shift` (mm): a tool placed to touch.
  void move_pivot(const Vec3& shift) { pivot_ += shift; }
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
  LoadCurve angle_;  ///< rad against s; empty: no turn
  Vec3 axis_ = Vec3::UnitY();
  Vec3 pivot_ = Vec3::Zero();
};

}  // namespace sf
