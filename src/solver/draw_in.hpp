#pragma once
// Draw-in: how far the blank's edge has been pulled in, measured at the nodes of a [[draw_in]]
// group along its direction (NUMISHEET's DX, DY, DD). Used by the run summary and the history.
#include "casefile/case_config.hpp"
#include "core/types.hpp"
#include "model/model.hpp"

namespace sf {

/// Draw-in (mm) of `draw_in` at the blank node positions `x` (mm, column per node): the mean over
/// the group's nodes of (x - reference) . direction (the direction is unit length, read from the
/// case). Positive when the edge moves inward, as the case's direction points inward.
/// NaN when a trim removed every node of the group.
double measure_draw_in(const Model& model, const DrawInConfig& draw_in, const Matrix3X& x);

}  // namespace sf
