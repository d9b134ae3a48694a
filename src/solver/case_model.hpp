#pragma once
// The model of a case as `sheetform run` builds it: from the case's meshes, or, for a case whose
// blank has no mesh but a formed part (blank.formed_part), on the part's own mesh and node groups
// (a trimmed part handed to a second case: docs/process-chain.md).
#include "casefile/case_config.hpp"
#include "model/model.hpp"

namespace sf {

/// build_model(config), with the formed part's mesh as the blank's when the case gives no mesh
/// (the part read as read_formed_part reads it: InputError naming the file for a bad one).
Model build_case_model(const CaseConfig& config);

}  // namespace sf
