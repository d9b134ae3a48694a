#pragma once
// The explicit central-difference time loop.
#include <filesystem>
#include <functional>
#include <memory>

#include "model/model.hpp"
#include "solver/explicit_step.hpp"
#include "solver/formed_part.hpp"
#include "solver/run_summary.hpp"
#include "solver/solution_state.hpp"

namespace sf {

struct RunOptions {
  std::filesystem::path output_directory;  ///< where results.h5 and the .xdmf files go
  bool write_results = true;
  /// The share of the blank this process computes (nullptr: all of it, serial). A distributed
  /// run's output process (Domain::is_root) writes the results; the others write nothing.
  std::shared_ptr<Domain> domain;
  /// A checkpoint to continue from (empty: start at time 0). The results go on in
  /// output_directory, which must hold the results of the run that wrote the checkpoint.
  std::filesystem::path restart_file;
  /// Write checkpoints (at the case's interval, on SIGUSR1, on a clean stop, at the end of the
  /// forming) into output_directory/checkpoint.h5; only with write_results.
  bool checkpoints = true;
  /// Stop cleanly at the end of this cycle, as on SIGTERM (-1: no such stop).
  long stop_at_cycle = -1;
  /// A formed part to start from instead of the case's blank.formed_part file (a trimmed part,
  /// solver/trim.hpp, whose mesh the model was built from); null: the file, if any.
  std::shared_ptr<const FormedPart> start_part;
};

/// Runs the model from time 0 (or from a checkpoint) to its end time, writing frames and history
/// as it goes, then the case's springback if it has one; the final state goes to `final_state`
/// when given. Throws InstabilityError (after writing what it can) when the run goes unstable,
/// ConvergenceError when an implicit springback cannot converge, RunStopped after a clean stop
/// on SIGINT or SIGTERM (solver/stop_request.hpp), InputError for a checkpoint that does not
/// belong to the case.
RunSummary run_explicit(const Model& model, const RunOptions& options,
                        SolutionState* final_state = nullptr);

}  // namespace sf
