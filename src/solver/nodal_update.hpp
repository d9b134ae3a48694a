#pragma once
// The central-difference update of the blank's nodes: velocities from the force balance, the
// velocity conditions (prescribed motions), positions (docs/time-integration.md).
#include "model/model.hpp"
#include "solver/solution_state.hpp"

namespace sf {

/// v(n+1/2) = v(n-1/2) + weight (M^-1 (f_ext + f_contact - f_int) - c v(n-1/2)), rotations alike,
/// then the constraints; weight (s) from velocity_update_weight. Throws InstabilityError naming
/// the first node whose velocity is not finite.
void update_velocities(const Model& model, SolutionState& state, double weight);

/// Holds the prescribed components at their velocities over the step [t, t + dt] (s); returns the
/// work (N mm) of the reactions that do so.
double apply_velocity_conditions(const Model& model, SolutionState& state, double weight,
                                 double dt);

/// x(n+1) = x(n) + dt v(n+1/2), the rotation vector alike; the clock and the cycle count advance.
void update_positions(SolutionState& state, double dt);

}  // namespace sf
