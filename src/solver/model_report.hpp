#pragma once
// What `sheetform check` and the start of a run print about the model: the case's units, the
// analysis, the blank and its element formulation, the material, the constraints and loads (with
// the direction each pressure pushes), the tools and contacts, and the time control that applies.
#include <string>

#include "casefile/unit_system.hpp"
#include "element/shell_part.hpp"
#include "model/model.hpp"

namespace sf {

/// The element formulation a shell part holds: its element types, the through-thickness rule and
/// the hourglass control of its quadrilaterals. static_step: as the implicit static step uses
/// it (the stiffness hourglass form, whatever the part holds: viscous forces have no static
/// stiffness).
std::string describe_shell_formulation(const ShellPart& part, bool static_step);

/// Prints the case and the model built from it (log_info), in the case's units.
void print_model(const CaseConfig& config, const Model& model);

}  // namespace sf
