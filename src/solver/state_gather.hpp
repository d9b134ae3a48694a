#pragma once
// The whole state on the output process of a distributed run (issue 17): before a frame, a
// history row, the summary or a springback, every node's kinematics and forces and every
// element's integration-point state are gathered from the process that owns them
// (Domain::gather_nodes, gather_elements). A serial run has them all already (no-op).
#include "solver/solution_state.hpp"

namespace sf {

/// Collective: every process calls it at the same point of the run. Only the output process's
/// state is completed; the others' is left as it was.
void gather_state_to_root(SolutionState& s);

/// Likewise for a checkpoint: every field the checkpoint keeps. Both gather the fields of
/// solver/state_fields.hpp with their role (output, checkpoint).
void gather_checkpoint_state_to_root(SolutionState& s);

/// Likewise for the formed part (solver/formed_part.hpp): every field it hands on.
void gather_formed_part_to_root(SolutionState& s);

}  // namespace sf
