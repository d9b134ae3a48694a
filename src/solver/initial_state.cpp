#include "solver/initial_state.hpp"

#include "element/shell_directors.hpp"
#include "model/blank_parts.hpp"
#include "solver/energy_balance.hpp"

namespace sf {

SolutionState make_initial_state(const Model& model) {
  SolutionState s;
  const Eigen::Index n = model.blank.mesh.nodes.cols();
  s.x = model.blank.mesh.nodes;
  for (Matrix3X* field : {&s.v, &s.omega, &s.rotation, &s.f_int, &s.m_int, &s.f_contact,
                          &s.f_contact_previous, &s.f_ext, &s.m_ext, &s.f_ext_previous,
                          &s.m_ext_previous, &s.f_int_previous, &s.m_int_previous}) {
    *field = Matrix3X::Zero(3, n);
  }
  s.half_thickness = VectorX::Zero(n);
  s.mass = model.blank.mass;
  s.rotational_inertia = model.blank.rotational_inertia;
  s.scaling = model.blank.scaling;
  update_inverse_masses(s);
  if (s.scaling.enabled()) {
    s.mass_before = s.mass;
    s.inertia_before = s.rotational_inertia;
  }
  s.shell = make_blank_shell_state(model.blank, model.initial);
  initialize_directors(model.blank.part, model.blank.mesh.nodes, s.shell);
  s.tools.resize(model.tools.size());
  s.contacts.resize(model.contacts.size());
  s.drawbeads.resize(model.drawbeads.size());
  for (DrawbeadState& bead : s.drawbeads) {
    size_drawbead_state(bead, static_cast<int>(n));
  }
  for (const InitialVelocityConfig& iv : model.initial.velocities) {
    const auto set = [&](int node) {
      const Vec3 p = model.blank.mesh.nodes.col(node);  // mm, the initial coordinates
      for (int c = 0; c < 3; ++c) {
        s.v(c, node) = iv.velocity[c].evaluate(p(0), p(1), p(2));
        s.omega(c, node) = iv.angular_velocity[c].evaluate(p(0), p(1), p(2));
      }
    };
    if (iv.group.empty()) {
      for (int node = 0; node < static_cast<int>(n); ++node) {
        set(node);
      }
    } else {
      for (int node : model.blank.group(iv.group).nodes) {
        set(node);
      }
    }
  }
  model.constraints.apply(s.v, s.omega);
  // The initial velocities are the whole-step velocities v(0) (constraints applied): the same
  // definition as the kinetic energy reported after every step. The forces at time 0 only enter
  // the first half kick, v(1/2) = v(0) + dt/2 a(0).
  s.energies.kinetic = kinetic_energy(model, s);
  s.energies.initial_kinetic = s.energies.kinetic;
  s.stable_dt = model.time.time_step;
  s.dt_element = model.time.limiting_element;
  return s;
}

}  // namespace sf
