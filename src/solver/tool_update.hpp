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

/// N mm, the torque the press applies to turn tool `tool` against the blank: minus the moment
/// of the blank's forces on it about the axis of its motion in effect, through its pivot, both
/// where the tool stands (positive when the blank resists a turn in the positive sense).
double press_torque(const Model& model, int tool, const ToolState& state);

}  // namespace sf
