#include "solver/static_driver.hpp"

#include <fmt/core.h>
#include <fmt/format.h>
#include <algorithm>
#include <chrono>

#include "core/errors.hpp"
#include "core/log.hpp"
#include "implicit/static_constraints.hpp"
#include "implicit/static_step.hpp"
#include "model/external_loads.hpp"
#include "solver/blank_node_name.hpp"
#include "solver/frame_output.hpp"
#include "solver/output_schedule.hpp"

namespace sf {
namespace {
/// Adds the prescribed displacements (mm) and rotations (rad) at time t (s) to du and dtheta,
/// along the nodes' axes.
void add_prescribed_displacements(const Model& model, double t, Matrix3X& du, Matrix3X& dtheta) {
  for (const PrescribedMotion& p : model.prescribed_motions) {
    const double value = p.target(t);
    Matrix3X& field = p.rotation ? dtheta : du;
    for (std::size_t k = 0; k < p.nodes.size(); ++k) {
      const int node = p.nodes[k];
      field.col(node) += (p.sign[k] * value) * model.constraints.frames.axis(node, p.component[k]);
    }
  }
}

/// The automatic rigid-body holds must carry no load. They are a minimal support of the modes the
/// case's constraints leave free (prescribed degrees of freedom count as held), so they carry
/// exactly the loads' resultant over those modes: zero when the loads are balanced there, and a
/// prescribed motion alone never loads them (the body moves rigidly to meet it). A reaction means
/// there is no equilibrium without them and the answer depends on where they were put: an
/// InputError naming them, when one carries more than 1e-6 of the largest load, reaction or
/// force the step measured against (or 10 x the force tolerance, if larger).
void check_automatic_holds(const Model& model, const StaticConstraints& constraints,
                           const StaticStepReport& report, double length,
                           const std::function<std::string(int)>& node_name) {
  if (constraints.added_holds.empty()) {
    return;
  }
  double scale = report.force_scale;
  for (Eigen::Index i = 0; i < report.reaction_force.cols(); ++i) {
    scale = std::max({scale, report.reaction_force.col(i).norm(),
                      report.reaction_moment.col(i).norm() / length});
  }
  const double limit = std::max(1e-6, 10.0 * model.analysis.implicit.force_tolerance) * scale;
  std::string loaded;
  for (const auto& [node, dof] : constraints.added_holds) {
    const double r =
        constraints.dofs.component(node, dof, report.reaction_force, report.reaction_moment);
    if (std::abs(dof < 3 ? r : r / length) > limit) {
      loaded +=
          fmt::format("{}{} {} carries {:.4g} {}", loaded.empty() ? "" : ", ", node_name(node),
                      constraints.dofs.dof_name(node, dof), r, dof < 3 ? "N" : "N mm");
    }
  }
  if (!loaded.empty()) {
    throw InputError(fmt::format(
        "{}: static analysis: the automatic rigid-body holds (implicit.rigid_body_modes = "
        "\"auto\") carry load: {}. The loads are not balanced over the rigid-body modes the "
        "constraints leave free ({}), so there is no equilibrium without those holds and the "
        "answer would depend on where they were put: hold the model with [[boundary]] entries",
        model.case_file.string(), loaded, fmt::join(constraints.free_modes, "; ")));
  }
}

// Frames at the pseudo-times of control.output_frames, each written at the first converged
// increment at or past its time (as the explicit loop does with its steps), and one of the final
// state; a history row at every converged increment.
class StaticOutput {
 public:
  StaticOutput(FrameOutput* output, double end_time, int frames)
      : output_(output), end_time_(end_time), schedule_(0.0, end_time, frames, 1) {}

  void record(const Model& model, const SolutionState& s, bool final_state) {
    const OutputSchedule::Due due = schedule_.after_step(s.time, s.cycle);
    if (!output_) {
      return;
    }
    output_->append_history(model, s);
    if (final_state || due.frame) {
      output_->write_frame(model, s);
      last_frame_time_ = s.time;
    }
  }

  // After a failed step: the last converged state as a frame when it is not one already.
  // Returns the sentence to append to the error message.
  std::string write_stop_state(const Model& model, const SolutionState& s) {
    if (!output_) {
      return {};
    }
    std::string sentence;
    if (s.time > last_frame_time_) {
      output_->write_frame(model, s);
      sentence = fmt::format(
          "; the last frame in the results (load factor {:.6f}) is the last converged state",
          s.time / end_time_);
    }
    output_->flush();
    return sentence;
  }

