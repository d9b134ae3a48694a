#include "solver/time_step_control.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "core/exact_sums.hpp"
#include "model/mass_scaling.hpp"
#include "solver/energy_balance.hpp"

namespace sf {
namespace {

// Mass was added at some nodes (s.mass against s.mass_before): their half-step velocities are
// lowered to keep the momentum, v' = r v with r = m_old / m_new (likewise the angular velocities).
// The half kicks scale the same way (r u, half_kick_rate: the force over m_new, the damping on
// r v), so the whole-step velocity at this time n becomes r v(n) too: momentum is kept at the
// whole step as well, and the reported kinetic energy drops by (1 - r) K(n), K(n) = 1/2 m_old
// |v(n)|^2 with v(n) = v(n-1/2) + dt(n-1/2) / 2 u (what the last step reported).
// The energy counted in energies.mass_scaling is the one that keeps the balance's exact
// invariant, total - supplied - D (D the half-kick energy 1/2 m |dt/2 u|^2 of the coming step,
// whole_step_kinetic_energy), unchanged across the mass change: D drops too, to r D, so
//   dE = (1 - r) (1/2 m_old |v(n)|^2 - 1/2 m_old |dt/2 u|^2),
// which at a constant step equals 1/2 (1 - r) m_old v(n-1/2) . v*(n+1/2), v* the next half-step
// velocity at the old mass: the product form of the kinetic energy at time n. Counting only the
// kinetic-energy drop (1 - r) K(n) would leave (1 - r) D in the balance at every change.
// dt: the step about to be taken (s); s.dt: the last one taken (0 before the first step).
void keep_momentum(const Model& model, SolutionState& s, double dt) {
  const double h_last = 0.5 * s.dt;
  const double h_next = 0.5 * dt;
  // Per node: the energy removed (t[0]) and the kinetic-energy drop (t[1]).
  auto rescale = [&](long i, double* t) {
    t[0] = 0.0;
    t[1] = 0.0;
    const double m_new = s.mass[i];
    const double m_old = s.mass_before[i];
    const double i_new = s.rotational_inertia[i];
    const double i_old = s.inertia_before[i];
    if (m_new == m_old && i_new == i_old) {
      return;
    }
    Vec3 u, u_omega;
    half_kick_rate(model, s, i, 1.0 / m_old, 1.0 / i_old, u, u_omega);
    if (m_new != m_old) {
      const double r = m_old / m_new;
      const double drop = 0.5 * (1.0 - r) * m_old * (s.v.col(i) + h_last * u).squaredNorm();
      t[1] += drop;
      t[0] += drop - 0.5 * (1.0 - r) * m_old * h_next * h_next * u.squaredNorm();
      s.v.col(i) *= r;
    }
    if (i_new != i_old) {
      const double r = i_old / i_new;
      const double drop =
          0.5 * (1.0 - r) * i_old * (s.omega.col(i) + h_last * u_omega).squaredNorm();
      t[1] += drop;
      t[0] += drop - 0.5 * (1.0 - r) * i_old * h_next * h_next * u_omega.squaredNorm();
      s.omega.col(i) *= r;
    }
  };
  // Every node this process holds keeps its momentum; each node's energies are counted by the
  // one process that owns it, summed exactly.
  for (const int node : s.domain->ghost_nodes()) {
    double unused[2];
    rescale(node, unused);
  }
  const auto sums = rounded(sum_over_nodes<2>(*s.domain, s.v.cols(), rescale));
  s.energies.mass_scaling += sums[0];
  s.energies.kinetic -= sums[1];
}

// The step every element allows after raising the density of those below the target
// (mass_scaling.hpp), the masses added at the nodes this process holds. Collective.
TimeStepCheck scale_mass(const Model& model, SolutionState& s) {
  const ShellPart& part = model.blank.part;
  if (s.element_dt_cycle != s.cycle) {  // no element pass at x yet: the elements' steps first
    compute_element_time_steps(part, s.x, s.scaling.element_dt);
  }
  const DensityRaise raise = raise_element_densities(part, s.domain->element_runs(), s.scaling);
  ExactSum sums[2] = {raise.added_mass, raise.newly_scaled};
  s.domain->reduce(sums);
  TimeStepCheck check;
  check.mass_added = sums[0].round();
  if (check.mass_added > 0.0) {
    s.domain->add_corner_masses(model.blank.node_corners, s.scaling.corner_mass, s.mass,
                                s.rotational_inertia);
    s.scaling.added_mass += check.mass_added;
    s.scaling.scaled_elements += static_cast<int>(sums[1].round());
  }
  const StableStep scaled = s.domain->smallest_time_step(s.scaling.scaled_dt);
  check.dt = scaled.dt;
  check.element = scaled.element;
  return check;
}

// The step the elements allow at their densities (no mass scaling). Collective.
TimeStepCheck physical_step(const Model& model, SolutionState& s) {
  // The element pass of this cycle has the elements' steps at x already; otherwise compute them.
  const StableStep physical =
      s.element_dt_cycle == s.cycle
          ? s.domain->smallest_time_step(s.scaling.element_dt)
          : compute_element_time_steps(model.blank.part, s.x, s.scaling.element_dt);
  TimeStepCheck check;
  check.dt = s.scaling.safety * physical.dt;
  check.element = physical.element;
  return check;
}

}  // namespace

double compute_time_step(const Model& model, SolutionState& s) {
  const PhaseTimer timer(s.times.time_step);
  const Blank& blank = model.blank;
  if (s.scaling.enabled()) {
    s.mass_before = s.mass;  // same size: no allocation
    s.inertia_before = s.rotational_inertia;
  }
  const TimeStepCheck check = s.scaling.enabled() ? scale_mass(model, s) : physical_step(model, s);
  if (check.mass_added > 0.0) {
    keep_momentum(model, s, check.dt);
    update_inverse_masses(s);
  }
  const double limit = model.time.mass_scaling_max_added;
  if (check.mass_added > 0.0 && limit > 0.0 && s.scaling.added_mass > limit * blank.physical_mass) {
    throw InstabilityError(fmt::format(
        "added mass {:.3f} % of the blank's mass passed control.mass_scaling_max_added = {:.3f} % "
        "at t = {:.6e} s, cycle {} ({} elements scaled; element {} limits the step): elements "
        "are being crushed below the target step {:.4e} s",
        100.0 * s.scaling.added_mass / blank.physical_mass, 100.0 * limit, s.time, s.cycle,
        s.scaling.scaled_elements, check.element, s.scaling.target_dt));
  }
  s.stable_dt = check.dt;
  s.dt_element = check.element;
  if (s.min_stable_dt == 0.0 || check.dt < s.min_stable_dt) {
    s.min_stable_dt = check.dt;
    s.min_dt_element = check.element;
  }
  s.max_stable_dt = std::max(s.max_stable_dt, check.dt);
  return check.dt;
}

void check_step_advances(const SolutionState& s, double dt, const char* where) {
  if (std::isfinite(dt) && s.time + dt > s.time) {
    return;
  }
  throw InstabilityError(fmt::format(
      "the time step {:.3e} s does not advance the time t = {:.6e} s at cycle {}{} (element {} "
      "limits the step, stable step {:.3e} s): the run cannot go on; check the blank's material "
      "(young, density) and its smallest elements",
      dt, s.time, s.cycle, where, s.dt_element, s.stable_dt));
}

}  // namespace sf
