#pragma once
// Internal forces of the assumed-strain quadrilateral shell (ShellFormulation::assumed_strain):
// one in-plane point; membrane strain from the nodal velocities as the Belytschko-Lin-Tsay
// element's; curvature and the MITC4 transverse shear from the nodes' positions and directors
// (shell_quad_directors.hpp); physical stabilisation of the hourglass fields
// (shell_quad_stabilization.hpp). A formulation policy of the element loop (element_loop.hpp);
// see docs/element-and-material.md.
#include "core/types.hpp"
#include "element/element_block.hpp"
#include "element/element_pass.hpp"
#include "element/shell_part.hpp"

namespace sf {

/// Elements [begin, end) of the quad block `block` (state indices, of one material; begin best a
/// multiple of kBlockLanes from the block's start): their corner forces and moments into
/// out.corners, their state updated (stresses, thickness, stabilisation resultants and directors:
/// the directors are turned by dt omega), their works summed into `out`, their critical steps
/// into out.element_dt (when not null). The directors must have been set (initialize_directors).
/// Stops at the first failing element, recorded in out.failure. Conventions:
/// compute_shell_internal_forces.
void run_assumed_strain_quads(const ElementBlock& block, const ShellPart& part,
                              const ShellMaterial& material, const ElementInputs& in,
                              ShellState& state, int begin, int end, ElementOutputs& out);

}  // namespace sf
