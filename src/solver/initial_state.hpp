#pragma once
// The state an explicit run starts from.
#include "model/model.hpp"
#include "solver/solution_state.hpp"

namespace sf {

/// The blank at rest in its mesh positions, or moving with the case's initial velocities (the
/// whole-step velocities v(0), constraints applied), with its shell state, directors and tools
/// sized; the kinetic energy of v(0) is the initial kinetic energy.
SolutionState make_initial_state(const Model& model);

}  // namespace sf
