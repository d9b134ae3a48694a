#pragma once
// Internal forces of the assumed-strain quadrilateral shell (ShellFormulation::assumed_strain):
// one in-plane point; membrane strain from the nodal velocities as the Belytschko-Lin-Tsay
// element's; curvature and the MITC4 transverse shear from the nodes' positions and directors
// (shell_quad_directors.hpp); physical stabilisation of the hourglass fields
// (shell_quad_stabilization.hpp). See docs/element-and-material.md.
#include "core/types.hpp"
#include "element/shell_forces.hpp"
#include "element/shell_part.hpp"

namespace sf {

/// Adds the internal forces (N) and moments (N mm) of every quad of `part` into f_int and m_int,
/// updating their state (stresses, thickness, stabilisation resultants and directors: the
/// directors are turned by dt omega). Same conventions as compute_shell_internal_forces; the
/// directors must have been set (initialize_directors). Throws InstabilityError naming the
/// element on inversion, collapse or a non-finite value. element_dt (when not null, one per element
/// of the part): each quad's critical step at x (compute_shell_internal_forces).
ShellForceResult compute_assumed_strain_quad_forces(const ShellPart& part, const Matrix3X& x,
                                                    const Matrix3X& v, const Matrix3X& omega,
                                                    double dt, ShellState& state, Matrix3X& f_int,
                                                    Matrix3X& m_int, double* element_dt = nullptr);

}  // namespace sf
