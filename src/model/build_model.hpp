#pragma once
#include "casefile/case_config.hpp"
#include "model/model.hpp"

namespace sf {

/// A blank given as a mesh with its node groups instead of the case's mesh file: a formed part's
/// own mesh (a trimmed part's, which no mesh file holds).
struct BlankMesh {
  PartMesh mesh;
  std::vector<NodeGroup> groups;
  /// A blank of several parts: their names, and each element's index into them (both empty for
  /// a blank of one part). The case's [[blank.parts]] of these names give their materials.
  std::vector<std::string> part_names;
  std::vector<int> element_part;
  std::string source;  ///< where it came from, for messages (the formed part's file)
};

/// Builds the model from a validated case: meshes every part with gmsh, attaches the material,
/// orients the tool surfaces toward the blank, sets up contact and constraints, applies mass
/// scaling and finds the end time. Throws InputError naming the file, key or group at fault.
/// With `blank`, the blank is that mesh and its groups (the case's blank.mesh is not read).
Model build_model(const CaseConfig& config, const BlankMesh* blank = nullptr);

/// The case with what build_model derived filled in (a force-controlled tool's default mass):
/// the resolved case written beside the results (Model::output.resolved_case holds its text).
CaseConfig resolve_case(const CaseConfig& config, const Model& model);

}  // namespace sf
