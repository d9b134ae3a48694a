#pragma once
#include "model/model.hpp"

namespace sf {

/// Builds the model from a validated case: meshes every part with gmsh, attaches the material,
/// orients the tool surfaces toward the blank, sets up contact and constraints, applies mass
/// scaling and finds the end time. Throws InputError naming the file, key or group at fault.
Model build_model(const CaseConfig& config);

}  // namespace sf
