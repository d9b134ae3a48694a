#pragma once
// The forces on the blank at the current state of an explicit run: applied loads, the elements'
// internal forces and the tools' contact forces.
#include "element/shell_forces.hpp"
#include "model/model.hpp"
#include "solver/solution_state.hpp"

namespace sf {

/// External, internal and contact forces at the current state (state.x, state.v, dt in s: the
/// step just taken, 0 before the first); returns the element pass's hourglass and plastic work
/// (N mm). Element and contact wall times are added to state.times.
ShellForceResult compute_forces(const Model& model, SolutionState& state, double dt);

}  // namespace sf
