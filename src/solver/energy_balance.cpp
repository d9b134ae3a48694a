#include "solver/energy_balance.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <string>

#include "contact/tool_placement.hpp"
#include "core/errors.hpp"
#include "core/exact_sums.hpp"
#include "model/operation_plan.hpp"
#include "solver/operation_sequence.hpp"

namespace sf {

double kinetic_energy(const Model& model, const SolutionState& s) {
  const auto sums = sum_over_nodes<1>(*s.domain, s.v.cols(), [&](long i, double* t) {
    t[0] = s.mass[i] * s.v.col(i).squaredNorm() +
           s.rotational_inertia[i] * s.omega.col(i).squaredNorm();
  });
  return 0.5 * sums[0].round();
}

// The velocity change of node i over half a kick: with the state at time n (s.v, s.omega the
// half-step velocities v(n-1/2) or, before the first step, v(0); the forces at time n), the
// central-difference update v(n+1/2) = v(n-1/2) + (dt(n-1/2) + dt(n+1/2)) / 2 (a(n) - c v(n-1/2))
// is split into two half kicks, v(n) = v(n-1/2) + dt(n-1/2) / 2 u and v(n+1/2) = v(n) +
// dt(n+1/2) / 2 u, with u the rate returned here (mm/s^2, rad/s^2): the same force sum, damping
// and current (possibly mass-scaled) masses as update_velocities; zero in the components the
// constraints hold at zero and those a prescribed velocity holds (there the velocity stays at the
// value the prescription gave it).
void half_kick_rate(const Model& model, const SolutionState& s, Eigen::Index i, double inverse_mass,
                    double inverse_inertia, Vec3& u, Vec3& u_omega) {
  const double c = damping_in_effect(model, s);
  u = inverse_mass * (s.f_ext.col(i) + s.f_contact.col(i) - s.f_int.col(i)) - c * s.v.col(i);
  u_omega = inverse_inertia * (s.m_ext.col(i) - s.m_int.col(i)) - c * s.omega.col(i);
  const NodalConstraints& constraints = model.constraints;
  const unsigned held = constraints.constrained_bits(static_cast<std::size_t>(i));
  if (held != 0) {
    constraints.zero_components(static_cast<int>(i), held, u, u_omega);
  }
}

// Kinetic energy (N mm) at the end of the step just taken, t(n+1), from the whole-step velocity
//   v(n+1) = v(n+1/2) + dt(n+1/2) / 2 (a(n+1) - c v(n+1/2)),
// a(n+1) from the forces just computed, without storing v(n+1). The half step used is the one
// just taken, dt(n+1/2) / 2, not the next one: the next velocity update, whatever its step, is
// then exactly v(n+1) followed by a second half kick dt(n+3/2) / 2 a(n+1) (half_kick_rate), so
// the reported v(n+1) is the one the scheme passes through, and the step it will take need not
// be known (it is cut to land on the end time). A constrained component is zero, a
// prescribed one stays at its prescribed value of the step (v(n+1/2)).
// With the trapezoidal work increments this balance is exact up to the half-kick energy
//   D(n+1) = 1/2 sum m |dt/2 u(n+1)|^2 = dt^2 / 8 F.M^-1.F (undamped),
// which is second order in dt: total - supplied = D(n+1) - D(0) at a constant step, for any
// forces (docs/time-integration.md).
namespace {

// Node i's terms of whole_step_kinetic_energy (twice the energies), h = dt / 2: the kinetic one
// into t[0], the half-kick one into t[1].
inline void whole_step_kinetic_terms(const Model& model, const SolutionState& s, Eigen::Index i,
                                     double h, double* t) {
  Vec3 u, u_omega;
  const double m = s.mass[i];
  const double j = s.rotational_inertia[i];
  half_kick_rate(model, s, i, s.inverse_mass[i], s.inverse_inertia[i], u, u_omega);
  t[0] = m * (s.v.col(i) + h * u).squaredNorm() + j * (s.omega.col(i) + h * u_omega).squaredNorm();
  t[1] = h * h * (m * u.squaredNorm() + j * u_omega.squaredNorm());
}

}  // namespace

KineticEnergy whole_step_kinetic_energy(const Model& model, const SolutionState& s, double dt) {
  const auto exact = sum_over_nodes<2>(*s.domain, s.v.cols(), [&](long i, double* t) {
    whole_step_kinetic_terms(model, s, i, 0.5 * dt, t);
  });
  const auto sums = rounded(exact);
  return {.kinetic = 0.5 * sums[0], .half_kick = 0.5 * sums[1]};
}

void update_half_kick_reference(const Model& model, SolutionState& s, double dt,
                                double dt_previous) {
  // D(0) from the forces at time 0; where the step changes, the kick about to be taken differs
  // from the reported D by the ratio of the squared steps, and that jump is taken out of the
  // reference (docs/time-integration.md).
  if (s.cycle == 0) {
    s.energies.half_kick_reference = whole_step_kinetic_energy(model, s, dt).half_kick;
  } else if (dt != dt_previous && dt_previous > 0.0) {
    const double ratio = dt / dt_previous;
    s.energies.half_kick_reference -= s.energies.half_kick * (1.0 - ratio * ratio);
  }
}

namespace {

// N mm, the work of the blank's force F and moment M (about the origin) on the tool over the
// step, by the trapezoidal rule. A point of the tool at x moves at w x (x - t) + dt/dt (t its
// placement's translation, w its angular velocity), so the power is F . dt/dt + w . (M - t x F).
double reaction_work_over_step(const ToolState& tool) {
  const Vec3 step = tool.displacement - tool.previous_displacement;
  double work = 0.5 * (tool.force + tool.previous_force).dot(step);
  if (tool.rotation != tool.previous_rotation) {
    const Vec3 turn = rotation_vector(tool.rotation * tool.previous_rotation.transpose());
    const Vec3 moment_now = tool.moment - tool.displacement.cross(tool.force);
    const Vec3 moment_before =
        tool.previous_moment - tool.previous_displacement.cross(tool.previous_force);
    work += 0.5 * (moment_now + moment_before).dot(turn);
  }
  return work;
}

// The node sums of a step, in one pass over the nodes, each exact (core/exact_sums.hpp): the
// trapezoidal work increments (N mm), the damping power's sum m |v|^2 (N mm/s), and the kinetic
// and half-kick energies at the step end (whole_step_kinetic_energy).
struct StepNodeSums {
  double element_work = 0.0;
  double load_work = 0.0;
  double damping_power = 0.0;
  double contact_work = 0.0;  // of the contact forces on the blank
  KineticEnergy kinetic;
};

StepNodeSums sum_over_nodes(const Model& model, const SolutionState& s, double dt) {
  const auto exact = sum_over_nodes<6>(*s.domain, s.x.cols(), [&](long i, double* t) {
    const auto v = s.v.col(i);
    const auto omega = s.omega.col(i);
    t[0] = 0.5 * dt *
           ((s.f_int.col(i) + s.f_int_previous.col(i)).dot(v) +
            (s.m_int.col(i) + s.m_int_previous.col(i)).dot(omega));
    t[1] = 0.5 * dt * (s.f_contact.col(i) + s.f_contact_previous.col(i)).dot(v);
    t[2] = 0.5 * dt *
           ((s.f_ext.col(i) + s.f_ext_previous.col(i)).dot(v) +
            (s.m_ext.col(i) + s.m_ext_previous.col(i)).dot(omega));
    t[3] = s.mass[i] * v.squaredNorm() + s.rotational_inertia[i] * omega.squaredNorm();
    whole_step_kinetic_terms(model, s, i, 0.5 * dt, t + 4);
  });
  const auto sums = rounded(exact);
  return {.element_work = sums[0],
          .load_work = sums[2],
          .damping_power = sums[3],
          .contact_work = sums[1],
          .kinetic = {.kinetic = 0.5 * sums[4], .half_kick = 0.5 * sums[5]}};
}

}  // namespace

void account_step_energies(const Model& model, SolutionState& s,
                           const ShellForceResult& element_result, double prescribed_work,
                           double time_before, double dt) {
  // The work increments by the trapezoidal rule.
  Energies& e = s.energies;
  const StepNodeSums sums = sum_over_nodes(model, s, dt);
  e.external_work += sums.load_work + prescribed_work;
  e.damping += damping_in_effect(model, s) * sums.damping_power * dt;
  const double hourglass_work = element_result.hourglass_work;
  e.plastic_work += element_result.plastic_work;
  e.hourglass += hourglass_work;
  e.internal += sums.element_work - hourglass_work;
  // The contact energy is the work done against the contact forces, on the blank and on the tools
  // (for the frictionless penalty: the spring energy 1/2 k g^2 up to the trapezoidal rule).
  e.contact -= sums.contact_work;
  double tool_kinetic = 0.0;
  for (std::size_t t = 0; t < s.tools.size(); ++t) {
    ToolState& tool = s.tools[t];
    const double reaction_work = reaction_work_over_step(tool);
    e.contact -= reaction_work;
    const Tool& model_tool = model.tools[t];
    if (tool.held) {
      tool.speed = 0.0;  // held where it is: no work, as a fixed tool's (no contact either)
    } else if (const auto& driven = model_tool.force_control) {
      // The press does the work of the applied force along the travel; the tool's damping
      // dissipates c M v^2 dt (on v(n+1/2), as for the blank); its kinetic energy is taken at
      // the step end, like the blank's.
      const double travel_step = dt * tool.velocity;
      e.external_work += 0.5 *
                         (driven->applied_force(time_before, tool.travel - travel_step) +
                          driven->applied_force(s.time, tool.travel)) *
                         travel_step;
      e.damping += driven->damping() * driven->mass() * tool.velocity * tool.velocity * dt;
      tool.speed = driven->whole_step_velocity(s.time, tool.force, tool.velocity, dt, tool.travel);
      tool_kinetic += 0.5 * driven->mass() * tool.speed * tool.speed;
    } else {
      // The press holds the tool against F on its prescribed path: it does -F . du of work.
      e.external_work -= reaction_work;
      tool.speed = speed_in_effect(model, static_cast<int>(t), tool.origin, s.time);
    }
    // A moving tool's peak is its largest push against its motion; a fixed tool's direction is
    // only the default axis, so its peak is the largest force along that axis either way.
    const double pushing = -tool.force.dot(model_tool.direction());
    const bool fixed = !tool.held && !model_tool.force_control &&
                       !motion_in_effect(model, static_cast<int>(t), tool.origin).moves();
    tool.peak_force = std::max(tool.peak_force, fixed ? std::abs(pushing) : pushing);
  }
  e.kinetic = sums.kinetic.kinetic + tool_kinetic;
  e.half_kick = sums.kinetic.half_kick;
}

void check_energy_blowup(const Model& model, const SolutionState& s, double energy_scale,
                         std::string_view where, std::string_view remedy_text) {
  const Energies& e = s.energies;
  const double ratio = model.time.energy_blowup_ratio;
  // Nothing to compare with while no work has been supplied and no tool moves (energy_scale 0):
  // a run loaded from rest does no work in its first step (v(1/2) = 0), while the kinetic energy
  // at its end already holds the first half kick, 1/2 m |dt/2 a(1)|^2 > 0.
  const double reference = std::max(e.supplied(), energy_scale);
  if (reference > 0.0 && e.total() > ratio * reference) {
    // Mass-proportional damping applied explicitly (on v(n-1/2)) amplifies for c dt > 2.
    const double c_dt = damping_in_effect(model, s) * s.dt;
    const std::string remedy =
        c_dt >= 2.0 ? fmt::format(
                          "control.damping = {} 1/s times the step {:.4e} s is {:.3g}, "
                          "beyond the explicit damping's stability limit 2: lower it",
                          damping_in_effect(model, s), s.dt, c_dt)
                    : std::string(remedy_text);
    throw InstabilityError(fmt::format(
        "energy blow-up{} at t = {:.6e} s, cycle {}: total energy {:.6e} N mm exceeds {} x "
        "{:.6e} N mm (the work supplied, {:.6e} N mm, or the run's energy scale if larger; "
        "kinetic {:.4e}, internal {:.4e}, hourglass {:.4e}, contact {:.4e}, damping {:.4e}); {}",
        where, s.time, s.cycle, e.total(), ratio, reference, e.supplied(), e.kinetic, e.internal,
        e.hourglass, e.contact, e.damping, remedy));
  }
}

}  // namespace sf
