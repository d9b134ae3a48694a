#pragma once
// Every part of the run state that a restart needs, named once: the checkpoint writer, its reader
// and the gather of a distributed run's state all walk this list, so a field added to the state
// and here is written, read and gathered alike.
//
// A visitor has
//   scalar(name, double& | long& | int& | bool&)   a number of the run
//   nodes(name, Matrix3X& | VectorX&)              a per-node array (columns or entries)
//   elements(name, std::vector<double>&, n)        a per-element array (n elements; may be empty)
// and is called with a SolutionState or a const one.
#include <string>
#include <type_traits>

#include "solver/solution_state.hpp"

namespace sf {

/// Visits the state's scalars and arrays. What is left out is scratch (the corner buffer, the
/// per-thread sums) or rebuilt exactly (the cached search's candidate lists: its answers are the
/// modified search's bit for bit, whatever the lists hold), or is never set when a checkpoint is
/// written: contact_off and released_loads belong to the springback's dynamic relaxation, whose
/// loop (solver/dynamic_relaxation.cpp) writes no checkpoint; only run_explicit does.
/// tests/solver/test_checkpoint_layout.cpp pins the order, names and kinds (format 1).
template <class Visitor, class State>
void visit_checkpoint_fields(Visitor& v, State& s) {
  static_assert(std::is_same_v<std::remove_const_t<State>, SolutionState>);
  v.scalar("time", s.time);
  v.scalar("cycle", s.cycle);
  v.scalar("dt", s.dt);
  v.scalar("stable_dt", s.stable_dt);
  v.scalar("dt_element", s.dt_element);
  v.scalar("min_stable_dt", s.min_stable_dt);
  v.scalar("max_stable_dt", s.max_stable_dt);
  v.scalar("min_dt_element", s.min_dt_element);
  v.scalar("element_dt_cycle", s.element_dt_cycle);
  v.scalar("contact_spring_energy", s.contact_spring_energy);
  v.scalar("peak_kinetic_ratio", s.peak_kinetic_ratio);

  v.nodes("x", s.x);
  v.nodes("v", s.v);
  v.nodes("omega", s.omega);
  v.nodes("rotation", s.rotation);
  v.nodes("f_int", s.f_int);
  v.nodes("m_int", s.m_int);
  v.nodes("f_contact", s.f_contact);
  v.nodes("f_ext", s.f_ext);
  v.nodes("m_ext", s.m_ext);
  v.nodes("f_ext_previous", s.f_ext_previous);
  v.nodes("m_ext_previous", s.m_ext_previous);
  v.nodes("f_int_previous", s.f_int_previous);
  v.nodes("m_int_previous", s.m_int_previous);
  v.nodes("f_contact_previous", s.f_contact_previous);
  v.nodes("half_thickness", s.half_thickness);
  v.nodes("mass", s.mass);
  v.nodes("rotational_inertia", s.rotational_inertia);
  v.nodes("inverse_mass", s.inverse_mass);
  v.nodes("inverse_inertia", s.inverse_inertia);

  const int n = s.shell.n_elements;
  v.scalar("mass_scaling/added_mass", s.scaling.added_mass);
  v.scalar("mass_scaling/scaled_elements", s.scaling.scaled_elements);
  v.elements("mass_scaling/density_factor", s.scaling.density_factor, n);
  v.elements("mass_scaling/element_dt", s.scaling.element_dt, n);

  v.elements("shell/sxx", s.shell.sxx, n);
  v.elements("shell/syy", s.shell.syy, n);
  v.elements("shell/sxy", s.shell.sxy, n);
  v.elements("shell/eps_p", s.shell.eps_p, n);
  v.elements("shell/flow_stress", s.shell.flow_stress, n);
  v.elements("shell/flow_stress_at", s.shell.flow_stress_at, n);
  v.elements("shell/sxz", s.shell.sxz, n);
  v.elements("shell/syz", s.shell.syz, n);
  v.elements("shell/thickness", s.shell.thickness, n);
  v.elements("shell/hourglass", s.shell.hourglass, n);
  v.elements("shell/director", s.shell.director, n);
  v.elements("shell/back_stress", s.shell.back_stress, n);

  auto& e = s.energies;
  v.scalar("energies/kinetic", e.kinetic);
  v.scalar("energies/internal", e.internal);
  v.scalar("energies/hourglass", e.hourglass);
  v.scalar("energies/contact", e.contact);
  v.scalar("energies/damping", e.damping);
  v.scalar("energies/external_work", e.external_work);
  v.scalar("energies/initial_kinetic", e.initial_kinetic);
  v.scalar("energies/mass_scaling", e.mass_scaling);
  v.scalar("energies/plastic_work", e.plastic_work);
  v.scalar("energies/friction_work", e.friction_work);
  v.scalar("energies/half_kick", e.half_kick);
  v.scalar("energies/half_kick_reference", e.half_kick_reference);

  for (std::size_t t = 0; t < s.tools.size(); ++t) {
    auto& tool = s.tools[t];
    const std::string p = "tools/" + std::to_string(t) + "/";
    v.scalar(p + "travel", tool.travel);
    v.scalar(p + "speed", tool.speed);
    v.scalar(p + "velocity", tool.velocity);
    v.scalar(p + "peak_force", tool.peak_force);
    v.scalar(p + "nodes_in_contact", tool.nodes_in_contact);
    v.scalar(p + "held", tool.held);
    for (int c = 0; c < 3; ++c) {
      const std::string k = std::to_string(c);
      v.scalar(p + "displacement" + k, tool.displacement[c]);
      v.scalar(p + "force" + k, tool.force[c]);
      v.scalar(p + "previous_displacement" + k, tool.previous_displacement[c]);
      v.scalar(p + "previous_force" + k, tool.previous_force[c]);
    }
  }
  for (std::size_t c = 0; c < s.contacts.size(); ++c) {
    auto& contact = s.contacts[c];
    const std::string p = "contacts/" + std::to_string(c) + "/";
    v.nodes(p + "stick_force", contact.stick_force);
    v.nodes(p + "bound_anchor", contact.distance_bounds.anchors());
    v.nodes(p + "bound_slack", contact.distance_bounds.slacks());
  }
}

}  // namespace sf
