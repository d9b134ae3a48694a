#pragma once
// Reactions of the constraints: the force and moment the supports exert on each held or
// prescribed node, and their totals per case entry ([[boundary]], [[prescribed_velocity]],
// [[prescribed_motion]]) for the run summary.
#include <optional>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "solver/solution_state.hpp"

namespace sf {

/// Per node, the reaction force (N) and moment (N mm) in global components: the components the
/// node's constraints hold or prescribe (in its axes) of what the supports add to the applied,
/// contact and internal forces; zero in the free components and at unconstrained nodes.
/// Static (state.dt = 0): f_int - f_ext. Explicit: f_int - f_ext - f_contact + c m v (damping),
/// plus, on a prescribed component, the inertia m a of the prescribed motion (a from its curve
/// by central differences over the last step state.dt). Not for the time loop (allocates).
void compute_reactions(const Model& model, const SolutionState& state, Matrix3X& force,
                       Matrix3X& moment);

/// The total reaction of one constraint entry over its group's nodes (a node in two groups counts
/// in both).
struct ConstraintReaction {
  std::string entry;           ///< e.g. "boundary[0]", "prescribed_motion[1]"
  std::string group;           ///< its node group
  Vec3 force = Vec3::Zero();   ///< N, sum over the group, global components
  Vec3 moment = Vec3::Zero();  ///< N mm, sum of the nodal moments, global components
  std::optional<Mat3> axes;    ///< the entry's own axes (columns), when it has them
  /// A [[prescribed_motion]]: the component along its degree of freedom (N, or N mm for a
  /// rotation), the force with which the support drives it.
  std::optional<double> along;
  std::string dof;  ///< that degree of freedom's name
};

/// The totals per entry, in the case's order: [[boundary]], [[prescribed_velocity]],
/// [[prescribed_motion]].
std::vector<ConstraintReaction> sum_reactions_by_entry(const Model& model, const Matrix3X& force,
                                                       const Matrix3X& moment);

}  // namespace sf
