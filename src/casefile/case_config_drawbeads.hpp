#pragma once
// The [[drawbeads]] tables of a case (docs/drawbeads.md): reader, writer and key table.
#include "casefile/case_config.hpp"
#include "casefile/toml_reader.hpp"
#include "casefile/toml_writer.hpp"

namespace sf {

/// Reads every [[drawbeads]] table (after the tools and contacts are read: a bead names a tool
/// with a [[contact]]). Throws InputError naming the table and key.
void read_drawbeads(const TomlSection& top, CaseConfig& config);

void write_drawbeads(TomlWriter& w, const CaseConfig& config);

}  // namespace sf
