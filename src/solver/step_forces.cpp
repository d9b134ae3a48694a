#include "solver/step_forces.hpp"

#include <fmt/core.h>

#include <chrono>

#include "core/errors.hpp"
#include "model/external_loads.hpp"

namespace sf {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The elements' internal forces and moments into state.f_int, m_int: each element into its
// corners, then each node sums its corners in a fixed order (element/corner_forces.hpp).
ShellForceResult compute_internal_forces(const Model& model, SolutionState& s, double dt) {
  try {
    // The elements' critical steps at x come with the forces (the next step's bound).
    run_element_pass(model.blank.part, ElementInputs{s.x, s.v, s.omega, dt}, s.shell,
                     s.element_pass, s.scaling.element_dt, s.domain->element_runs());
    s.domain->assemble_corners(model.blank.node_corners, s.element_pass.corners, s.f_int, s.m_int);
    // The pass's exact works (left in its first share) made global, then rounded once.
    const ElementOutputs& total = s.element_pass.shares[0];
    ExactSum works[3] = {total.internal_work, total.plastic_work, total.hourglass_work};
    s.domain->reduce(works);
    const ShellForceResult r{.hourglass_work = works[2].round(),
                             .internal_work = works[0].round(),
                             .plastic_work = works[1].round()};
    s.element_dt_cycle = s.cycle;
    return r;
  } catch (const InstabilityError& e) {
    throw InstabilityError(fmt::format("{} at t = {:.6e} s, cycle {}", e.what(), s.time, s.cycle));
  }
}

// The contact offset of every node: half the mean thickness of the elements around it (mm).
void update_contact_offsets(const Model& model, SolutionState& s) {
  gather_half_thickness(model.blank.node_corners, s.shell.thickness,
                        model.blank.inverse_element_count, s.half_thickness);
}

// A contact call's exact sums and counts (left in the pair's first share) made global, then
// rounded once.
ContactResult global_contact_result(Domain& domain, const ContactShare& total) {
  ExactSum sums[9] = {total.force_on_tool[0], total.force_on_tool[1], total.force_on_tool[2],
                      total.energy, total.friction_work};
  const int counts[4] = {total.nodes_in_contact, total.sliding_nodes, total.sticking_nodes,
                         total.projection_fallbacks};
  for (int k = 0; k < 4; ++k) {
    sums[5 + k].add(counts[k]);  // integers: exact
  }
  domain.reduce(sums);
  ContactResult r;
  r.force_on_tool = Vec3(sums[0].round(), sums[1].round(), sums[2].round());
  r.energy = sums[3].round();
  r.friction_work = sums[4].round();
  r.nodes_in_contact = static_cast<int>(sums[5].round());
  r.sliding_nodes = static_cast<int>(sums[6].round());
  r.sticking_nodes = static_cast<int>(sums[7].round());
  r.projection_fallbacks = static_cast<int>(sums[8].round());
  return r;
}

// The penalty contact of every pair into state.f_contact (zeroed here), the tools' reactions and
// contact counts, the spring energy and the friction work.
void compute_contact_forces(const Model& model, SolutionState& s, double dt) {
  s.f_contact.setZero();
  s.contact_spring_energy = 0.0;
  for (ToolState& t : s.tools) {
    t.force.setZero();
    t.nodes_in_contact = 0;
  }
  if (s.contact_off) {
    return;
  }
  for (std::size_t k = 0; k < model.contacts.size(); ++k) {
    const ContactInterface& c = model.contacts[k];
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
    compute_penalty_contact(c.pair, s.contacts[k], kinematics, s.f_contact);
    const ContactResult r = global_contact_result(*s.domain, s.contacts[k].shares[0]);
    tool.force += r.force_on_tool;
    tool.nodes_in_contact += r.nodes_in_contact;
    s.contact_spring_energy += r.energy;
    s.energies.friction_work += r.friction_work;
  }
}

}  // namespace

ShellForceResult compute_forces(const Model& model, SolutionState& s, double dt) {
  compute_external_forces(model, s.time, s.x, s.f_ext, s.m_ext, s.released_loads);
  const Clock::time_point element_start = Clock::now();
  const ShellForceResult elements = compute_internal_forces(model, s, dt);
  s.times.elements += seconds_since(element_start);
  const Clock::time_point contact_start = Clock::now();
  if (!model.contacts.empty() && !s.contact_off) {
    update_contact_offsets(model, s);  // only the contact uses them
  }
  compute_contact_forces(model, s, dt);
  s.times.contact += seconds_since(contact_start);
  return elements;
}

}  // namespace sf
