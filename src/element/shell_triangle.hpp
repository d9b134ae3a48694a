#pragma once
// Internal forces of the 3-node C0 shell triangle: constant-strain membrane, constant curvature
// from linear rotations, DSG3 transverse shear with Lyly-Stenberg-Vihinen stabilisation. See
// shell_triangle_geometry.hpp and docs/element-and-material.md.
#include "core/types.hpp"
#include "element/element_pass.hpp"
#include "element/shell_part.hpp"

namespace sf {

/// Triangles [begin, end) of `part` (triangle k is state element part.quads.cols() + k): their
/// corner forces and moments into out.corners, their integration-point state updated, their works
/// summed into `out` (no hourglass modes). Strains on the mid-step configuration x - dt/2 v, forces
/// on x (conventions: compute_shell_internal_forces). Stops at the first failing triangle
/// (collapse, a normal that flips within the step, a non-finite value), recorded in out.failure.
void compute_triangle_forces(const ShellPart& part, const ShellMaterial& material,
                             const ElementInputs& in, ShellState& state, int begin, int end,
                             ElementOutputs& out);

/// The same for the assumed-strain formulation (ShellFormulation::assumed_strain): membrane as
/// above, curvature and DSG3 shear from the nodes' positions and directors
/// (shell_triangle_directors.hpp), the directors turned by dt omega. The directors must have been
/// set (initialize_directors).
void compute_assumed_strain_triangle_forces(const ShellPart& part, const ShellMaterial& material,
                                            const ElementInputs& in, ShellState& state, int begin,
                                            int end, ElementOutputs& out);

}  // namespace sf
