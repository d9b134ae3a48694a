#pragma once
// Internal forces of the 3-node shell triangles, formulation policies of the element loop
// (element_loop.hpp). The C0 triangle: constant-strain membrane, constant curvature from linear
// rotations, DSG3 transverse shear with Lyly-Stenberg-Vihinen stabilisation (shell_triangle.cpp,
// shell_triangle_geometry.hpp). The assumed-strain triangle: membrane as the C0 one's, curvature
// and DSG3 shear from the nodes' positions and directors (shell_triangle_assumed_strain.cpp,
// shell_triangle_directors.hpp). See docs/element-and-material.md.
#include "core/types.hpp"
#include "element/element_block.hpp"
#include "element/element_pass.hpp"
#include "element/shell_part.hpp"

namespace sf {

/// Elements [begin, end) of the triangle block `block` (state indices, of one material): their
/// corner forces and moments into out.corners, their integration-point state updated, their works
/// summed into `out` (no hourglass modes), their critical steps into out.element_dt (when not
/// null). Strains on the mid-step configuration x - dt/2 v, forces on x (conventions:
/// compute_shell_internal_forces). Stops at the first failing triangle (collapse, a normal that
/// flips within the step, a non-finite value), recorded in out.failure.
void run_c0_triangles(const ElementBlock& block, const ShellPart& part,
                      const ShellMaterial& material, const ElementInputs& in, ShellState& state,
                      int begin, int end, ElementOutputs& out);

/// The same for the assumed-strain formulation (ShellFormulation::assumed_strain): the directors
/// turned by dt omega; they must have been set (initialize_directors).
void run_assumed_strain_triangles(const ElementBlock& block, const ShellPart& part,
                                  const ShellMaterial& material, const ElementInputs& in,
                                  ShellState& state, int begin, int end, ElementOutputs& out);

}  // namespace sf
