#pragma once
// The explicit central-difference time loop.
#include <filesystem>
#include <functional>
#include <memory>

#include "model/model.hpp"
#include "solver/explicit_step.hpp"
#include "solver/run_summary.hpp"
#include "solver/solution_state.hpp"

namespace sf {

struct RunOptions {
  std::filesystem::path output_directory;  ///< where results.h5 and the .xdmf files go
  bool write_results = true;
  /// The share of the blank this process computes (nullptr: all of it, serial). A distributed
  /// run's output process (Domain::is_root) writes the results; the others write nothing.
  std::shared_ptr<Domain> domain;
};

/// Runs the model from time 0 to its end time, writing frames and history as it goes, then the
/// case's springback if it has one; the final state goes to `final_state` when given. Throws
/// InstabilityError (after writing what it can) when the run goes unstable, ConvergenceError when
/// an implicit springback cannot converge.
RunSummary run_explicit(const Model& model, const RunOptions& options,
                        SolutionState* final_state = nullptr);

}  // namespace sf
