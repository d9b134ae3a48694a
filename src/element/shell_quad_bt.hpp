#pragma once
// Internal forces of the Belytschko-Lin-Tsay quad (Belytschko, Lin & Tsay 1984; Hallquist,
// LS-DYNA Theory Manual) with viscous or stiffness hourglass control (Flanagan & Belytschko
// 1981), one share of an element pass (shell_forces.hpp runs the pass).
#include "element/element_pass.hpp"
#include "element/shell_part.hpp"

namespace sf {

/// Quads [begin, end) of `part` (of one material; begin best a multiple of kBlockLanes): their
/// corner forces and moments into out.corners, their state updated, their works summed into `out`,
/// their critical steps into out.element_dt (when not null). Stops at the first failing element,
/// recorded in out.failure. Conventions: compute_shell_internal_forces.
void compute_bt_quad_forces(const ShellPart& part, const ShellMaterial& material,
                            const ElementInputs& in, ShellState& state, int begin, int end,
                            ElementOutputs& out);

}  // namespace sf
