#include "solver/time_loop.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "core/errors.hpp"
#include "solver/energy_balance.hpp"
#include "solver/explicit_step.hpp"
#include "solver/time_step_control.hpp"

namespace sf {

void run_time_loop(const Model& model, SolutionState& s, double& dt_previous,
                   const LoopChecks& checks, std::span<LoopObserver* const> observers) {
  const double initial_dt = model.time.time_step;
  while (true) {
    bool stop = false;
    for (LoopObserver* o : observers) {
      stop = o->before_step(s) || stop;
    }
    if (stop) {
      return;
    }
    double dt = compute_time_step(model, s);
    if (dt < 1e-3 * initial_dt) {
      throw InstabilityError(fmt::format(
          "time step collapsed to {:.3e} s (from {:.3e} s) at t = {:.6e} s, cycle {}{}: an "
          "element is being crushed",
          dt, initial_dt, s.time, s.cycle, checks.where));
    }
    for (LoopObserver* o : observers) {
      dt = o->bound_step(s, dt);
    }
    check_step_advances(s, dt, checks.where);
    advance_one_step(model, s, dt, dt_previous);
    dt_previous = dt;
    check_energy_blowup(model, s, checks.energy_scale, checks.blowup_where, checks.blowup_remedy);
    for (LoopObserver* o : observers) {
      stop = o->after_step(s) || stop;
    }
    if (stop) {
      return;
    }
  }
}

}  // namespace sf
