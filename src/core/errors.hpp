#pragma once
// The two kinds of failure a user can meet, each with its own exit code.
#include <stdexcept>
#include <string>

namespace sf {

/// Exit codes of the `sheetform` command.
enum ExitCode : int {
  exit_ok = 0,
  exit_internal_error = 1,  ///< a bug: an unexpected exception
  exit_input_error = 2,     ///< bad input: case file, mesh, command line
  exit_unstable = 3,        ///< the run went unstable (NaN, inversion, energy blow-up)
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

}  // namespace sf
