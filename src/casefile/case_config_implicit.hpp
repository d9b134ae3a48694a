#pragma once
// The case-file sections of implicit statics: [analysis], [implicit] and [springback]
// (docs/static-analysis.md). Called by read_case after [control] is read.
#include "casefile/case_config.hpp"
#include "casefile/toml_reader.hpp"

namespace sf {

/// Reads [analysis], [implicit] and [springback] into `config` and checks them against the rest
/// of the case (a static analysis has no tools and runs over control.end_time; springback needs
/// an explicit forming run with tools). Throws InputError naming the key.
void read_implicit_sections(const TomlSection& top, CaseConfig& config);

}  // namespace sf