 private:
  FrameOutput* output_;
  double end_time_;  // s, the pseudo-time of load factor 1
  OutputSchedule schedule_;
  double last_frame_time_ = 0.0;
};

}  // namespace

RunSummary run_static(const Model& model, const RunOptions& options, SolutionState* final_state) {
  if (!model.blank.formed_part.empty()) {
    throw InputError(fmt::format(
        "{}: blank.formed_part: a static analysis does not start from a formed part yet (an "
        "explicit run does)",
        model.case_file.string()));
  }
  const auto start = std::chrono::steady_clock::now();
  SolutionState s = make_initial_state(model);
  const auto node_name = blank_node_namer(model);
  // Held and prescribed degrees of freedom are not solved for; the prescribed ones move by their
  // curves (StaticLoad::prescribed).
  StaticConstraints constraints = make_static_constraints(
      s.x, model.constraints.held_or_prescribed(), model.analysis.implicit.rigid_body_modes,
      node_name, model.constraints.frames);
  std::unique_ptr<FrameOutput> output;
  if (options.write_results) {
    output = std::make_unique<FrameOutput>(model, options.output_directory);
    output->write_frame(model, s);
    output->append_history(model, s);
  }
  if (output && model.analysis.linear) {
    output->set_stress_geometry(&model.blank.mesh.nodes);
  }
  StaticShellBody body(model.blank.part, s.x, s.shell);
  ImplicitStepSummary step;
  step.free_modes = constraints.free_modes;
  step.added_constraints = constraints.added;

  const double end_time = model.time.end_time;
  StaticLoad load;
  load.at = [&](double lambda, const Matrix3X& x, Matrix3X& f, Matrix3X& m) {
    compute_external_forces(model, lambda * end_time, x, f, m);
  };
  for (const PrescribedMotion& p : model.prescribed_motions) {
    if (p.kind != PrescribedMotion::Kind::displacement) {
      // read_case refuses it; a configuration made in code may not have been read.
      throw InputError(
          fmt::format("{}: {}: a static analysis prescribes displacements and "
                      "rotations, not velocities",
                      model.case_file.string(), p.entry));
    }
  }
  if (!model.prescribed_motions.empty()) {
    // A prescribed displacement without a curve ramps from 0 over 0..end_time (build_model).
    load.prescribed = [&](double lambda, Matrix3X& du, Matrix3X& dtheta) {
      add_prescribed_displacements(model, lambda * end_time, du, dtheta);
    };
  }
  StaticStepOptions step_options;
  step_options.controls = model.analysis.implicit;
  step_options.linear = model.analysis.linear;
  step_options.node_name = node_name;
  log_info("static analysis ({}): {} equations, loads over 0..{} s in {} increment{}\n",
           step_options.linear ? "linear" : "nonlinear", constraints.dofs.equation_count(),
           end_time, step_options.linear ? 1 : step_options.controls.increments,
           step_options.linear || step_options.controls.increments == 1 ? "" : "s");
  StaticOutput schedule(output.get(), end_time, model.output.frames);
  try {
    step.report =
        solve_static_step(body, constraints.dofs, load, step_options,
                          [&](double lambda, const StaticShellBody& b,
                              const StaticStepReport& report, const ConvergedIncrement& increment) {
                            s.x = b.x();
                            s.shell = b.state();
                            s.rotation = increment.rotation;
                            s.time = lambda * end_time;
                            s.cycle += 1;
                            s.energies.internal = report.internal_work;
                            s.energies.hourglass = report.hourglass_work;
                            s.energies.external_work = report.external_work;
                            // The forces of the converged state, as the step's residual used
                            // them: f_int - f_ext is the reaction on held and prescribed dofs.
                            s.f_int = increment.f_int;
                            s.m_int = increment.m_int;
                            s.f_ext = increment.f_ext;
                            s.m_ext = increment.m_ext;
                            schedule.record(model, s, lambda >= 1.0 - 1e-12);
                          });
  } catch (const ConvergenceError& error) {
    throw ConvergenceError(error.what() + schedule.write_stop_state(model, s));
  }
  if (output) {
    output->flush();
  }
  // The state's internal forces: those of the last converged increment (f_int - f_ext is the
  // reaction where a degree of freedom is held or prescribed), for the summary's reactions.
  s.f_int = step.report.reaction_force + s.f_ext;
  s.m_int = step.report.reaction_moment + s.m_ext;
  check_automatic_holds(model, constraints, step.report, body.length_scale(), node_name);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  step.wall_seconds = wall;
  RunSummary summary = make_run_summary(model, s, wall);
  summary.static_step = std::move(step);
  if (final_state) {
    *final_state = std::move(s);
  }
  return summary;
}

}  // namespace sf
