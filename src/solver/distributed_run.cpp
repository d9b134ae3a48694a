#include "solver/distributed_run.hpp"

#include <fmt/core.h>

#include "core/errors.hpp"

namespace sf {

void check_distributable(const Model& model, const std::string& case_file, int ranks) {
  if (ranks <= 1) {
    return;
  }
  auto refuse = [&](const std::string& what) {
    throw InputError(fmt::format(
        "{}: {} is not supported in a run over {} MPI ranks (docs/parallel.md); run it on one "
        "rank, with threads: sheetform run --threads N",
        case_file, what, ranks));
  };
  if (model.analysis.is_static()) {
    refuse("a static analysis ([analysis] type = \"static\")");
  }
  if (model.blank.scaling.enabled()) {
    refuse("mass scaling (control.mass_scaling_dt)");
  }
  if (!model.loads.pressures.empty()) {
    refuse("a pressure load ([[load]] type = \"pressure\")");
  }
  if (model.springback &&
      model.springback->method == SpringbackConfig::Method::dynamic_relaxation) {
    refuse(
        "springback by dynamic relaxation ([springback] method = \"dynamic_relaxation\"; "
        "the implicit springback is supported)");
  }
}

}  // namespace sf
