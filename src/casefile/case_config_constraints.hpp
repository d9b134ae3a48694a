#pragma once
// The case-file sections of kinematic constraints on blank nodes: [[boundary]] (degrees of
// freedom held at zero, in the global axes or a local frame), [[prescribed_motion]] (one degree
// of freedom driven along a curve) and [[prescribed_velocity]] (translational velocities of an
// explicit run). docs/case-file.md.
#include "casefile/case_config.hpp"
#include "casefile/toml_reader.hpp"

namespace sf {

/// Reads [[boundary]], [[prescribed_velocity]] and [[prescribed_motion]] into `config`. Throws
/// InputError naming the file, line and key for an unknown degree of freedom, a duplicate, zero
/// or near-parallel axes, a key that does not apply to the entry's type, ...
void read_constraint_sections(const TomlSection& top, CaseConfig& config);

/// The checks that need the analysis type (call after [analysis] is read): a static analysis
/// prescribes displacements, not velocities; an explicit run needs a curve for a prescribed
/// displacement (a constant one would be a jump at time 0).
void check_constraints_for_analysis(const TomlSection& top, const CaseConfig& config);

}  // namespace sf
