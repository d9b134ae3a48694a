#pragma once
// A case received from someone else must not run commands on this machine (issue 18, item 4):
// gmsh's .geo language can start programs (SystemCall, NonBlockingSystemCall, OnelabRun) and end
// the process (Exit). Those statements are refused before gmsh reads the file, unless the user
// allows them (sheetform --allow-geo-system-calls). docs/case-file.md, "Security".
#include <filesystem>

namespace sf {

/// Whether .geo files may run commands (set once by the command line; false by default): the
/// scan below is skipped, and gmsh runs unconfined (meshing/sandbox.hpp; its limits still apply).
bool& geo_system_calls_allowed();

/// Whether the scan below runs (true by default). It is the friendly first message; the sandbox is
/// what keeps a file from running commands, and tests switch the scan off to show that it holds
/// alone.
bool& geo_scan_enabled();

/// Throws InputError naming the file, the line and the statement when `geo_file`, or a .geo it
/// includes or merges (Include "..."; Merge "..."; relative to the including file), calls
/// SystemCall, NonBlockingSystemCall, OnelabRun or Exit, or includes a computed path, and
/// geo_system_calls_allowed() is false. Comments and string literals are not searched.
void check_geo_runs_no_commands(const std::filesystem::path& geo_file);

}  // namespace sf
