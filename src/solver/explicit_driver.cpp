#include "solver/explicit_driver.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/errors.hpp"
#include "core/log.hpp"
#include "element/shell_directors.hpp"
#include "model/external_loads.hpp"
#include "solver/central_difference.hpp"
#include "solver/frame_output.hpp"
#include "solver/progress.hpp"
#include "solver/springback.hpp"

namespace sf {
namespace {

// Kinetic energy (N mm) of the velocities as they stand in the state: the initial velocities
// v(0), which are already at a whole step.
double kinetic_energy(const Model& model, const SolutionState& s) {
  double e = 0.0;
  const Eigen::Index n = s.v.cols();
  for (Eigen::Index i = 0; i < n; ++i) {
    e += model.blank.mass[i] * s.v.col(i).squaredNorm() +
         model.blank.rotational_inertia[i] * s.omega.col(i).squaredNorm();
  }
  return 0.5 * e;
}

// The velocity change of node i over half a kick: with the state at time n (s.v, s.omega the
// half-step velocities v(n-1/2) or, before the first step, v(0); the forces at time n), the
// central-difference update v(n+1/2) = v(n-1/2) + (dt(n-1/2) + dt(n+1/2)) / 2 (a(n) - c v(n-1/2))
// is split into two half kicks, v(n) = v(n-1/2) + dt(n-1/2) / 2 u and v(n+1/2) = v(n) +
// dt(n+1/2) / 2 u, with u the rate returned here (mm/s^2, rad/s^2): the same force sum, damping
// and current (possibly mass-scaled) masses as update_velocities; zero in the components the
// constraints hold at zero and those a prescribed velocity holds (there the velocity stays at the
// value the prescription gave it).
// mass (tonne) and inertia (tonne mm^2) are the node's.
void half_kick_rate(const Model& model, const SolutionState& s, Eigen::Index i, double mass,
                    double inertia, Vec3& u, Vec3& u_omega) {
  const double c = model.loads.damping;
  u = (1.0 / mass) * (s.f_ext.col(i) + s.f_contact.col(i) - s.f_int.col(i)) - c * s.v.col(i);
  u_omega = (1.0 / inertia) * (s.m_ext.col(i) - s.m_int.col(i)) - c * s.omega.col(i);
  const NodalConstraints& constraints = model.constraints;
  const unsigned held = constraints.constrained_bits(static_cast<std::size_t>(i));
  if (held != 0) {
    constraints.zero_components(static_cast<int>(i), held, u, u_omega);
  }
}

// The kinetic energy at the step end and the half-kick energy D (N mm).
struct KineticEnergy {
  double kinetic = 0.0;
  double half_kick = 0.0;
};

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
KineticEnergy whole_step_kinetic_energy(const Model& model, const SolutionState& s, double dt) {
  const double h = 0.5 * dt;
  KineticEnergy e;
  const Eigen::Index n = s.v.cols();
  Vec3 u, u_omega;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double m = model.blank.mass[i];
    const double j = model.blank.rotational_inertia[i];
    half_kick_rate(model, s, i, m, j, u, u_omega);
    e.kinetic +=
        m * (s.v.col(i) + h * u).squaredNorm() + j * (s.omega.col(i) + h * u_omega).squaredNorm();
    e.half_kick += h * h * (m * u.squaredNorm() + j * u_omega.squaredNorm());
  }
  e.kinetic *= 0.5;
  e.half_kick *= 0.5;
  return e;
}

// Accelerations from the nodal force balance, straight into the half-step velocity update.
// Returns false if any value is not finite (the caller then finds and names the node).
// Mass-proportional damping acts on the old half-step velocity (force -c m v), which keeps the
// update explicit; it is stable for c dt < 2.
bool update_velocities(const Model& model, SolutionState& s, double weight) {
  const Eigen::Index n = s.v.cols();
  const double c = model.loads.damping;
  double check = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double inv_m = 1.0 / model.blank.mass[i];
    const double inv_i = 1.0 / model.blank.rotational_inertia[i];
    s.v.col(i) += (weight * inv_m) * (s.f_ext.col(i) + s.f_contact.col(i) - s.f_int.col(i)) -
                  (weight * c) * s.v.col(i);
    s.omega.col(i) +=
        (weight * inv_i) * (s.m_ext.col(i) - s.m_int.col(i)) - (weight * c) * s.omega.col(i);
    check += s.v.col(i).sum() + s.omega.col(i).sum();
  }
  model.constraints.apply(s.v, s.omega);
  return std::isfinite(check);
}

