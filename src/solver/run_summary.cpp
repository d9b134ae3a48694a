#include <omp.h>

#include "solver/run_summary.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>

#include "casefile/unit_system.hpp"
#include "core/build_info.hpp"
#include "core/errors.hpp"
#include "model/operation_plan.hpp"
#include "solver/draw_in.hpp"
#include "solver/implicit_summary.hpp"
#include "solver/tool_update.hpp"

namespace sf {

namespace {

std::string format_vector(const Vec3& v) {
  return fmt::format("({:.5g}, {:.5g}, {:.5g})", v.x(), v.y(), v.z());
}

/// "  reaction boundary[0] 'clamp': force (...) N, moment (...) N mm[; in its axes ...]"
std::string format_reaction(const ConstraintReaction& c) {
  std::string text = fmt::format("  reaction {:<22} force {} N, moment {} N mm",
                                 fmt::format("{} '{}'", c.entry, c.group), format_vector(c.force),
                                 format_vector(c.moment));
  if (c.axes) {
    text += fmt::format("; in its axes {} N, {} N mm", format_vector(c.axes->transpose() * c.force),
                        format_vector(c.axes->transpose() * c.moment));
  }
  if (c.along) {
    text += fmt::format("; along {} {:.6g} {}", c.dof, *c.along, c.dof[0] == 'r' ? "N mm" : "N");
  }
  return text;
}

nlohmann::json json_vector(const Vec3& v) {
  return nlohmann::json::array({v.x(), v.y(), v.z()});
}

nlohmann::json reaction_json(const ConstraintReaction& c) {
  nlohmann::json j = {
      {"group", c.group}, {"force_N", json_vector(c.force)}, {"moment_Nmm", json_vector(c.moment)}};
  if (c.axes) {
    j["axes"] = nlohmann::json::array(
        {json_vector(c.axes->col(0)), json_vector(c.axes->col(1)), json_vector(c.axes->col(2))});
    j["force_in_axes_N"] = json_vector(c.axes->transpose() * c.force);
    j["moment_in_axes_Nmm"] = json_vector(c.axes->transpose() * c.moment);
  }
  if (c.along) {
    j["dof"] = c.dof;
    j[c.dof[0] == 'r' ? "along_dof_Nmm" : "along_dof_N"] = *c.along;
  }
  return j;
}

// The ranks' own work (step phases less their time in messages) and their time in messages.
std::string rank_balance_line(const std::vector<std::array<double, 6>>& per_rank) {
  double work_min = 1e300, work_max = 0.0, work_sum = 0.0, comm_min = 1e300, comm_max = 0.0;
  for (const auto& t : per_rank) {
    const double work = t[0] + t[1] + t[2] + t[3] - t[5];
    work_min = std::min(work_min, work);
    work_max = std::max(work_max, work);
    work_sum += work;
    comm_min = std::min(comm_min, t[5]);
    comm_max = std::max(comm_max, t[5]);
  }
  const double mean = work_sum / static_cast<double>(per_rank.size());
  return fmt::format(
      "  ranks               {}: own work {:.2f} to {:.2f} s (max / mean {:.3f}), messages "
      "{:.2f} to {:.2f} s",
      per_rank.size(), work_min, work_max, mean > 0.0 ? work_max / mean : 0.0, comm_min, comm_max);
}

}  // namespace

void set_per_unit_costs(RunSummary& r, const PhaseTimes& t, double element_cycles,
                        double node_cycles) {
  const double wall_seconds = r.wall_seconds;
  if (element_cycles > 0.0) {
    r.ns_per_element_cycle = 1e9 * wall_seconds / element_cycles;
  }
  if (wall_seconds > 0.0) {
    r.element_share = t.elements / wall_seconds;
    r.contact_share = t.contact / wall_seconds;
  }
  if (element_cycles > 0.0 && node_cycles > 0.0) {
    const double per_element_cycle = 1e9 / element_cycles;
    r.phase_ns = {t.elements * per_element_cycle,
                  t.contact * per_element_cycle,
                  t.time_step * per_element_cycle,
                  t.nodal * per_element_cycle,
                  t.output * per_element_cycle,
                  (wall_seconds - t.elements - t.contact - t.time_step - t.nodal - t.output) *
                      per_element_cycle};
    r.contact_ns_per_node_cycle = 1e9 * t.contact / node_cycles;
  }
}

// Each part's thinning and plastic strain (a blank of several parts; none for one part).
std::vector<PartSummary> summarise_parts(const Model& model, const SolutionState& s) {
  std::vector<PartSummary> parts;
  if (model.blank.parts.size() < 2) {
    return parts;
  }
  for (const BlankPartInfo& p : model.blank.parts) {
    parts.push_back({.name = p.name,
                     .initial_thickness = p.thickness,
                     .min_thickness = std::numeric_limits<double>::infinity(),
                     .max_thinning = 0.0,
                     .max_plastic_strain = 0.0});
  }
  const auto n_points = static_cast<std::size_t>(s.shell.n_points);
  for (int e = 0; e < s.shell.n_elements; ++e) {
    PartSummary& p = parts[static_cast<std::size_t>(material_index(model.blank.part, e))];
    const double t = s.shell.thickness[static_cast<std::size_t>(e)];
    p.min_thickness = std::min(p.min_thickness, t);
    p.max_thinning = std::max(p.max_thinning, 1.0 - t / p.initial_thickness);
    for (std::size_t k = 0; k < n_points; ++k) {
      p.max_plastic_strain =
          std::max(p.max_plastic_strain, s.shell.eps_p[static_cast<std::size_t>(e) * n_points + k]);
    }
  }
  return parts;
}

RunSummary make_run_summary(const Model& model, const SolutionState& s, double wall_seconds) {
  RunSummary r;
  r.units = model.output.units;
  r.cycles = s.cycle;
  r.end_time = s.time;
  r.wall_seconds = wall_seconds;
  r.elements = element_count(model.blank.part);
  r.nodes = static_cast<int>(model.blank.mesh.nodes.cols());
  r.threads = omp_get_max_threads();
  set_per_unit_costs(r, s.times, static_cast<double>(r.cycles) * r.elements,
                     static_cast<double>(r.cycles) * r.nodes);
  r.energies = s.energies;
  r.drawbeads = !model.drawbeads.empty();
  r.peak_kinetic_ratio = s.peak_kinetic_ratio;
  r.physical_mass = model.blank.physical_mass;
  r.added_mass = s.scaling.added_mass;
  r.added_mass_fraction = r.added_mass / r.physical_mass;
  r.scaled_elements = s.scaling.scaled_elements;
  r.min_time_step = s.min_stable_dt;
  r.max_time_step = s.max_stable_dt;
  r.min_time_step_element = s.min_dt_element;
  const auto [tmin, tmax] = std::minmax_element(s.shell.thickness.begin(), s.shell.thickness.end());
  r.min_thickness = *tmin;
  r.max_thickness = *tmax;
  r.max_plastic_strain = *std::max_element(s.shell.eps_p.begin(), s.shell.eps_p.end());
  r.parts = summarise_parts(model, s);
  for (std::size_t t = 0; t < model.tools.size(); ++t) {
    ToolSummary ts;
    ts.name = model.tools[t].name;
    ts.travel = s.tools[t].travel;
    ts.speed = s.tools[t].speed;
    ts.final_force = -s.tools[t].force.dot(model.tools[t].direction());
    ts.peak_force = s.tools[t].peak_force;
    if (const auto& driven = model.tools[t].force_control) {
      ts.force_controlled = true;
      ts.applied_force = driven->applied_force(s.time, s.tools[t].travel);
    }
    if (ever_turns(model, static_cast<int>(t))) {
      ts.turns = true;
      ts.angle = s.tools[t].angle * (180.0 / std::numbers::pi);
      ts.torque = press_torque(model, static_cast<int>(t), s.tools[t]);
    }
    r.tools.push_back(ts);
  }
  const double end_stroke = model.time.stroke_tool >= 0
                                ? s.tools[static_cast<std::size_t>(model.time.stroke_tool)].travel
                                : 0.0;
  for (const DrawInConfig& dc : model.output.draw_ins) {
    DrawInResult d;
    d.name = dc.name;
    d.computed = measure_draw_in(model, dc, s.x);
    d.measured = dc.measured;
    d.measured_stroke = dc.measured_stroke;
    d.end_stroke = end_stroke;
    d.source = dc.source;
    // Same stroke within 1e-6 of it: the run's end condition lands on the stroke to round-off.
    d.comparable = dc.measured >= 0.0 &&
                   (dc.measured_stroke == 0.0 ||
                    std::abs(end_stroke - dc.measured_stroke) <= 1e-6 * dc.measured_stroke);
    r.draw_ins.push_back(d);
  }
  Matrix3X reaction_force, reaction_moment;
  compute_reactions(model, s, reaction_force, reaction_moment);
  if (!model.output.reactions.empty()) {
    r.reactions = sum_reactions_by_entry(model, reaction_force, reaction_moment);
  }
  for (const HistoryGroupConfig& h : model.output.history_groups) {
    const NodeGroup& group = model.blank.group(h.group);
    r.history_groups.push_back(
        {h.group, static_cast<int>(group.nodes.size()), h,
         measure_group(model, s, group.nodes, {reaction_force, reaction_moment})});
  }
  return r;
}

namespace {

std::string format_group_vector(const Vec3& v) {
  return fmt::format("({:.6g}, {:.6g}, {:.6g})", v.x(), v.y(), v.z());
}

template <typename Add>
void add_history_groups(const RunSummary& r, const Add& add) {
  const UnitSystem units = parse_unit_system(r.units);
  for (const HistoryGroupResult& g : r.history_groups) {
    std::string text;
    const auto put = [&text](const std::string& part) {
      text += (text.empty() ? "" : ", ") + part;
    };
    if (g.quantities.displacement) {
      put(fmt::format("displacement {} {}", format_group_vector(g.values.displacement),
                      units.length));
    }
    if (g.quantities.velocity) {
      put(fmt::format("velocity {} {}", format_group_vector(g.values.velocity), units.velocity()));
    }
    if (g.quantities.rotation) {
      put(fmt::format("rotation {} rad", format_group_vector(g.values.rotation)));
    }
    if (g.quantities.reaction) {
      put(fmt::format("reaction {} {}, moment {} {}", format_group_vector(g.values.reaction_force),
                      units.force, format_group_vector(g.values.reaction_moment), units.moment()));
    }
    add(fmt::format("  group {:<13} ({} nodes) {}", g.group, g.nodes, text));
  }
}

nlohmann::json vector_json(const Vec3& v) {
  return nlohmann::json::array({v.x(), v.y(), v.z()});
}

nlohmann::json history_groups_json(const RunSummary& r) {
  const UnitSystem units = parse_unit_system(r.units);
  nlohmann::json j = nlohmann::json::object();
  for (const HistoryGroupResult& g : r.history_groups) {
    nlohmann::json entry = {{"nodes", g.nodes}};
    nlohmann::json unit_names = nlohmann::json::object();
    if (g.quantities.displacement) {
      entry["displacement"] = vector_json(g.values.displacement);
      unit_names["displacement"] = units.length;
    }
    if (g.quantities.velocity) {
      entry["velocity"] = vector_json(g.values.velocity);
      unit_names["velocity"] = units.velocity();
    }
    if (g.quantities.rotation) {
      entry["rotation"] = vector_json(g.values.rotation);
      unit_names["rotation"] = "rad";
    }
    if (g.quantities.reaction) {
      entry["reaction_force"] = vector_json(g.values.reaction_force);
      entry["reaction_moment"] = vector_json(g.values.reaction_moment);
      unit_names["reaction_force"] = units.force;
      unit_names["reaction_moment"] = units.moment();
    }
    entry["units"] = unit_names;
    j[g.group] = entry;
  }
  return j;
}

}  // namespace

// The lines of an explicit run's cost, time step and mass (a static analysis has none of them).
template <typename Add>
void add_explicit_run_lines(const RunSummary& r, const UnitSystem& u, const Add& add) {
  add(fmt::format("  time split          elements {:.0f} %, contact {:.0f} %, rest {:.0f} %",
                  100.0 * r.element_share, 100.0 * r.contact_share,
                  100.0 * (1.0 - r.element_share - r.contact_share)));
  add(fmt::format("  time step           {:.4e} to {:.4e} {} (smallest limited by element {})",
                  r.min_time_step, r.max_time_step, u.time, r.min_time_step_element));
}

template <typename Add>
void add_energy_lines(const RunSummary& r, const UnitSystem& u, const Add& add) {
  const Energies& e = r.energies;
  if (r.static_step) {
    add(fmt::format("  energies [{}]     internal {:.4e}, hourglass {:.4e}, external work {:.4e}",
                    u.moment(), e.internal, e.hourglass, e.external_work));
  } else {
    add(
        fmt::format("  energies [{}]     kinetic {:.4e}, internal {:.4e}, hourglass {:.4e}, "
                    "contact {:.4e}, external work {:.4e}",
                    u.moment(), e.kinetic, e.internal, e.hourglass, e.contact, e.external_work));
    add(
        fmt::format("                      damping {:.4e}, mass scaling {:.4e}; plastic work "
                    "{:.4e} (part of internal), friction work {:.4e} (part of contact)",
                    e.damping, e.mass_scaling, e.plastic_work, e.friction_work));
    if (r.drawbeads) {
      add(fmt::format("                      drawbead work {:.4e} (part of contact)",
                      e.drawbead_work));
    }
  }
  add(fmt::format("  energy balance      {:+.3e} (total - external work, relative)",
                  e.balance_error()));
  if (r.static_step) {
    return;
  }
  add(fmt::format("  kinetic / internal  {:.4f} at the end, {:.4f} at most after 10% of the run",
                  e.kinetic_ratio(), r.peak_kinetic_ratio));
  add(fmt::format("  added mass          {:.4e} {}, {:.2f} % of {:.4e} {} ({} elements scaled)",
                  r.added_mass, u.mass, 100.0 * r.added_mass_fraction, r.physical_mass, u.mass,
                  r.scaled_elements));
}

template <class Add>
void add_operation_lines(const RunSummary& r, const UnitSystem& u, const Add& add) {
  for (std::size_t k = 0; k < r.operations.size(); ++k) {
    const OperationRecord& o = r.operations[k];
    add(
        fmt::format("  operation {}         '{}' ({}): t = {:.4e} to {:.4e} {}, cycles {} to {}, "
                    "{:.1f} s of wall time; ended by {}",
                    k + 1, o.name, o.kind, o.start_time, o.end_time, u.time, o.start_cycle,
                    o.end_cycle, o.wall_seconds, o.ended_by));
  }
}

nlohmann::json operations_json(const RunSummary& r) {
  nlohmann::json list = nlohmann::json::array();
  for (const OperationRecord& o : r.operations) {
    list.push_back({{"name", o.name},
                    {"kind", o.kind},
                    {"ended_by", o.ended_by},
                    {"start_time_s", o.start_time},
                    {"end_time_s", o.end_time},
                    {"start_cycle", o.start_cycle},
                    {"end_cycle", o.end_cycle},
                    {"first_frame", o.first_frame},
                    {"last_frame", o.last_frame},
                    {"wall_seconds", o.wall_seconds}});
  }
  return list;
}

std::string format_run_summary(const RunSummary& r) {
  std::string text;
  auto add = [&text](const std::string& line) { text += line + "\n"; };
  const UnitSystem u = parse_unit_system(r.units);
  add(fmt::format("Run summary"));
  if (r.static_step) {
    add(fmt::format("  increments          {} converged, to the pseudo-time {:.6e} {}", r.cycles,
                    r.end_time, u.time));
    add(fmt::format("  wall time           {:.2f} s ({} elements)", r.wall_seconds, r.elements));
  } else {
    add(fmt::format("  cycles              {}", r.cycles));
    add(fmt::format("  end time            {:.6e} {}", r.end_time, u.time));
    add(fmt::format(
        "  wall time           {:.2f} s ({:.0f} ns per element-cycle, {} elements, "
        "{} thread{}{})",
        r.wall_seconds, r.ns_per_element_cycle, r.elements, r.threads, r.threads == 1 ? "" : "s",
        r.ranks == 1 ? std::string() : fmt::format(" x {} MPI ranks", r.ranks)));
    const RunSummary::PhaseCosts& p = r.phase_ns;
    add(
        fmt::format("  per element-cycle   elements {:.0f}, contact {:.0f}, time step {:.0f}, "
                    "nodal {:.0f}, output {:.0f}, other {:.0f} ns",
                    p.elements, p.contact, p.time_step, p.nodal, p.output, p.other));
    if (r.phase_seconds_per_rank.size() > 1) {
      add(rank_balance_line(r.phase_seconds_per_rank));
    }
    add_explicit_run_lines(r, u, add);
    add_operation_lines(r, u, add);
  }
  add_energy_lines(r, u, add);
  add(fmt::format("  thickness           {:.4f} to {:.4f} {}", r.min_thickness, r.max_thickness,
                  u.length));
  add(fmt::format("  max plastic strain  {:.4f}", r.max_plastic_strain));
  for (const PartSummary& p : r.parts) {
    add(
        fmt::format("  part {:<14} t0 {:.4f} {}, min {:.4f} {} (thinning {:.1f} %), max plastic "
                    "strain {:.4f}",
                    p.name, p.initial_thickness, u.length, p.min_thickness, u.length,
                    100.0 * p.max_thinning, p.max_plastic_strain));
  }
  for (const ToolSummary& t : r.tools) {
    add(fmt::format("  tool {:<14} travel {:8.3f} {}, force {:10.1f} {}, peak {:10.1f} {}{}",
                    t.name, t.travel, u.length, t.final_force, u.force, t.peak_force, u.force,
                    t.force_controlled
                        ? fmt::format(" (force-controlled: applied {:.1f} {}, speed {:.4g} {})",
                                      t.applied_force, u.force, t.speed, u.velocity())
                        : std::string()));
    if (t.turns) {
      add(fmt::format("  tool {:<14} angle  {:8.3f} deg, torque {:10.1f} {}", t.name, t.angle,
                      t.torque, u.moment()));
    }
  }
  for (const DrawInResult& d : r.draw_ins) {
    if (!std::isfinite(d.computed)) {
      add(fmt::format("  draw-in {:<11} none: a trim removed its nodes", d.name));
    } else if (d.measured >= 0.0 && !d.comparable) {
      add(fmt::format(
          "  draw-in {:<11} {:7.3f} {}   (measured {:.3f} {} at {:g} {} of stroke; this run "
          "ended at {:.3f} {}: not compared)",
          d.name, d.computed, u.length, d.measured, u.length, d.measured_stroke, u.length,
          d.end_stroke, u.length));
    } else if (d.measured >= 0.0) {
      add(fmt::format(
          "  draw-in {:<11} {:7.3f} {}   measured {:7.3f} {}   deviation {:+.1f} %  ({})", d.name,
          d.computed, u.length, d.measured, u.length,
          100.0 * (d.computed - d.measured) / d.measured, d.source));
    } else {
      add(fmt::format("  draw-in {:<11} {:7.3f} {}", d.name, d.computed, u.length));
    }
  }
  add_history_groups(r, add);
  for (const SearchAuditSummary& a : r.search_audits) {
    if (a.max_misses == 0) {
      add(fmt::format(
          "  search audit {:<8} {} search: no misses in {} audits ({} nodes within reach "
          "at the end)",
          a.tool, a.search, a.audits, a.final_nodes_checked));
      continue;
    }
    add(fmt::format(
        "  search audit {:<8} {} search: {} misses of {} nodes within reach at the end; "
        "at most {} (t = {:.4e} {}), {} over {} audits; largest gap error {:.3e} {}",
        a.tool, a.search, a.final_misses, a.final_nodes_checked, a.max_misses, a.max_misses_time,
        u.time, a.total_misses, a.audits, a.max_gap_error, u.length));
  }
  for (const ConstraintReaction& c : r.reactions) {
    add(format_reaction(c));
  }
  if (r.static_step) {
    add("Static step");
    text += format_implicit_step(*r.static_step);
  }
  if (r.springback) {
    text += format_springback(*r.springback);
  }
  return text;
}

void write_run_summary_json(const RunSummary& r, const std::filesystem::path& file) {
  nlohmann::json j;
  j["version"] = build_info::version;
  j["git_hash"] = build_info::git_hash;
  j["cycles"] = r.cycles;
  j["end_time_s"] = r.end_time;
  j["wall_seconds"] = r.wall_seconds;
  j["ns_per_element_cycle"] = r.ns_per_element_cycle;
  j["element_time_share"] = r.element_share;
  j["contact_time_share"] = r.contact_share;
  j["phase_ns_per_element_cycle"] = {
      {"elements", r.phase_ns.elements},   {"contact", r.phase_ns.contact},
      {"time_step", r.phase_ns.time_step}, {"nodal", r.phase_ns.nodal},
      {"output", r.phase_ns.output},       {"other", r.phase_ns.other}};
  j["contact_ns_per_node_cycle"] = r.contact_ns_per_node_cycle;
  j["elements"] = r.elements;
  j["nodes"] = r.nodes;
  j["threads"] = r.threads;
  j["ranks"] = r.ranks;
  if (!r.phase_seconds_per_rank.empty()) {  // {phase: [s on rank 0, rank 1, ...]}
    const char* names[6] = {"elements", "contact", "time_step", "nodal", "output", "communication"};
    nlohmann::json per_rank = nlohmann::json::object();
    for (std::size_t k = 0; k < 6; ++k) {
      nlohmann::json seconds = nlohmann::json::array();
      for (const auto& t : r.phase_seconds_per_rank) {
        seconds.push_back(t[k]);
      }
      per_rank[names[k]] = seconds;
    }
    j["phase_seconds_per_rank"] = per_rank;
  }
  j["energy_Nmm"] = {{"kinetic", r.energies.kinetic},
                     {"internal", r.energies.internal},
                     {"hourglass", r.energies.hourglass},
                     {"contact", r.energies.contact},
                     {"damping", r.energies.damping},
                     {"initial_kinetic", r.energies.initial_kinetic},
                     {"mass_scaling", r.energies.mass_scaling},
                     {"plastic_work", r.energies.plastic_work},
                     {"friction_work", r.energies.friction_work},
                     {"external_work", r.energies.external_work},
                     {"half_kick", r.energies.half_kick_change()},
                     {"balance_error", r.energies.balance_error()}};
  if (r.drawbeads) {
    j["energy_Nmm"]["drawbead_work"] = r.energies.drawbead_work;
  }
  j["kinetic_ratio_end"] = r.energies.kinetic_ratio();
  j["kinetic_ratio_peak"] = r.peak_kinetic_ratio;
  j["physical_mass_tonne"] = r.physical_mass;
  j["added_mass_tonne"] = r.added_mass;
  j["added_mass_fraction"] = r.added_mass_fraction;
  j["added_mass_percent"] = 100.0 * r.added_mass_fraction;
  j["scaled_elements"] = r.scaled_elements;
  j["time_step_s"] = {
      {"min", r.min_time_step}, {"max", r.max_time_step}, {"min_element", r.min_time_step_element}};
  j["min_thickness_mm"] = r.min_thickness;
  j["max_thickness_mm"] = r.max_thickness;
  j["max_plastic_strain"] = r.max_plastic_strain;
  for (const PartSummary& p : r.parts) {
    j["parts"][p.name] = {{"initial_thickness_mm", p.initial_thickness},
                          {"min_thickness_mm", p.min_thickness},
                          {"max_thinning_percent", 100.0 * p.max_thinning},
                          {"max_plastic_strain", p.max_plastic_strain}};
  }
  for (const ToolSummary& t : r.tools) {
    j["tools"][t.name] = {{"travel_mm", t.travel},
                          {"speed_mm_s", t.speed},
                          {"final_force_N", t.final_force},
                          {"peak_force_N", t.peak_force}};
    if (t.force_controlled) {
      j["tools"][t.name]["applied_force_N"] = t.applied_force;
    }
    if (t.turns) {
      j["tools"][t.name]["angle_deg"] = t.angle;
      j["tools"][t.name]["torque_Nmm"] = t.torque;
    }
  }
  for (const DrawInResult& d : r.draw_ins) {
    nlohmann::json entry = {{"computed_mm", d.computed}};
    if (d.measured >= 0.0) {
      entry["measured_mm"] = d.measured;
      entry["source"] = d.source;
      entry["measured_stroke_mm"] = d.measured_stroke;
      entry["compared"] = d.comparable;
    }
    j["draw_in"][d.name] = entry;
  }
  for (const SearchAuditSummary& a : r.search_audits) {
    j["search_audit"][a.tool] = {{"search", a.search},
                                 {"audits", a.audits},
                                 {"final_misses", a.final_misses},
                                 {"final_nodes_checked", a.final_nodes_checked},
                                 {"max_misses", a.max_misses},
                                 {"max_misses_time_s", a.max_misses_time},
                                 {"total_misses", a.total_misses},
                                 {"max_gap_error_mm", a.max_gap_error}};
  }
  for (const ConstraintReaction& c : r.reactions) {
    j["reactions"][c.entry] = reaction_json(c);
  }
  if (!r.history_groups.empty()) {
    j["history"] = history_groups_json(r);
  }
  if (r.static_step) {
    j["static_step"] = implicit_step_json(*r.static_step);
  }
  if (r.springback) {
    j["springback"] = springback_json(*r.springback);
  }
  if (!r.operations.empty()) {
    j["operations"] = operations_json(r);
  }
  std::ofstream out(file);
  if (!out) {
    throw InputError(fmt::format("cannot write {}", file.string()));
  }
  out << j.dump(2) << "\n";
}

}  // namespace sf
