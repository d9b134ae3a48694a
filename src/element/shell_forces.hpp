#pragma once
// Internal forces of the shell part: quadrilaterals of either formulation (ShellFormulation) and
// triangles. The Belytschko-Lin-Tsay quad (Belytschko, Lin & Tsay 1984; Hallquist, LS-DYNA Theory
// Manual) with viscous or stiffness hourglass control (Flanagan & Belytschko 1981) is here; the
// assumed-strain quad in shell_quad_assumed_strain.hpp, the triangle in shell_triangle.hpp.
#include <span>

#include "core/types.hpp"
#include "element/shell_part.hpp"

namespace sf {

/// What one internal-force pass reports besides the forces.
struct ShellForceResult {
  /// N mm, work of the hourglass (stabilisation) forces in this step: the viscous form's
  /// dissipation (>= 0), or the change of the energy stored by the stiffness form and the
  /// assumed-strain stabilisation (trapezoidal rule on the resultants).
  double hourglass_work = 0.0;
  double internal_work = 0.0;  ///< N mm, increment of the stress work of this step (trapezoidal
                               ///< rule on stress, mid-step volume; excludes hourglass)
  double plastic_work = 0.0;   ///< N mm, the plastic part of internal_work (>= 0, dissipated):
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
/// With element_dt (one per element), also each element's critical step L / c at x (s, as
/// compute_element_time_steps gives it: the same bits), the quads' from the end-of-step geometry
/// the forces use, so that the time-step control needs no pass of its own.
ShellForceResult compute_shell_internal_forces(const ShellPart& part, const Matrix3X& x,
                                               const Matrix3X& v, const Matrix3X& omega, double dt,
                                               ShellState& state, Matrix3X& f_int, Matrix3X& m_int,
                                               std::span<double> element_dt = {});

}  // namespace sf
