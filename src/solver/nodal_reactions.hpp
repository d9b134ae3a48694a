#pragma once
// Reactions: the force and moment the constraints (boundary conditions, prescribed velocities,
// the holds of a static step) exert on each blank node, from a per-node mask of held components
// and the forces of a state, in global components.
#include <vector>

#include "core/types.hpp"
#include "model/model.hpp"
#include "solver/solution_state.hpp"

namespace sf {

/// The components held at `node` in an explicit state: the boundary conditions' and the
/// prescribed velocities' (bits 0-2 translations x, y, z; bits 3-5 rotations x, y, z).
unsigned explicit_held_components(const Model& model, const SolutionState& s, int node);

/// Per node, the reaction force (N) and moment (N mm): on every held component what the
/// constraint supplies beyond the applied forces so that the node follows its held motion,
///   R = f_int - f_ext - f_contact + m (a + c v)     (moments: m_int - m_ext + J (alpha + c w)),
/// with c the mass-proportional damping, m and J the node's (scaled) mass and inertia and a the
/// acceleration the held motion imposes: zero for a component held at rest; for a prescribed
/// velocity the difference of its target over the state's last step, centred on the state's
/// time, (v(t + dt/2) - v(t - dt/2)) / dt (zero when no step has been taken). Zero on free
/// components. A static state (v = 0, no contact) gives f_int - f_ext on the held components.
/// held: per node, the held components (as NodalConstraints::mask); null = those of the explicit
/// run (explicit_held_components). force and moment are resized to 3 x nodes (no allocation when
/// they have that size already).
void compute_nodal_reactions(const Model& model, const SolutionState& s,
                             const std::vector<unsigned char>* held, Matrix3X& force,
                             Matrix3X& moment);

}  // namespace sf
