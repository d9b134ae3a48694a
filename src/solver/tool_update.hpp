#pragma once
// The rigid tools' positions over one explicit step.
#include "model/model.hpp"
#include "solver/solution_state.hpp"

namespace sf {

/// Moves the tools to their positions at state.time (the step's end), keeping the old positions
/// and forces for the work increment. A force-controlled tool takes the same central-difference
/// step as the blank's nodes (weight, dt in s) from its force and the blank's reaction at
/// time_before (s), the step's start.
void move_tools(const Model& model, SolutionState& state, double time_before, double weight,
                double dt);

}  // namespace sf
