#pragma once
// The case-file tables of the press line's operations, [[operations]] and
// [[operations.motion]] (docs/process-chain.md, docs/case-file.md). Read by read_case after the
// tools, [control] and [springback].
#include <string_view>

#include "casefile/case_config.hpp"
#include "casefile/toml_reader.hpp"
#include "casefile/toml_writer.hpp"

namespace sf {

/// Reads every [[operations]] table into config.operations. Throws InputError naming the key for
/// a tool that is not defined, an end condition without its value, a gravity operation without
/// control.gravity, a springback that is not the last operation, and the like.
void read_operations(const TomlSection& top, CaseConfig& config);

/// The kind's name as the case file spells it ("gravity", "closing", ...).
std::string_view operation_kind_name(OperationConfig::Kind kind);

/// Writes the [[operations]] tables of the resolved case.
void write_operations(TomlWriter& w, const CaseConfig& config);

}  // namespace sf
