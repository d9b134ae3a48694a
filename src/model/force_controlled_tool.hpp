#pragma once
// A tool driven by a force instead of a prescribed motion (the blank holder of a press cushion): a
// rigid body of mass M that moves along a fixed unit axis d only, pushed by the applied force
// F(t) along d, by the blank's force on it R (its component along d) and held back by
// mass-proportional damping c:
//   M a = F(t) + R . d - c M v.
// The travel s along d and the velocity v are integrated by the driver with the blank's
// central-difference step (velocity at the half step, travel at whole steps), in the same cycle
// as the blank's positions (docs/time-integration.md, "Force-controlled tools").
#include "core/types.hpp"
#include "model/load_curve.hpp"

namespace sf {

class ForceControlledTool {
 public:
  ForceControlledTool() = default;
  /// direction: the axis (normalised here); force: N against the time (s) or, of_travel, against
  /// the tool's travel (mm: a gas spring, a cushion); mass: tonne (> 0); damping: 1/s.
  ForceControlledTool(const Vec3& direction, LoadCurve force, double mass, double damping,
                      bool of_travel = false);

  const Vec3& direction() const { return direction_; }
  double mass() const { return mass_; }        ///< tonne
  double damping() const { return damping_; }  ///< 1/s
  /// Whether the force is a function of the travel (else of the time).
  bool of_travel() const { return of_travel_; }
  /// The applied force along the direction at time t (s) and travel s (mm), N.
  double applied_force(double t, double travel = 0.0) const {
    return force_.value(of_travel_ ? travel : t);
  }
  /// N/mm, the steepest slope of a force of the travel (0 for a force of the time): the spring
  /// it adds to the tool's stability bound.
  double stiffness() const;

  /// The rate of the velocity (mm/s^2) at time t: u = (F(t) + R . d) / M - c v, with R the
  /// blank's force on the tool (N) and v the velocity the damping acts on (mm/s; the half-step
  /// velocity v(n-1/2), as for the blank's nodes).
  double rate(double t, const Vec3& reaction, double velocity, double travel = 0.0) const {
    return (applied_force(t, travel) + reaction.dot(direction_)) / mass_ - damping_ * velocity;
  }

  /// One central-difference step from time t(n) (s) with the reaction R(n) (N):
  ///   v(n+1/2) = v(n-1/2) + weight u(n),   s(n+1) = s(n) + dt v(n+1/2),
  /// weight = (dt(n-1/2) + dt(n+1/2)) / 2 (dt / 2 on the first step, from v(0)). `velocity`
  /// (mm/s) and `travel` (mm) are updated in place.
  void step(double t, const Vec3& reaction, double weight, double dt, double& velocity,
            double& travel) const;

  /// The whole-step velocity v(n+1) = v(n+1/2) + dt/2 u(n+1) (mm/s) at the end of a step of size
  /// dt (s), from the force and reaction at t(n+1): the velocity the kinetic energy is taken at.
  double whole_step_velocity(double t, const Vec3& reaction, double half_step_velocity, double dt,
                             double travel = 0.0) const {
    return half_step_velocity + 0.5 * dt * rate(t, reaction, half_step_velocity, travel);
  }

 private:
  Vec3 direction_ = Vec3(0.0, 0.0, -1.0);
  LoadCurve force_;
  double mass_ = 0.0;
  double damping_ = 0.0;
  bool of_travel_ = false;
};

}  // namespace sf
