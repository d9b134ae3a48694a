#pragma once
// Checkpoints of an explicit run: one HDF5 file holding everything the run needs to go on
// (solver/checkpoint_fields.hpp: the nodal fields, the shell state, the mass scaling, the tools,
// the contact history, the energies), where its output stands (frames, history rows, audits) and
// what the time loop keeps between cycles. A run restarted from it gives the uninterrupted run's
// bits (docs/restart.md). The file is written to a temporary name and renamed over the old one,
// so a run killed while writing leaves the previous checkpoint whole.
#include <filesystem>
#include <string>

#include "solver/frame_output.hpp"
#include "solver/solution_state.hpp"

namespace sf {

/// What the explicit time loop keeps from one cycle to the next besides the state.
struct LoopMark {
  double dt_previous = 0.0;      ///< s, the step before (0 before the first)
  double last_frame_time = 0.0;  ///< s, of the last frame written
  bool warned_added_mass = false;
};

/// A checkpoint's own data beside the state.
struct CheckpointInfo {
  std::string case_digest;  ///< the physics of the case it belongs to (solver/case_digest.hpp)
  std::string git_hash;     ///< the build that wrote it
  double end_time = 0.0;    ///< s, the end of the run it was written by
  LoopMark loop;
  OutputMark output;
};

/// The checkpoint file of a results folder.
inline std::filesystem::path checkpoint_path(const std::filesystem::path& results_folder) {
  return results_folder / "checkpoint.h5";
}

/// Writes `file` atomically (a temporary file beside it, then renamed). Throws OutputError
/// naming the file when it cannot be written (the previous checkpoint, if any, stays whole).
void write_checkpoint(const std::filesystem::path& file, const SolutionState& state,
                      const CheckpointInfo& info);

/// Reads `file` into `state`, which must be the model's state sized for its run (make it with
/// make_initial_state and one force evaluation). Throws InputError naming the file and the
/// entry when it is not a checkpoint, or of a model of other sizes.
CheckpointInfo read_checkpoint(const std::filesystem::path& file, SolutionState& state);

}  // namespace sf
