#pragma once
// Writes a small case (a .geo and a case.toml) into the build tree and reads it, for the run-level
// verification tests.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/case_config.hpp"
#include "model/build_model.hpp"
#include "solver/explicit_driver.hpp"

namespace sf::test {

/// Writes <build>/test_output/<name>/{blank.geo, case.toml} and reads the case. `case_text` is the
/// case file without its mesh key, which is added as the [blank] table's first line (so
/// `case_text` starts inside [blank]).
inline CaseConfig write_case(const std::string& name, const std::string& geo,
                             const std::string& case_text) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "blank.geo") << geo;
  std::ofstream(folder / "case.toml") << "[blank]\nmesh = \"blank.geo\"\n" << case_text;
  return read_case(folder / "case.toml");
}

/// Central-difference steps from the state until model.end_time (no output); calls
/// `after_step(state)` after every step.
template <class AfterStep>
void run_to_end(Model& model, SolutionState& s, AfterStep&& after_step) {
  double dt_previous = 0.0;
  while (s.time < model.end_time * (1.0 - 1e-12)) {
    const double dt = std::min(compute_time_step(model, s), model.end_time - s.time);
    advance_one_step(model, s, dt, dt_previous);
    dt_previous = dt;
    after_step(s);
  }
}

}  // namespace sf::test
