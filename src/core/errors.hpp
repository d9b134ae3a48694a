#pragma once
// The kinds of failure a user can meet, each with its own exit code.
#include <stdexcept>
#include <string>

namespace sf {

/// Exit codes of the `sheetform` command.
enum ExitCode : int {
  exit_ok = 0,
  exit_internal_error = 1,  ///< a bug: an unexpected exception
  exit_input_error = 2,     ///< bad input: case file, mesh, command line
  exit_unstable = 3,        ///< the run went unstable (NaN, inversion, energy blow-up)
  exit_not_converged = 4,   ///< an implicit static step failed: no convergence, singular system
  /// Stopped on request (Ctrl-C, SIGTERM) at the end of a cycle: the last frame and a checkpoint
  /// are written, and `sheetform run CASE --restart CHECKPOINT` continues the run.
  exit_stopped = 5,
  exit_output_error = 6,  ///< the results could not be written (a full disk, a lost folder)
};

/// Anything a user can get wrong: the message names the file, the key or the entity, and what
/// was expected.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A run that went unstable. The message names the element or node, the time and the cycle.
class InstabilityError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An implicit static step that cannot go on: Newton failed after every allowed cut of the
/// increment, or the stiffness is singular (missing constraints, a mechanism). The message names
/// the load level, the residual and the node or degree of freedom where it is largest.
class ConvergenceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A run stopped on request (a signal) at the end of a cycle, with its last frame and a
/// checkpoint written. The message says where it stopped and how to continue.
class RunStopped : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The results (or a checkpoint) could not be written: a full disk, a folder removed or made
/// read-only during the run. The message names the file and what the system said.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace sf