// Holds the prescribed components (in each node's axes) at their velocities over the step [t, t +
// dt]: a prescribed velocity at its value at mid-step, a prescribed displacement (or rotation) at
// the velocity that reaches its value at the step end, (d(t + dt) - d(t)) / dt (central
// difference). Returns the work (N mm) of the reactions that do so over the step: reaction = m
// (v_prescribed - v_free) / weight (the rotational inertia for a rotation), times v_prescribed dt.
double apply_prescribed_motions(const Model& model, SolutionState& s, double weight, double dt) {
  double work = 0.0;
  const double t0 = s.time;
  const NodeFrames& frames = model.constraints.frames;
  for (const PrescribedMotion& p : model.prescribed_motions) {
    const double target = p.kind == PrescribedMotion::Kind::velocity
                              ? p.target(t0 + 0.5 * dt)
                              : (p.target(t0 + dt) - p.target(t0)) / dt;
    const VectorX& mass = p.rotation ? model.blank.rotational_inertia : model.blank.mass;
    Matrix3X& field = p.rotation ? s.omega : s.v;
    for (std::size_t k = 0; k < p.nodes.size(); ++k) {
      const int node = p.nodes[k];
      const int component = p.component[k];
      const double value = p.sign[k] * target;
      double free = 0.0;
      if (!frames.has(node)) {
        double& held = field(component % 3, node);
        free = held;
        held = value;
      } else {
        const Vec3 axis = frames.axis(node, component);
        free = axis.dot(field.col(node));
        field.col(node) += (value - free) * axis;
      }
      const double reaction = mass[node] * (value - free) / weight;
      work += reaction * value * dt;
    }
  }
  return work;
}

[[noreturn]] void throw_non_finite(const Model& model, const SolutionState& s) {
  for (Eigen::Index i = 0; i < s.v.cols(); ++i) {
    if (!s.v.col(i).allFinite() || !s.omega.col(i).allFinite()) {
      throw InstabilityError(fmt::format(
          "non-finite velocity at blank node {} (gmsh node {}) at t = {:.6e} s, cycle {}; "
          "forces there: internal ({}, {}, {}) N, contact ({}, {}, {}) N",
          i, model.blank.mesh.gmsh_node_tags[static_cast<std::size_t>(i)], s.time, s.cycle,
          s.f_int(0, i), s.f_int(1, i), s.f_int(2, i), s.f_contact(0, i), s.f_contact(1, i),
          s.f_contact(2, i)));
    }
  }
  throw InstabilityError(
      fmt::format("non-finite state at t = {:.6e} s, cycle {}", s.time, s.cycle));
}

// Mass was added at some nodes (blank.mass against s.mass_before): their half-step velocities are
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
  const Eigen::Index n = s.v.cols();
  const double h_last = 0.5 * s.dt;
  const double h_next = 0.5 * dt;
  double removed = 0.0;
  double kinetic_drop = 0.0;
  Vec3 u, u_omega;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double m_new = model.blank.mass[i];
    const double m_old = s.mass_before[i];
    const double i_new = model.blank.rotational_inertia[i];
    const double i_old = s.inertia_before[i];
    if (m_new == m_old && i_new == i_old) {
      continue;
    }
    half_kick_rate(model, s, i, m_old, i_old, u, u_omega);
    if (m_new != m_old) {
      const double r = m_old / m_new;
      const double drop = 0.5 * (1.0 - r) * m_old * (s.v.col(i) + h_last * u).squaredNorm();
      kinetic_drop += drop;
      removed += drop - 0.5 * (1.0 - r) * m_old * h_next * h_next * u.squaredNorm();
      s.v.col(i) *= r;
    }
    if (i_new != i_old) {
      const double r = i_old / i_new;
      const double drop =
          0.5 * (1.0 - r) * i_old * (s.omega.col(i) + h_last * u_omega).squaredNorm();
      kinetic_drop += drop;
      removed += drop - 0.5 * (1.0 - r) * i_old * h_next * h_next * u_omega.squaredNorm();
      s.omega.col(i) *= r;
    }
  }
  s.energies.mass_scaling += removed;
  s.energies.kinetic -= kinetic_drop;
}

