#pragma once
// Internal forces of the Belytschko-Lin-Tsay quad (Belytschko, Lin & Tsay 1984; Hallquist,
// LS-DYNA Theory Manual) with viscous or stiffness hourglass control (Flanagan & Belytschko
// 1981): a formulation policy of the element loop (element_loop.hpp).
#include "element/element_block.hpp"
#include "element/element_pass.hpp"
#include "element/shell_part.hpp"

namespace sf {

/// Elements [begin, end) of the quad block `block` (state indices, of one material; begin best a
/// multiple of kBlockLanes from the block's start): their corner forces and moments into
/// out.corners, their state updated, their works summed into `out`, their critical steps into
/// out.element_dt (when not null). Stops at the first failing element, recorded in out.failure.
/// Conventions: compute_shell_internal_forces.
void run_bt_quads(const ElementBlock& block, const ShellPart& part, const ShellMaterial& material,
                  const ElementInputs& in, ShellState& state, int begin, int end,
                  ElementOutputs& out);

}  // namespace sf
