#pragma once
// Internal forces of the Belytschko-Lin-Tsay shell (Belytschko, Lin & Tsay 1984; Hallquist,
// LS-DYNA Theory Manual), with viscous or stiffness hourglass control (Flanagan & Belytschko
// 1981).
#include "core/types.hpp"
#include "element/shell_part.hpp"

namespace sf {

/// What one internal-force pass reports besides the forces.
struct ShellForceResult {
  double hourglass_power = 0.0;  ///< N mm/s, sum over elements of the hourglass forces' power
                                 ///< (>= 0, dissipated); hourglass energy += dt * this
  double internal_work = 0.0;    ///< N mm, increment of the stress work of this step (trapezoidal
                                 ///< rule on stress, mid-step volume; excludes hourglass)
  double plastic_work = 0.0;     ///< N mm, the plastic part of internal_work (>= 0, dissipated):
                                 ///< the points' d_plastic_work on the same quadrature
};

/// Adds every element's (quads, then triangles: see shell_triangle.hpp) internal nodal forces (N)
/// and moments (N mm) into f_int and m_int
/// (3 x n_nodes, global components; the caller zeroes them), updating stresses, plastic strains and
/// thicknesses in `state`. Sign: f_int resists the motion, M a = f_ext - f_int, and
/// f_int . v + m_int . omega is the stress power.
/// x: nodal coordinates at the end of the step (mm); v: velocities (mm/s) and omega: angular
/// velocities (rad/s) at mid-step; dt: step (s). Strain increments are taken on the mid-step
/// configuration x - dt/2 v, forces on x. Throws InstabilityError naming the element on
/// inversion, collapse or a non-finite value.
ShellForceResult compute_shell_internal_forces(const ShellPart& part, const Matrix3X& x,
                                               const Matrix3X& v, const Matrix3X& omega, double dt,
                                               ShellState& state, Matrix3X& f_int, Matrix3X& m_int);

}  // namespace sf
