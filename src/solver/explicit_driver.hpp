#pragma once
// The explicit central-difference time loop.
#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

#include "model/build_model.hpp"

#include "model/model.hpp"
#include "solver/explicit_step.hpp"
#include "solver/formed_part.hpp"
#include "solver/frame_output.hpp"
#include "solver/phase_times.hpp"
#include "solver/run_summary.hpp"
#include "solver/solution_state.hpp"

namespace sf {

/// How the run goes on after a trim ([[operations]] kind "trim", solver/trim.hpp): the model
/// built again on the trimmed part's mesh (build_model with a BlankMesh), and the share of it this
/// process computes (null: the whole of it, serial).
struct ModelRebuild {
  std::function<Model(const BlankMesh&)> model;
  std::function<std::shared_ptr<Domain>(const Model&)> domain;
};

/// Where a run after a trim takes up (run_explicit sets it for itself on the rebuilt model).
struct RunContinuation {
  int operation = 0;                     ///< the trim, the first operation of this run
  OutputMark output;                     ///< the results written before it
  std::vector<OperationRecord> records;  ///< the operations ended before it
  std::string trim_report;               ///< what the trim removed, in words
  PhaseTimes times;                      ///< s, the run's phases so far
  double peak_kinetic_ratio = 0.0;       ///< -, the run's largest so far
  double element_cycles = 0.0;           ///< element-cycles run so far (elements x cycles per mesh)
  double node_cycles = 0.0;              ///< node-cycles run so far
  long cycle = 0;                        ///< the cycle of the trim
  std::chrono::steady_clock::time_point wall_start;  ///< the case's start
};

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
  /// Needed by a case with a trim operation (else InputError when one is met).
  ModelRebuild rebuild;
  /// Set by run_explicit itself for the run after a trim.
  std::shared_ptr<const RunContinuation> continuation;
};

/// Runs the model from time 0 (or from a checkpoint) to its end time, writing frames and history
/// as it goes, then the case's springback if it has one; the final state goes to `final_state`
/// when given. Throws InstabilityError (after writing what it can) when the run goes unstable,
/// ConvergenceError when an implicit springback cannot converge, RunStopped after a clean stop
/// on SIGINT or SIGTERM (solver/stop_request.hpp), InputError for a checkpoint that does not
/// belong to the case. A case with a trim operation runs the operations up to it, trims the
/// part as it stands, builds the model again on the trimmed mesh (options.rebuild) and goes on
/// with it in the same results (a new mesh from the trim on, results/results_writer.hpp); the
/// summary then covers every operation and `final_state` is the trimmed model's.
RunSummary run_explicit(const Model& model, const RunOptions& options,
                        SolutionState* final_state = nullptr);

}  // namespace sf
