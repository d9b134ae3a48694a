#include "solver/step_forces.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <climits>

#include "core/errors.hpp"
#include "core/log.hpp"
#include "element/element_block.hpp"
#include "model/external_loads.hpp"

namespace sf {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The failure of this process's phase (none if `body` returns), typed for the agreement.
template <typename Body>
PhaseError phase_error_of(long key_if_unknown, Body&& body) {
  try {
    body();
    return {};
  } catch (const InputError& e) {
    return {PhaseError::Kind::input, key_if_unknown, e.what()};
  } catch (const InstabilityError& e) {
    return {PhaseError::Kind::instability, key_if_unknown, e.what()};
  } catch (const std::exception& e) {
    return {PhaseError::Kind::internal, key_if_unknown, e.what()};
  }
}

// Every process stops together with the failure they agree on, thrown as its own kind.
// `failures` is the number of processes that failed, summed exactly with the phase's other sums
// (so that a phase without failures needs no message of its own): the agreement on which failure
// to report is a collective call made only when some process failed.
void throw_agreed(Domain& domain, const ExactSum& failures, PhaseError local) {
  if (failures.round() == 0.0) {
    return;
  }
  const PhaseError e = domain.agree(std::move(local));
  switch (e.kind) {
    case PhaseError::Kind::none:
      return;
    case PhaseError::Kind::input:
      throw InputError(e.message);
    case PhaseError::Kind::instability:
      throw InstabilityError(e.message);
    case PhaseError::Kind::internal:
      throw std::runtime_error(e.message);
  }
}

// The elements' internal forces and moments into state.f_int, m_int: each element into its
// corners, then each node sums its corners in a fixed order (element/corner_forces.hpp).
ShellForceResult compute_internal_forces(const Model& model, SolutionState& s, double dt) {
  // The elements' critical steps at x come with the forces (the next step's bound). A failing
  // pass reports its lowest failing element, and every process agrees on the lowest of all.
  PhaseError failure = phase_error_of(LONG_MAX, [&] {
    run_element_pass(model.blank.part, ElementInputs{s.x, s.v, s.omega, dt}, s.shell,
                     s.element_pass, s.scaling.element_dt, s.domain->element_runs());
  });
  if (failure.failed()) {
    failure.key = s.element_pass.shares[0].failure.element;
    if (failure.kind == PhaseError::Kind::instability) {
      failure.message =
          fmt::format("{} at t = {:.6e} s, cycle {}", failure.message, s.time, s.cycle);
    }
  }
  // A failed pass's corners are assembled too (whatever they hold), as the other processes'
  // exchange expects them; nothing uses them, as the failure is thrown next.
  s.domain->assemble_corners(model.blank.node_corners, s.element_pass.corners, s.f_int, s.m_int);
  // The pass's exact works (left in its first share) made global, then rounded once.
  const ElementOutputs& total = s.element_pass.shares[0];
  ExactSum sums[4] = {total.internal_work, total.plastic_work, total.hourglass_work};
  sums[3].add(failure.failed() ? 1.0 : 0.0);
  s.domain->reduce(sums);
  throw_agreed(*s.domain, sums[3], std::move(failure));
  const ShellForceResult r{.hourglass_work = sums[2].round(),
                           .internal_work = sums[0].round(),
                           .plastic_work = sums[1].round()};
  s.element_dt_cycle = s.cycle;
  return r;
}

// The contact offset of every node: half the mean thickness of the elements around it (mm).
void update_contact_offsets(const Model& model, SolutionState& s) {
  s.domain->assemble_half_thickness(element_blocks(model.blank.part), model.blank.node_corners,
                                    s.shell.thickness, model.blank.inverse_element_count,
                                    s.half_thickness);
}

// The blank against a tool over the step dt just taken (s.v its mid-step velocity; dt = 0 on the
// first call).
ContactKinematics kinematics_against(const SolutionState& s, const ToolState& tool, double dt) {
  const Vec3 tool_step =
      dt > 0.0 ? Vec3(tool.displacement - tool.previous_displacement) : Vec3::Zero();
  return ContactKinematics{
      .x = s.x,
      .v = s.v,
      .half_thickness = s.half_thickness,
      .tool_displacement = tool.displacement,
      .tool_displacement_increment = tool_step,
      .dt = dt,
      .owned_nodes = s.domain->owned_nodes(),
      .ghost_nodes = s.domain->ghost_nodes(),
      .tool_rotation = tool.rotation,
      .tool_rotation_previous = dt > 0.0 ? tool.previous_rotation : tool.rotation};
}

// The exact sums of one contact call (left in the pair's first share), kContactSums of them.
constexpr int kContactSums = 12 + kTableEnds;

void add_contact_sums(const ContactShare& total, ExactSum* sums) {
  for (int c = 0; c < 3; ++c) {
    sums[c] = total.force_on_tool[c];
    sums[9 + c] = total.moment_on_tool[c];
  }
  sums[3] = total.energy;
  sums[4] = total.friction_work;
  const int counts[4] = {total.nodes_in_contact, total.sliding_nodes, total.sticking_nodes,
                         total.projection_fallbacks};
  for (int k = 0; k < 4; ++k) {
    sums[5 + k] = ExactSum();
    sums[5 + k].add(counts[k]);  // integers: exact
  }
  for (int e = 0; e < kTableEnds; ++e) {
    sums[12 + e] = ExactSum();
    sums[12 + e].add(total.beyond_table[e]);
  }
}

ContactResult contact_result(const ExactSum* sums) {
  ContactResult r;
  r.force_on_tool = Vec3(sums[0].round(), sums[1].round(), sums[2].round());
  r.energy = sums[3].round();
  r.friction_work = sums[4].round();
  r.nodes_in_contact = static_cast<int>(sums[5].round());
  r.sliding_nodes = static_cast<int>(sums[6].round());
  r.sticking_nodes = static_cast<int>(sums[7].round());
  r.projection_fallbacks = static_cast<int>(sums[8].round());
  r.moment_on_tool = Vec3(sums[9].round(), sums[10].round(), sums[11].round());
  for (int e = 0; e < kTableEnds; ++e) {
    r.beyond_table[e] = static_cast<int>(sums[12 + e].round());
  }
  return r;
}

// Warns, once a run for each end of each pair's friction tables, when a node met a pressure or
// slip speed beyond it (every process knows it from the reduced counts; rank 0 speaks).
void warn_beyond_friction_tables(const Model& model, std::size_t k, const ContactResult& r,
                                 SolutionState& s) {
  ContactState& state = s.contacts[k];
  for (int e = 0; e < kTableEnds; ++e) {
    if (r.beyond_table[e] > 0 && !state.warned_beyond_table[e]) {
      state.warned_beyond_table[e] = true;
      const ContactInterface& c = model.contacts[k];
      const std::string where = fmt::format("{}: contact[{}] (tool '{}')", model.case_file.string(),
                                            k, model.tools[static_cast<std::size_t>(c.tool)].name);
      log_warning("{}", friction_table_warning(c.pair.friction, static_cast<TableEnd>(e), where,
                                               s.time, s.cycle));
    }
  }
}

// The penalty contact of every pair into state.f_contact (zeroed here), the tools' reactions and
// contact counts, the spring energy and the friction work. All pairs' sums are made global in
// one reduction; a failure is that of the first failing pair at its lowest failing node, as a
// serial run meets it.
void compute_contact_forces(const Model& model, SolutionState& s, double dt) {
  s.f_contact.setZero();
  s.contact_spring_energy = 0.0;
  for (ToolState& t : s.tools) {
    t.force.setZero();
    t.moment.setZero();
    t.nodes_in_contact = 0;
  }
  if (s.contact_off || model.contacts.empty()) {
    for (ContactState& c : s.contacts) {
      c.normal_force.setZero();  // the results: nothing presses
    }
    return;
  }
  const std::size_t pairs = model.contacts.size();
  std::vector<ExactSum>& sums = s.contact_sums;  // scratch: no allocation after the first call
  sums.resize(kContactSums * pairs + 1);
  sums.back() = ExactSum();
  PhaseError failure;
  for (std::size_t k = 0; k < pairs; ++k) {
    const ContactInterface& c = model.contacts[k];
    const ToolState& tool = s.tools[static_cast<std::size_t>(c.tool)];
    if (tool.held) {  // out of play: an operation leaves it out (or springback holds it)
      size_contact_state(c.pair, s.contacts[k], static_cast<int>(s.x.cols()));
      s.contacts[k].normal_force.setZero();
      std::fill_n(sums.data() + kContactSums * k, kContactSums, ExactSum());
      continue;
    }
    const ContactKinematics kinematics = kinematics_against(s, tool, dt);
    PhaseError pair_failure = phase_error_of(
        LONG_MAX, [&] { compute_penalty_contact(c.pair, s.contacts[k], kinematics, s.f_contact); });
    if (pair_failure.failed() && !failure.failed()) {
      // Pair by pair, then node by node (a failure without a node: after the pair's nodes).
      const long nodes = static_cast<long>(s.x.cols()) + 1;
      const long node = std::min<long>(s.contacts[k].shares[0].first_failing_node(), nodes - 1);
      pair_failure.key = static_cast<long>(k) * nodes + node;
      failure = std::move(pair_failure);
      sums.back().add(1.0);
    }
    add_contact_sums(s.contacts[k].shares[0], sums.data() + kContactSums * k);
  }
  s.domain->reduce(sums);
  throw_agreed(*s.domain, sums.back(), std::move(failure));
  for (std::size_t k = 0; k < pairs; ++k) {
    const ContactResult r = contact_result(sums.data() + kContactSums * k);
    ToolState& tool = s.tools[static_cast<std::size_t>(model.contacts[k].tool)];
    tool.force += r.force_on_tool;
    tool.moment += r.moment_on_tool;
    tool.nodes_in_contact += r.nodes_in_contact;
    s.contact_spring_energy += r.energy;
    s.energies.friction_work += r.friction_work;
    warn_beyond_friction_tables(model, k, r, s);
  }
}

// The exact sums of one drawbead call: the reaction (3), its moment (3), the slip work.
constexpr int kBeadSums = 7;

// The drawbead lines' forces into state.f_contact (after the contact pairs'), their reactions to
// their tools' forces and moments, their slip work to the energies. A bead of a tool out of play
// acts on nothing and starts afresh.
void add_drawbead_forces(const Model& model, SolutionState& s, double dt) {
  if (s.contact_off || model.drawbeads.empty()) {
    return;
  }
  std::vector<ExactSum>& sums = s.contact_sums;  // scratch, after the contact's use of it
  sums.assign(kBeadSums * model.drawbeads.size(), ExactSum());
  for (std::size_t b = 0; b < model.drawbeads.size(); ++b) {
    const DrawbeadInterface& bead = model.drawbeads[b];
    const ToolState& tool = s.tools[static_cast<std::size_t>(bead.tool)];
    if (tool.held) {
      s.drawbeads[b].restraint.setZero();
      continue;
    }
    compute_drawbead_forces(bead.line, s.drawbeads[b], kinematics_against(s, tool, dt),
                            s.f_contact);
    const DrawbeadShare& total = s.drawbeads[b].shares[0];
    for (int c = 0; c < 3; ++c) {
      sums[kBeadSums * b + c] = total.force_on_tool[c];
      sums[kBeadSums * b + 3 + c] = total.moment_on_tool[c];
    }
    sums[kBeadSums * b + 6] = total.work;
  }
  s.domain->reduce(sums);
  for (std::size_t b = 0; b < model.drawbeads.size(); ++b) {
    ToolState& tool = s.tools[static_cast<std::size_t>(model.drawbeads[b].tool)];
    const ExactSum* r = sums.data() + kBeadSums * b;
    tool.force += Vec3(r[0].round(), r[1].round(), r[2].round());
    tool.moment += Vec3(r[3].round(), r[4].round(), r[5].round());
    s.energies.drawbead_work += r[6].round();
  }
}

// The pressure loads (following the deforming surface) added to s.f_ext over the processes: each
// process writes its elements' shares to their corner slots, flagged where the element carries
// the load, and every held node adds its flagged corners in the serial order.
void add_pressure_forces(const Model& model, SolutionState& s) {
  if (model.loads.pressures.empty()) {
    return;
  }
  const ShellPart& part = model.blank.part;
  const ElementBlocks blocks = element_blocks(part);
  const auto n_corners = static_cast<std::size_t>(corner_count(part));
  if (s.pressure_corners.size() != kLoadCornerWidth * n_corners) {
    s.pressure_corners.assign(kLoadCornerWidth * n_corners, 0.0);
  }
  const ElementRun all{0, element_count(part)};
  const std::span<const ElementRun> runs = s.domain->element_runs().empty()
                                               ? std::span<const ElementRun>(&all, 1)
                                               : s.domain->element_runs();
  for (const PressureLoad& load : model.loads.pressures) {
    const double p = load.scale.value(s.time) * load.pressure;
    auto next = load.elements.begin();  // ascending, as the runs
    for (const ElementRun& run : runs) {
      for (int e = run.begin; e < run.end; ++e) {
        next = std::lower_bound(next, load.elements.end(), e);
        const bool carries = next != load.elements.end() && *next == e;
        const ElementBlock& block = blocks.of(e);
        const Vec3 f = carries ? pressure_node_force(block, s.x, e, p) : Vec3::Zero();
        const int n_nodes = block.nodes_per_element();
        const int slot = block.corner_slot(e, 0);
        double* c =
            s.pressure_corners.data() + kLoadCornerWidth * static_cast<std::ptrdiff_t>(slot);
        for (int a = 0; a < n_nodes; ++a, c += kLoadCornerWidth) {
          c[0] = f(0);
          c[1] = f(1);
          c[2] = f(2);
          c[3] = carries ? 1.0 : 0.0;
        }
      }
    }
    s.domain->add_flagged_corner_forces(model.blank.node_corners, s.pressure_corners, s.f_ext);
  }
}

}  // namespace

ShellForceResult compute_forces(const Model& model, SolutionState& s, double dt) {
  compute_nodal_loads(model, s.time, s.f_ext, s.m_ext, s.released_loads);
  add_pressure_forces(model, s);
  const Clock::time_point element_start = Clock::now();
  const ShellForceResult elements = compute_internal_forces(model, s, dt);
  s.times.elements += seconds_since(element_start);
  const Clock::time_point contact_start = Clock::now();
  if (!model.contacts.empty() && !s.contact_off) {
    update_contact_offsets(model, s);  // only the contact uses them
  }
  compute_contact_forces(model, s, dt);
  add_drawbead_forces(model, s, dt);
  s.times.contact += seconds_since(contact_start);
  return elements;
}

}  // namespace sf
