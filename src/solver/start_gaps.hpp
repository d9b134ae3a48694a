#pragma once
// Each blank node's gap to a tool at time 0, as node-on-surface contact sees it: shared by the
// start-up penetration check (run_estimate.hpp) and the tools' clearance line
// (tool_mesh_report.hpp), so that both measure a blank of several thicknesses alike.
#include "model/model.hpp"

namespace sf {

/// mm per blank node: its distance to the tool of `contact` standing where its motion puts it at
/// time 0 (the pair's own search, within its cutoff), less the node's initial half thickness
/// (initial_half_thickness). Negative: the node's face is inside the tool. NaN for a node with
/// no tool triangle within the cutoff.
VectorX start_gaps(const Model& model, const ContactInterface& contact);

}  // namespace sf
