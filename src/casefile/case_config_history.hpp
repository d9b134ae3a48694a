#pragma once
// The case-file tables of node-group history output, [[history]] (docs/case-file.md). Called by
// read_case after [analysis] is read (a static analysis records no velocities).
#include "casefile/case_config.hpp"
#include "casefile/toml_reader.hpp"

namespace sf {

/// Reads every [[history]] table into config.history_groups. Throws InputError naming the key for
/// a missing or badly named group, a group given twice, or an unknown, repeated or (static)
/// inapplicable quantity.
void read_history_groups(const TomlSection& top, CaseConfig& config);

}  // namespace sf
