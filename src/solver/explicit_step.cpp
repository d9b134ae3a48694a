#include "solver/explicit_step.hpp"

#include "solver/central_difference.hpp"
#include "solver/nodal_update.hpp"
#include "solver/tool_update.hpp"

namespace sf {
namespace {

// The forces of time n become the previous ones, for the step's trapezoidal work.
void keep_previous_forces(SolutionState& s) {
  s.f_int_previous.swap(s.f_int);
  s.m_int_previous.swap(s.m_int);
  s.f_ext_previous.swap(s.f_ext);
  s.m_ext_previous.swap(s.m_ext);
  s.f_contact_previous.swap(s.f_contact);
}

void take_step(const Model& model, SolutionState& s, double dt, double dt_previous) {
  const double time_before = s.time;  // t(n)
  update_half_kick_reference(model, s, dt, dt_previous);
  const double weight = velocity_update_weight(dt, dt_previous);
  update_velocities(model, s, weight);  // v(n+1/2)
  const double prescribed_work = apply_velocity_conditions(model, s, weight, dt);
  update_positions(s, dt);  // x(n+1), t(n+1)
  move_tools(model, s, time_before, weight, dt);
  keep_previous_forces(s);
  const ShellForceResult elements = compute_forces(model, s, dt);  // at t(n+1)
  account_step_energies(model, s, elements, prescribed_work, time_before, dt);
}

}  // namespace

void advance_one_step(const Model& model, SolutionState& s, double dt, double dt_previous) {
  // The nodal phases' time: the step's less the element and contact passes' (timed inside).
  const double inner_before = s.times.elements + s.times.contact;
  double step_seconds = 0.0;
  {
    PhaseTimer timer(step_seconds);
    take_step(model, s, dt, dt_previous);
  }
  s.times.nodal += step_seconds - (s.times.elements + s.times.contact - inner_before);
}

}  // namespace sf
