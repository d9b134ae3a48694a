#pragma once
// Internal forces of the 3-node C0 shell triangle: constant-strain membrane, constant curvature
// from linear rotations, DSG3 transverse shear with Lyly-Stenberg-Vihinen stabilisation. See
// shell_triangle_geometry.hpp and docs/element-and-material.md.
#include "core/types.hpp"
#include "element/shell_forces.hpp"
#include "element/shell_part.hpp"

namespace sf {

/// Adds the internal nodal forces (N) and moments (N mm) of every triangle of `part` into f_int
/// and m_int (3 x n_nodes, global components), updating their integration-point state: triangle
/// k is state element part.quads.cols() + k. Same conventions as compute_shell_internal_forces
/// (strains on the mid-step configuration x - dt/2 v, forces on x, f_int resists the motion,
/// f_int . v + m_int . omega is the stress power). No hourglass modes: hourglass_work is 0.
/// Throws InstabilityError naming the element on collapse, a normal that flips within the step
/// (inversion) or a non-finite value. Array sizes are checked by compute_shell_internal_forces.
ShellForceResult compute_triangle_internal_forces(const ShellPart& part, const Matrix3X& x,
                                                  const Matrix3X& v, const Matrix3X& omega,
                                                  double dt, ShellState& state, Matrix3X& f_int,
                                                  Matrix3X& m_int);

/// The same for the assumed-strain formulation (ShellFormulation::assumed_strain): membrane as
/// above, curvature and DSG3 shear from the nodes' positions and directors
/// (shell_triangle_directors.hpp), the directors turned by dt omega. The directors must have been
/// set (initialize_directors).
ShellForceResult compute_assumed_strain_triangle_forces(const ShellPart& part, const Matrix3X& x,
                                                        const Matrix3X& v, const Matrix3X& omega,
                                                        double dt, ShellState& state,
                                                        Matrix3X& f_int, Matrix3X& m_int);

}  // namespace sf
