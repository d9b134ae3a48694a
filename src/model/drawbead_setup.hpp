#pragma once
// The case's [[drawbeads]] made into the model's bead lines (docs/drawbeads.md).
#include "casefile/case_config.hpp"
#include "model/model.hpp"

namespace sf {

/// Builds model.drawbeads from config.drawbeads, after the tools and contact pairs: each line
/// moved with its tool's touch shift, cut into pieces no longer than a quarter of its width and
/// laid on the tool's surface (each point moved to the nearest point of the surface, whose
/// normal it takes; the points where it runs straight on a flat face dropped again); its force
/// curves from the case or from the round bead's geometry; its
/// spring from the tool's contact stiffness. Throws InputError (naming the case, the bead and
/// the point) for a line that misses the tool by more than half its width, or a round bead
/// whose sheet is not known (a blank of several parts with no `thickness`, an elastic blank
/// with no `flow_stress`).
void set_up_drawbeads(const CaseConfig& config, Model& model);

}  // namespace sf
