#pragma once
// The case-file tables of blank nodes chosen by position, [[node_group]] (docs/case-file.md).
#include "casefile/case_config.hpp"
#include "casefile/toml_reader.hpp"

namespace sf {

/// Reads every [[node_group]] table into config.node_groups. Throws InputError naming the key for
/// a missing or badly formed name, a name given twice, no criterion, a zero normal, a box whose
/// minimum exceeds its maximum, or a point combined with nothing to make a plane of (point alone
/// is the nearest node; with normal, a plane; with box or outline, refused as ambiguous).
void read_node_groups(const TomlSection& top, CaseConfig& config);

}  // namespace sf