void check_energy(const Model& model, const SolutionState& s, double energy_scale) {
  const Energies& e = s.energies;
  const double ratio = model.config.control.energy_blowup_ratio;
  // Nothing to compare with while no work has been supplied and no tool moves (energy_scale 0):
  // a run loaded from rest does no work in its first step (v(1/2) = 0), while the kinetic energy
  // at its end already holds the first half kick, 1/2 m |dt/2 a(1)|^2 > 0.
  const double reference = std::max(e.supplied(), energy_scale);
  if (reference > 0.0 && e.total() > ratio * reference) {
    // Mass-proportional damping applied explicitly (on v(n-1/2)) amplifies for c dt > 2.
    const double c_dt = model.loads.damping * s.dt;
    const std::string remedy =
        c_dt >= 2.0 ? fmt::format(
                          "control.damping = {} 1/s times the step {:.4e} s is {:.3g}, "
                          "beyond the explicit damping's stability limit 2: lower it",
                          model.loads.damping, s.dt, c_dt)
                    : std::string("reduce the time-step safety factor or the penalty scale");
    throw InstabilityError(fmt::format(
        "energy blow-up at t = {:.6e} s, cycle {}: total energy {:.6e} N mm exceeds {} x the "
        "work supplied {:.6e} N mm (kinetic {:.4e}, internal {:.4e}, hourglass {:.4e}, contact "
        "{:.4e}, damping {:.4e}); {}",
        s.time, s.cycle, e.total(), ratio, e.supplied(), e.kinetic, e.internal, e.hourglass,
        e.contact, e.damping, remedy));
  }
}

}  // namespace

SolutionState make_initial_state(const Model& model) {
  SolutionState s;
  const Eigen::Index n = model.blank.mesh.nodes.cols();
  s.x = model.blank.mesh.nodes;
  s.v = Matrix3X::Zero(3, n);
  s.omega = Matrix3X::Zero(3, n);
  s.rotation = Matrix3X::Zero(3, n);
  s.f_int = Matrix3X::Zero(3, n);
  s.m_int = Matrix3X::Zero(3, n);
  s.f_contact = Matrix3X::Zero(3, n);
  s.f_contact_previous = Matrix3X::Zero(3, n);
  s.f_ext = Matrix3X::Zero(3, n);
  s.m_ext = Matrix3X::Zero(3, n);
  s.f_ext_previous = Matrix3X::Zero(3, n);
  s.m_ext_previous = Matrix3X::Zero(3, n);
  s.f_int_previous = Matrix3X::Zero(3, n);
  s.m_int_previous = Matrix3X::Zero(3, n);
  s.half_thickness = VectorX::Zero(n);
  if (model.blank.scaling.enabled()) {
    s.mass_before = model.blank.mass;
    s.inertia_before = model.blank.rotational_inertia;
  }
  s.shell = make_shell_state(element_count(model.blank.part), model.config.blank.integration_points,
                             model.config.blank.thickness);
  initialize_directors(model.blank.part, model.blank.mesh.nodes, s.shell);
  s.tools.resize(model.tools.size());
  for (const InitialVelocityConfig& iv : model.config.initial_velocities) {
    const Vec3 velocity(iv.velocity[0], iv.velocity[1], iv.velocity[2]);
    if (iv.group.empty()) {
      s.v.colwise() = velocity;
    } else {
      for (int node : model.blank.group(iv.group).nodes) {
        s.v.col(node) = velocity;
      }
    }
  }
  model.constraints.apply(s.v, s.omega);
  // The initial velocities are the whole-step velocities v(0) (constraints applied): the same
  // definition as the kinetic energy reported after every step. The forces at time 0 only enter
  // the first half kick, v(1/2) = v(0) + dt/2 a(0).
  s.energies.kinetic = kinetic_energy(model, s);
  s.energies.initial_kinetic = s.energies.kinetic;
  s.stable_dt = model.time_step;
  s.dt_element = model.limiting_element;
  return s;
}

