#include "solver/static_driver.hpp"

#include <fmt/core.h>

#include <chrono>

#include "core/log.hpp"
#include "implicit/static_constraints.hpp"
#include "implicit/static_step.hpp"
#include "model/external_loads.hpp"
#include "solver/blank_node_name.hpp"
#include "solver/frame_output.hpp"

namespace sf {

RunSummary run_static(Model& model, const RunOptions& options, SolutionState* final_state) {
  const auto start = std::chrono::steady_clock::now();
  SolutionState s = make_initial_state(model);
  std::unique_ptr<FrameOutput> output;
  if (options.write_results) {
    output = std::make_unique<FrameOutput>(model, options.output_directory);
    output->write_frame(model, s);
    output->append_history(model, s);
  }
  if (output && model.config.analysis.linear) {
    output->set_stress_geometry(&model.blank.mesh.nodes);
  }
  const auto node_name = blank_node_namer(model);
  StaticShellBody body(model.blank.part, s.x, s.shell);
  ImplicitStepSummary step;
  StaticConstraints constraints = make_static_constraints(
      s.x, model.constraints.mask, model.config.implicit.rigid_body_modes, node_name);
  step.free_modes = constraints.free_modes;
  step.added_constraints = constraints.added;

  const double end_time = model.config.control.end_time;
  // A load without a curve ramps from zero at time 0 to its value at end_time (in an explicit run
  // it would be constant): the static step follows the load from the unloaded state.
  const LoadCurve ramp({0.0, end_time}, {0.0, 1.0});
  std::size_t nodal = 0;
  std::size_t pressure = 0;
  for (const LoadConfig& lc : model.config.loads) {  // build_model keeps the case's order
    LoadCurve& scale = lc.type == LoadConfig::Type::pressure
                           ? model.loads.pressures.at(pressure++).scale
                           : model.loads.nodal.at(nodal++).scale;
    if (lc.curve.times.empty()) {
      scale = ramp;
    }
  }
  model.loads.gravity_scale = ramp;
  StaticLoad load;
  load.at = [&](double lambda, const Matrix3X& x, Matrix3X& f, Matrix3X& m) {
    compute_external_forces(model, lambda * end_time, x, f, m);
  };
  StaticStepOptions step_options;
  step_options.controls = model.config.implicit;
  step_options.linear = model.config.analysis.linear;
  step_options.node_name = node_name;
  log_info("static analysis ({}): {} equations, loads over 0..{} s in {} increment{}\n",
           step_options.linear ? "linear" : "nonlinear", constraints.dofs.equation_count(),
           end_time, step_options.linear ? 1 : step_options.controls.increments,
           step_options.linear || step_options.controls.increments == 1 ? "" : "s");
  step.report = solve_static_step(
      body, constraints.dofs, load, step_options,
      [&](double lambda, const StaticShellBody& b, const StaticStepReport& report) {
        s.x = b.x();
        s.shell = b.state();
        s.time = lambda * end_time;
        s.cycle += 1;
        s.energies.internal = report.internal_work;
        s.energies.external_work = report.external_work;
        compute_external_forces(model, s.time, s.x, s.f_ext, s.m_ext);
        if (output) {
          output->append_history(model, s);
          output->write_frame(model, s);
        }
      });
  if (output) {
    output->flush();
  }
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
