#pragma once
// The central-difference update with a variable time step (Belytschko, Liu & Moran, Nonlinear
// Finite Elements for Continua and Structures, 2000, sect. 6.2.1, box 6.1):
//   v(n+1/2) = v(n-1/2) + (dt(n-1/2) + dt(n+1/2)) / 2 * a(n),   x(n+1) = x(n) + dt(n+1/2) v(n+1/2).
// A run starts from v(0): the first half step is v(1/2) = v(0) + dt/2 a(0).

namespace sf {

/// The weight of a(n) in the velocity update (s): dt and dt_previous are the steps after and
/// before time n (s); dt_previous = 0 marks the first step.
inline double velocity_update_weight(double dt, double dt_previous) {
  return dt_previous > 0.0 ? 0.5 * (dt_previous + dt) : 0.5 * dt;
}

}  // namespace sf
