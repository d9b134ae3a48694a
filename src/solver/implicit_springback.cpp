// The implicit springback method: release the tool forces with the static step.
#include <fmt/core.h>

#include <chrono>

#include "core/log.hpp"
#include "implicit/static_constraints.hpp"
#include "solver/blank_node_name.hpp"
#include "solver/output_schedule.hpp"
#include "solver/springback.hpp"

namespace sf {

ImplicitStepSummary run_implicit_springback(const Model& model, SolutionState& s,
                                            FrameOutput* output) {
  const auto start = std::chrono::steady_clock::now();
  const auto node_name = blank_node_namer(model);
  StaticShellBody body(model.blank.part, s.x, s.shell);
  ImplicitStepSummary summary;
  // The case's holds stay; prescribed degrees of freedom stay where forming left them (the tools
  // are released, not the blank's grips).
  StaticConstraints constraints = make_static_constraints(
      s.x, model.constraints.held_or_prescribed(), model.analysis.implicit.rigid_body_modes,
      node_name, model.constraints.frames);
  summary.free_modes = constraints.free_modes;
  summary.added_constraints = constraints.added;

  // The blank's static internal forces in the formed state: what the tools held it with (the
  // inertia of the last cycles aside). Releasing them, (1 - lambda) applied, takes the tools away.
  const Eigen::Index n = s.x.cols();
  const Matrix3X zero = Matrix3X::Zero(3, n);
  Matrix3X f_release, m_release;
  ShellState trial;
  body.compute_forces(zero, zero, f_release, m_release, trial);
  const double length = body.length_scale();
  StaticLoad load;
  load.at = [&](double lambda, const Matrix3X&, Matrix3X& f, Matrix3X& m) {
    f = (1.0 - lambda) * f_release;
    m = (1.0 - lambda) * m_release;
  };
  load.reference_force =
      std::sqrt(f_release.squaredNorm() + m_release.squaredNorm() / (length * length));

  StaticStepOptions options;
  options.controls = model.analysis.implicit;
  options.node_name = node_name;
  options.stabilization =
      model.springback ? model.springback->stabilization * body.membrane_stiffness() : 0.0;
  const double t_formed = s.time;
  const Matrix3X rotation_formed = s.rotation;
  // The release runs over the pseudo-time of one forming frame interval, a frame per increment.
  const double frame_interval = model.time.end_time / model.output.frames;
  OutputSchedule schedule = OutputSchedule::every_step();
  s.v.setZero();
  s.omega.setZero();
  s.f_contact.setZero();
  log_info("springback (implicit): releasing {:.4g} N of tool forces over {} equations\n",
           load.reference_force, constraints.dofs.equation_count());
  summary.report =
      solve_static_step(body, constraints.dofs, load, options,
                        [&](double lambda, const StaticShellBody& b, const StaticStepReport&,
                            const ConvergedIncrement& increment) {
                          s.x = b.x();
                          s.rotation = rotation_formed + increment.rotation;
                          s.shell = b.state();
                          s.time = t_formed + lambda * frame_interval;
                          s.cycle += 1;
                          if (schedule.after_step(s.time, s.cycle).frame && output) {
                            output->write_frame(model, s);
                          }
                        });
  s.energies.internal += summary.report.internal_work;
  s.energies.hourglass += summary.report.hourglass_work;
  s.energies.external_work += summary.report.external_work;
  summary.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace sf