double compute_time_step(Model& model, SolutionState& s) {
  Blank& blank = model.blank;
  if (blank.scaling.enabled()) {
    s.mass_before = blank.mass;  // same size: no allocation
    s.inertia_before = blank.rotational_inertia;
  }
  const TimeStepCheck check =
      scale_mass_to_time_step(blank.part, s.x, blank.scaling, blank.mass, blank.rotational_inertia);
  if (check.mass_added > 0.0) {
    keep_momentum(model, s, check.dt);
  }
  const double limit = model.config.control.mass_scaling_max_added;
  if (check.mass_added > 0.0 && limit > 0.0 &&
      blank.scaling.added_mass > limit * blank.physical_mass) {
    throw InstabilityError(fmt::format(
        "added mass {:.3f} % of the blank's mass passed control.mass_scaling_max_added = {:.3f} % "
        "at t = {:.6e} s, cycle {} ({} elements scaled; element {} limits the step): elements "
        "are being crushed below the target step {:.4e} s",
        100.0 * blank.scaling.added_mass / blank.physical_mass, 100.0 * limit, s.time, s.cycle,
        blank.scaling.scaled_elements, check.element, blank.scaling.target_dt));
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

ShellForceResult compute_forces(Model& model, SolutionState& s, double dt) {
  s.f_int.setZero();
  s.m_int.setZero();
  s.f_contact.setZero();
  compute_external_forces(model, s.time, s.x, s.f_ext, s.m_ext);
  ShellForceResult element_result;
  const auto element_start = std::chrono::steady_clock::now();
  try {
    element_result = compute_shell_internal_forces(model.blank.part, s.x, s.v, s.omega, dt, s.shell,
                                                   s.f_int, s.m_int);
  } catch (const InstabilityError& e) {
    throw InstabilityError(fmt::format("{} at t = {:.6e} s, cycle {}", e.what(), s.time, s.cycle));
  }
  const auto contact_start = std::chrono::steady_clock::now();
  s.element_seconds += std::chrono::duration<double>(contact_start - element_start).count();
  // Half thickness per node: the mean over the elements around it.
  s.half_thickness.setZero();
  const QuadConn& quads = model.blank.part.quads;
  const TriConn& triangles = model.blank.part.triangles;
  for (Eigen::Index e = 0; e < quads.cols(); ++e) {
    for (int a = 0; a < 4; ++a) {
      s.half_thickness[quads(a, e)] += 0.5 * s.shell.thickness[static_cast<std::size_t>(e)];
    }
  }
  for (Eigen::Index k = 0; k < triangles.cols(); ++k) {
    const double half = 0.5 * s.shell.thickness[static_cast<std::size_t>(quads.cols() + k)];
    for (int a = 0; a < 3; ++a) {
      s.half_thickness[triangles(a, k)] += half;
    }
  }
  s.half_thickness.array() *= model.blank.inverse_element_count.array();

  s.contact_spring_energy = 0.0;
  for (ToolState& t : s.tools) {
    t.force.setZero();
    t.nodes_in_contact = 0;
  }
  for (ContactInterface& c : model.contacts) {
    ToolState& tool = s.tools[static_cast<std::size_t>(c.tool)];
    // s.v is the mid-step velocity of the step dt just taken (dt = 0 on the first call).
    const Vec3 tool_step =
        dt > 0.0 ? Vec3(tool.displacement - tool.previous_displacement) : Vec3::Zero();
    const ContactKinematics kinematics{.x = s.x,
                                       .v = s.v,
                                       .half_thickness = s.half_thickness,
                                       .tool_displacement = tool.displacement,
                                       .tool_displacement_increment = tool_step,
                                       .dt = dt};
    const ContactResult r = compute_penalty_contact(c.pair, kinematics, s.f_contact);
    tool.force += r.force_on_tool;
    tool.nodes_in_contact += r.nodes_in_contact;
    s.contact_spring_energy += r.energy;
    s.energies.friction_work += r.friction_work;
  }
  s.contact_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - contact_start).count();
  return element_result;
}

void advance_one_step(Model& model, SolutionState& s, double dt, double dt_previous) {
  const double time_before = s.time;  // t(n)
  // The half-kick energy's reference (docs/time-integration.md): D(0) from the forces at time 0;
  // where the step changes, the kick about to be taken differs from the reported D by the ratio
  // of the squared steps, and that jump is taken out of the reference.
  if (s.cycle == 0) {
    s.energies.half_kick_reference = whole_step_kinetic_energy(model, s, dt).half_kick;
  } else if (dt != dt_previous && dt_previous > 0.0) {
    const double ratio = dt / dt_previous;
    s.energies.half_kick_reference -= s.energies.half_kick * (1.0 - ratio * ratio);
  }
  const double weight = velocity_update_weight(dt, dt_previous);
  if (!update_velocities(model, s, weight)) {
    throw_non_finite(model, s);
  }
  const double prescribed_work = apply_prescribed_motions(model, s, weight, dt);
  s.x += dt * s.v;
  s.rotation += dt * s.omega;
  s.time += dt;
  s.cycle += 1;
  s.dt = dt;

  // Tools move to their positions at the new time; the old ones stay for the work increment. A
  // force-controlled tool takes the same central-difference step as the blank's nodes, from the
  // force and the blank's reaction at t(n) (the reaction of the last compute_forces): its travel
  // at t(n+1) is found in the same cycle as the blank's positions, so the contact at t(n+1) below
  // sees both at t(n+1).
  for (std::size_t t = 0; t < s.tools.size(); ++t) {
    ToolState& tool = s.tools[t];
    tool.previous_displacement = tool.displacement;
    tool.previous_force = tool.force;
    if (const auto& driven = model.tools[t].force_control) {
      driven->step(time_before, tool.force, weight, dt, tool.velocity, tool.travel);
      tool.displacement = tool.travel * driven->direction();
    } else {
      tool.travel = model.tools[t].motion.travel(s.time);
      tool.displacement = model.tools[t].motion.displacement(s.time);
    }
  }

  s.f_int_previous.swap(s.f_int);
  s.m_int_previous.swap(s.m_int);
  s.f_ext_previous.swap(s.f_ext);
  s.m_ext_previous.swap(s.m_ext);
  s.f_contact_previous.swap(s.f_contact);
  const ShellForceResult element_result = compute_forces(model, s, dt);

  // Energies by the trapezoidal rule on the work increments.
  Energies& e = s.energies;
  double element_work = 0.0;
  double load_work = 0.0;
  double damping_power = 0.0;
  double contact_work = 0.0;  // of the contact forces on the blank
  const Eigen::Index n = s.x.cols();
  for (Eigen::Index i = 0; i < n; ++i) {
    element_work += 0.5 * dt *
                    ((s.f_int.col(i) + s.f_int_previous.col(i)).dot(s.v.col(i)) +
                     (s.m_int.col(i) + s.m_int_previous.col(i)).dot(s.omega.col(i)));
    contact_work += 0.5 * dt * (s.f_contact.col(i) + s.f_contact_previous.col(i)).dot(s.v.col(i));
    load_work += 0.5 * dt *
                 ((s.f_ext.col(i) + s.f_ext_previous.col(i)).dot(s.v.col(i)) +
                  (s.m_ext.col(i) + s.m_ext_previous.col(i)).dot(s.omega.col(i)));
    damping_power += model.blank.mass[i] * s.v.col(i).squaredNorm() +
                     model.blank.rotational_inertia[i] * s.omega.col(i).squaredNorm();
  }
  e.external_work += load_work + prescribed_work;
  e.damping += model.loads.damping * damping_power * dt;
  const double hourglass_work = element_result.hourglass_work;
  e.plastic_work += element_result.plastic_work;
  e.hourglass += hourglass_work;
  e.internal += element_work - hourglass_work;
  // The contact energy is the work done against the contact forces, on the blank and on the tools
  // (for the frictionless penalty: the spring energy 1/2 k g^2 up to the trapezoidal rule).
  e.contact -= contact_work;
  double tool_kinetic = 0.0;
  for (std::size_t t = 0; t < s.tools.size(); ++t) {
    ToolState& tool = s.tools[t];
    // Work of the blank's force F on the tool over the step.
    const Vec3 step = tool.displacement - tool.previous_displacement;
    const double reaction_work = 0.5 * (tool.force + tool.previous_force).dot(step);
    e.contact -= reaction_work;
    if (const auto& driven = model.tools[t].force_control) {
      // The press does the work of the applied force along the travel; the tool's damping
      // dissipates c M v^2 dt (on v(n+1/2), as for the blank); its kinetic energy is taken at
      // the step end, like the blank's.
      const double travel_step = dt * tool.velocity;
      e.external_work +=
          0.5 * (driven->applied_force(time_before) + driven->applied_force(s.time)) * travel_step;
      e.damping += driven->damping() * driven->mass() * tool.velocity * tool.velocity * dt;
      tool.speed = driven->whole_step_velocity(s.time, tool.force, tool.velocity, dt);
      tool_kinetic += 0.5 * driven->mass() * tool.speed * tool.speed;
    } else {
      // The press holds the tool against F on its prescribed path: it does -F . du of work.
      e.external_work -= reaction_work;
      tool.speed = model.tools[t].motion.speed(s.time);
    }
    // A moving tool's peak is its largest push against its motion; a fixed tool's direction is
    // only the default axis, so its peak is the largest force along that axis either way.
    const double pushing = -tool.force.dot(model.tools[t].direction());
    const bool fixed = !model.tools[t].force_control && !model.tools[t].motion.moves();
    tool.peak_force = std::max(tool.peak_force, fixed ? std::abs(pushing) : pushing);
  }
  const KineticEnergy kinetic = whole_step_kinetic_energy(model, s, dt);
  e.kinetic = kinetic.kinetic + tool_kinetic;
  e.half_kick = kinetic.half_kick;
}

RunSummary run_explicit(Model& model, const RunOptions& options, SolutionState* final_state) {
  const auto wall_start = std::chrono::steady_clock::now();
  const ControlConfig& control = model.config.control;
  SolutionState s = make_initial_state(model);
  for (std::size_t t = 0; t < s.tools.size(); ++t) {
    s.tools[t].displacement = model.tools[t].motion.displacement(0.0);
    s.tools[t].travel = model.tools[t].motion.travel(0.0);
    s.tools[t].speed = model.tools[t].motion.speed(0.0);
  }

  std::unique_ptr<FrameOutput> output;
  if (options.write_results) {
    output = std::make_unique<FrameOutput>(model, options.output_directory);
  }
  compute_forces(model, s, 0.0);
  if (output) {
    output->write_frame(model, s);
    output->append_history(model, s);
  }

  // Energy scale below which the blow-up check is silent: the blank's kinetic energy at the
  // fastest tool speed, a thousandth of it (0 without moving tools).
  double max_speed = 0.0;
  for (const Tool& t : model.tools) {
    for (int k = 0; k <= 100; ++k) {
      max_speed = std::max(max_speed, std::abs(t.motion.speed(model.end_time * k / 100.0)));
    }
  }
  const double energy_scale = 1e-3 * 0.5 * model.blank.mass.sum() * max_speed * max_speed;

  const double frame_interval = model.end_time / control.output_frames;
  double next_frame_time = frame_interval;
  const double initial_dt = model.time_step;
  double dt_previous = 0.0;
  double last_frame_time = 0.0;  // s, of the last frame written (the first is at t = 0)
  Progress progress(model, control.progress_interval);
  // Added mass above this share of the physical mass is worth a warning (once).
  constexpr double warn_fraction = 0.05;
  bool warned = false;
  auto warn_about_added_mass = [&]() {
    const double fraction = model.blank.scaling.added_mass / model.blank.physical_mass;
    if (!warned && fraction > warn_fraction) {
      warned = true;
      log_warning(
          "mass scaling has added {:.2f} % of the blank's mass by t = {:.6e} s, cycle {} ({} "
          "elements scaled); check that the inertia forces stay small (kinetic / internal energy) "
          "or set control.mass_scaling_max_added\n",
          100.0 * fraction, s.time, s.cycle, model.blank.scaling.scaled_elements);
    }
  };
  warn_about_added_mass();

  try {
    while (s.time < model.end_time * (1.0 - 1e-12)) {
      double dt = compute_time_step(model, s);
      if (dt < 1e-3 * initial_dt) {
        throw InstabilityError(fmt::format(
            "time step collapsed to {:.3e} s (from {:.3e} s) at t = {:.6e} s, cycle {}: an "
            "element is being crushed",
            dt, initial_dt, s.time, s.cycle));
      }
      // Land exactly on the end time. Frames are written at the first step end at or past each
      // frame time, not by cutting the step to it: a step cut short and the full one after it
      // change the amplitude of the modes near the stability limit (the contact springs, capped
      // at w dt = 0.87), and frame after frame that pumped energy into the flange's contact
      // chatter (the U-channel's energy balance grew 2x per frame, to 1.5e-4 at 10 mm).
      dt = std::min(dt, model.end_time - s.time);
      advance_one_step(model, s, dt, dt_previous);
      dt_previous = dt;
      if (s.time > 0.1 * model.end_time) {
        s.peak_kinetic_ratio = std::max(s.peak_kinetic_ratio, s.energies.kinetic_ratio());
      }
      check_energy(model, s, energy_scale);
      warn_about_added_mass();

      const bool frame_due = s.time >= next_frame_time * (1.0 - 1e-12);
      // A history row every history_interval cycles and at every frame (the frame's added mass,
      // time step, energies).
      if (output && (s.cycle % control.history_interval == 0 || frame_due)) {
        output->append_history(model, s);
      }
      if (frame_due) {
        if (output) {
          output->write_frame(model, s);
          last_frame_time = s.time;
        }
        while (next_frame_time <= s.time * (1.0 + 1e-12)) {
          next_frame_time += frame_interval;  // a step longer than the frame interval
        }
      }
      progress.report(model, s, false);
    }
  } catch (const InstabilityError& error) {
    // Keep what a user needs to see the failure: the history up to the stop and, when the nodes
    // still have finite positions, one last frame of the state at the stop (for a NaN, the state
    // of the last completed cycle; for an inverted element or an energy blow-up, the offending
    // configuration). The frames written before stay as they are.
    const std::string last_frame =
        output ? output->write_stop_state(model, s, last_frame_time) : std::string();
    throw InstabilityError(error.what() + last_frame);
  }
  if (output) {
    output->append_history(model, s);
    output->flush();
  }
  progress.report(model, s, true);
  const double wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  RunSummary summary = make_run_summary(model, s, wall_seconds);
  if (output) {
    for (const SearchAuditRecord& a : output->search_audits().records()) {
      summary.search_audits.push_back({a.tool, a.search, a.audits, a.last.misses,
                                       a.last.nodes_checked, a.max_misses, a.max_misses_time,
                                       a.total_misses, a.max_gap_error});
    }
  }
  // The forming summary above is the state with the tools in place; springback goes on from it.
  if (model.config.springback) {
    summary.springback = run_springback(model, s, output.get());
    if (output) {
      output->flush();
    }
  }
  if (final_state) {
    *final_state = std::move(s);
  }
  return summary;
}

}  // namespace sf
