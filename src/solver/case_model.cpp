#include "solver/case_model.hpp"

#include "model/build_model.hpp"
#include "solver/formed_part.hpp"

namespace sf {

Model build_case_model(const CaseConfig& config) {
  if (!config.blank.mesh.file.empty() || config.blank.formed_part.empty()) {
    return build_model(config);
  }
  const BlankMesh mesh = blank_mesh_of(read_formed_part(config.blank.formed_part));
  return build_model(config, &mesh);
}

}  // namespace sf
