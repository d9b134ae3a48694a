#pragma once
// Internal forces of the shell part: one element pass over the quads of either formulation
// (ShellFormulation; Belytschko-Lin-Tsay in shell_quad_bt.hpp, assumed strain in
// shell_quad_assumed_strain.hpp) and the triangles (shell_triangle.hpp). Threads share out the
// elements; each element writes only its own corner slots and state, the works are summed
// exactly, and the nodes sum their corners in a fixed order (corner_forces.hpp): the results do
// not depend on the thread count.
#include <span>
#include <vector>

#include "core/types.hpp"
#include "element/corner_forces.hpp"
#include "element/element_pass.hpp"
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

/// Consecutive elements [begin, end) by state index, all in one element block: a piece of a
/// rank's share of the blank (parallel/rank_plan.hpp); a pass over all elements is one run per
/// block.
struct ElementRun {
  int begin = 0;
  int end = 0;
};

/// The runs of consecutive ids in `elements` (ascending state indices of the blocks' elements),
/// never crossing from one block into the next.
std::vector<ElementRun> element_runs(std::span<const int> elements, const ElementBlocks& blocks);

/// The scratch of the element passes over one part: the corner buffer and one output share per
/// thread. Sized by the first pass; later passes allocate nothing.
struct ElementPass {
  std::vector<double> corners;         ///< kCornerWidth per corner slot
  std::vector<ElementOutputs> shares;  ///< one per thread of the last pass
  NodeTurns turns;                     ///< the directors' turn at each node (assumed strain)
};

/// Every element's (quads, then triangles) internal nodal forces (N) and moments (N mm) into its
/// corner slots of pass.corners (global components), updating stresses, plastic strains and
/// thicknesses in `state`. Sign: the forces resist the motion, M a = f_ext - f_int, and
/// f_int . v + m_int . omega is the stress power. in.x: nodal coordinates at the end of the step
/// (mm); in.v: velocities (mm/s) and in.omega: angular velocities (rad/s) at mid-step; in.dt:
/// step (s). Strain increments are taken on the mid-step configuration x - dt/2 v, forces on x.
/// With element_dt (one per element), also each element's critical step L / c at x (s, the same
/// bits as compute_element_time_steps), so that the time-step control needs no pass of its own.
/// Throws InstabilityError naming the lowest failing element (inversion, collapse, a non-finite
/// value): the element a serial pass stops at, whatever the thread count.
/// With `runs` (ascending, each all quads or all triangles: element_runs), only those elements
/// (an MPI rank's share: their corner slots, state and steps; the works summed over them).
ShellForceResult run_element_pass(const ShellPart& part, const ElementInputs& in, ShellState& state,
                                  ElementPass& pass, std::span<double> element_dt = {},
                                  std::span<const ElementRun> runs = {});

/// The same, with the corners summed at the nodes and added into f_int and m_int (3 x n_nodes;
/// the caller zeroes them): for callers outside the time loop (the static analysis, tests), which
/// may allocate.
ShellForceResult compute_shell_internal_forces(const ShellPart& part, const Matrix3X& x,
                                               const Matrix3X& v, const Matrix3X& omega, double dt,
                                               ShellState& state, Matrix3X& f_int, Matrix3X& m_int,
                                               std::span<double> element_dt = {});

}  // namespace sf
