#pragma once
#include "casefile/case_config.hpp"
#include "model/model.hpp"

namespace sf {

/// Builds the model from a validated case: meshes every part with gmsh, attaches the material,
/// orients the tool surfaces toward the blank, sets up contact and constraints, applies mass
/// scaling and finds the end time. Throws InputError naming the file, key or group at fault.
Model build_model(const CaseConfig& config);

/// The case with what build_model derived filled in (a force-controlled tool's default mass):
/// the resolved case written beside the results (Model::output.resolved_case holds its text).
CaseConfig resolve_case(const CaseConfig& config, const Model& model);

}  // namespace sf
