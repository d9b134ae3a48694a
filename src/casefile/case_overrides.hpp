#pragma once
// Command-line overrides of case-file keys (`sheetform run CASE --set blank.parameters.n=32`):
// applied to the parsed TOML before it is read, so an overridden value is checked like any other
// and lands in the resolved case.
#include <toml++/toml.h>

#include <string>
#include <vector>

#include "casefile/case_config.hpp"

namespace sf {

/// Applies every override "KEY=VALUE", in order, to `root`. KEY is a dotted path of bare keys,
/// an array of tables taking an index: blank.parameters.n, tools[1].element_size,
/// control.output_frames. VALUE is a TOML value: 32, 2.5, "text", true, [1.0, 0.0, 0.0],
/// { n = 16 }. Missing tables on the path are created; an index must name an existing table.
/// Values keep the override as their source, so messages about them name it ("command line
/// (--set ...)") instead of a line of the case file. Throws InputError naming the override for a
/// malformed one.
void apply_case_overrides(toml::table& root, const std::vector<std::string>& overrides);

/// Applies run's --stroke, --end-time and --search (CaseOptions) to `root` as overrides of
/// control.stroke/end_time and of every [[contact]]'s search. Throws InputError for both end
/// conditions at once, a value that is not finite and > 0, or --search without a [[contact]]
/// (`file` names the case).
void apply_run_options(toml::table& root, const CaseOptions& options, const std::string& file);

}  // namespace sf
