#pragma once
// The springback and static-step parts of the run summary: console text and summary.json.
#include <nlohmann/json.hpp>
#include <string>

#include "implicit/static_step.hpp"
#include "solver/springback.hpp"

namespace sf {

/// Lines (each ending in a newline) for the console summary.
std::string format_implicit_step(const ImplicitStepSummary& step);
std::string format_springback(const SpringbackSummary& springback);

nlohmann::json implicit_step_json(const ImplicitStepSummary& step);
nlohmann::json springback_json(const SpringbackSummary& springback);

}  // namespace sf
