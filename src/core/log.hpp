#pragma once
// Console output: one place decides where messages go and how verbose they are.
#include <fmt/core.h>

#include <cstdio>
#include <utility>

namespace sf {

enum class Verbosity { quiet = 0, normal = 1, verbose = 2 };

/// The process-wide verbosity (set once by the command line).
Verbosity& verbosity();

/// Whether warnings are printed: true, except on the ranks of a distributed run other than rank
/// 0 (one rank speaks, once).
bool& warnings_enabled();

template <typename... Args>
void log_info(fmt::format_string<Args...> f, Args&&... args) {
  if (verbosity() >= Verbosity::normal) {
    fmt::print(stdout, f, std::forward<Args>(args)...);
    std::fflush(stdout);
  }
}

/// Detail for --verbose runs (Newton iterations, solver statistics).
template <typename... Args>
void log_verbose(fmt::format_string<Args...> f, Args&&... args) {
  if (verbosity() >= Verbosity::verbose) {
    fmt::print(stdout, f, std::forward<Args>(args)...);
    std::fflush(stdout);
  }
}

template <typename... Args>
void log_warning(fmt::format_string<Args...> f, Args&&... args) {
  if (!warnings_enabled()) {
    return;
  }
  fmt::print(stderr, "warning: ");
  fmt::print(stderr, f, std::forward<Args>(args)...);
}

}  // namespace sf
