#include "solver/springback.hpp"

#include <chrono>

#include "core/errors.hpp"
#include "core/log.hpp"

namespace sf {

SpringbackSummary run_springback(const Model& model, SolutionState& s, FrameOutput* output) {
  const auto start = std::chrono::steady_clock::now();
  const SpringbackConfig& config = *model.springback;
  const Matrix3X formed = s.x;
  if (output) {
    output->set_springback_reference(formed);
  }
  SpringbackSummary summary;
  // The measures' regions are picked on the formed shape, known only now: ranges that do not fit
  // it (a shorter stroke than the case was written for) cost the measures, not the springback.
  const std::vector<int>* section = nullptr;
  if (config.u_channel) {
    section = &model.blank.group(config.u_channel->section).nodes;
    try {
      summary.u_channel_formed = measure_u_channel(*config.u_channel, *section, formed, formed);
    } catch (const InputError& e) {
      log_warning("no U-channel measures: {}\n", e.what());
      section = nullptr;
    }
  }
  if (config.method == SpringbackConfig::Method::implicit) {
    summary.method = "implicit";
    summary.implicit = run_implicit_springback(model, s, output);
  } else {
    summary.method = "dynamic_relaxation";
    summary.relaxation = run_dynamic_relaxation(model, s, output, config);
  }
  for (Eigen::Index i = 0; i < s.x.cols(); ++i) {
    const double d = (s.x.col(i) - formed.col(i)).norm();
    if (d > summary.max_displacement) {
      summary.max_displacement = d;
      summary.max_displacement_node = static_cast<int>(i);
    }
  }
  if (section) {
    summary.u_channel = measure_u_channel(*config.u_channel, *section, formed, s.x);
  }
  summary.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace sf
