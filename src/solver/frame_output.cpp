#include "solver/frame_output.hpp"

#include <fmt/core.h>

#include <numbers>

#include "casefile/unit_system.hpp"
#include "core/build_info.hpp"
#include "model/operation_plan.hpp"
#include "solver/draw_in.hpp"
#include "solver/reactions.hpp"
#include "solver/state_fields.hpp"
#include "solver/tool_update.hpp"

namespace sf {

namespace {

// A history column and how its value is read (the [[history]] groups' columns, computed
// together, come after these).
struct HistoryValue {
  HistoryColumn column;
  HistoryReader value;
};

// Every column but the groups', each named and read in one place.
std::vector<HistoryValue> history_values(const Model& model) {
  const UnitSystem units = parse_unit_system(model.output.units);
  const std::string energy = units.moment();
  using M = const Model&;
  using S = const SolutionState&;
  using A = const SearchAuditRecorder&;
  std::vector<HistoryValue> v = {
      {{"time", units.time}, [](M, S s, A) { return s.time; }},
      {{"time_step", units.time}, [](M, S s, A) { return s.dt; }},
      {{"stable_time_step", units.time}, [](M, S s, A) { return s.stable_dt; }},
      {{"time_step_element", "-"}, [](M, S s, A) { return static_cast<double>(s.dt_element); }},
      {{"kinetic_energy", energy}, [](M, S s, A) { return s.energies.kinetic; }},
      {{"internal_energy", energy}, [](M, S s, A) { return s.energies.internal; }},
      {{"hourglass_energy", energy}, [](M, S s, A) { return s.energies.hourglass; }},
      {{"contact_energy", energy}, [](M, S s, A) { return s.energies.contact; }},
      {{"damping_energy", energy}, [](M, S s, A) { return s.energies.damping; }},
      {{"mass_scaling_energy", energy}, [](M, S s, A) { return s.energies.mass_scaling; }},
      {{"plastic_work", energy}, [](M, S s, A) { return s.energies.plastic_work; }},
      {{"friction_work", energy}, [](M, S s, A) { return s.energies.friction_work; }},
      {{"external_work", energy}, [](M, S s, A) { return s.energies.external_work; }},
      {{"half_kick_energy", energy}, [](M, S s, A) { return s.energies.half_kick_change(); }},
      {{"energy_balance_error", "-"}, [](M, S s, A) { return s.energies.balance_error(); }},
      {{"added_mass", units.mass}, [](M, S s, A) { return s.scaling.added_mass; }},
      {{"added_mass_percent", "%"},
       [](M m, S s, A) { return 100.0 * s.scaling.added_mass / m.blank.physical_mass; }},
      {{"scaled_elements", "-"},
       [](M, S s, A) { return static_cast<double>(s.scaling.scaled_elements); }},
  };
  if (!model.drawbeads.empty()) {
    v.push_back({{"drawbead_work", energy}, [](M, S s, A) { return s.energies.drawbead_work; }});
  }
  for (std::size_t t = 0; t < model.tools.size(); ++t) {
    const std::string& name = model.tools[t].name;
    v.push_back({{name + "_travel", units.length}, [t](M, S s, A) { return s.tools[t].travel; }});
    v.push_back({{name + "_speed", units.velocity()}, [t](M, S s, A) { return s.tools[t].speed; }});
    // Positive when the blank resists the tool's motion (the punch force; a holder's force).
    v.push_back({{name + "_force", units.force},
                 [t](M m, S s, A) { return -s.tools[t].force.dot(m.tools[t].direction()); }});
    v.push_back({{name + "_nodes_in_contact", "-"},
                 [t](M, S s, A) { return static_cast<double>(s.tools[t].nodes_in_contact); }});
    if (ever_turns(model, static_cast<int>(t))) {
      v.push_back({{name + "_angle", "deg"},
                   [t](M, S s, A) { return s.tools[t].angle * (180.0 / std::numbers::pi); }});
      v.push_back({{name + "_torque", units.moment()},
                   [t](M m, S s, A) { return press_torque(m, static_cast<int>(t), s.tools[t]); }});
    }
  }
  for (std::size_t d = 0; d < model.output.draw_ins.size(); ++d) {
    v.push_back({{"draw_in_" + model.output.draw_ins[d].name, units.length},
                 [d](M m, S s, A) { return measure_draw_in(m, m.output.draw_ins[d], s.x); }});
  }
  std::size_t audit = 0;  // the audited pairs' records, in the order of the pairs
  for (const ContactInterface& contact : model.contacts) {
    if (contact.audit) {
      v.push_back(
          {{model.tools[static_cast<std::size_t>(contact.tool)].name + "_search_misses", "-"},
           [audit](M, S, A a) { return static_cast<double>(a.records()[audit].last.misses); }});
      ++audit;
    }
  }
  return v;
}

}  // namespace

std::vector<HistoryColumn> history_columns(const Model& model) {
  std::vector<HistoryColumn> columns;
  for (HistoryValue& v : history_values(model)) {
    columns.push_back(std::move(v.column));
  }
  for (HistoryColumn& column :
       history_group_columns(model, parse_unit_system(model.output.units))) {
    columns.push_back(std::move(column));
  }
  return columns;
}

FrameOutput::FrameOutput(const Model& model, const std::filesystem::path& directory)
    : audits_(model) {
  std::vector<PartTopology> parts = set_up(model);
  std::vector<std::string> names, units;
  for (HistoryColumn& column : history_columns(model)) {
    names.push_back(std::move(column.name));
    units.push_back(std::move(column.unit));
  }
  row_.resize(names.size());
  writer_ = std::make_unique<ResultsWriter>(directory, std::move(parts), std::move(names),
                                            std::move(units));
  writer_->write_run_info("resolved_case", model.output.resolved_case);
  writer_->write_run_info("version", build_info::version);
  writer_->write_run_info("git_hash", build_info::git_hash);
  writer_->write_run_info("build", std::string(build_info::build_type) + ", " +
                                       build_info::compiler + ", flags: " + build_info::cxx_flags);
}

FrameOutput::FrameOutput(const Model& model, const std::filesystem::path& directory,
                         const OutputMark& mark, bool blank_mesh_changed)
    : audits_(model) {
  std::vector<PartTopology> parts = set_up(model);
  const PartTopology blank = parts.front();
  std::vector<std::string> names;
  for (HistoryColumn& column : history_columns(model)) {
    names.push_back(std::move(column.name));
  }
  row_.resize(names.size());
  writer_ = std::make_unique<ResultsWriter>(
      directory, std::move(parts), std::move(names),
      ResultsWriter::Resume{mark.frames, mark.history_rows, mark.run_id});
  if (blank_mesh_changed) {
    writer_->change_topology(blank);
  }
  // The case may have a later end (an extended stroke): the results say which case made them.
  writer_->write_run_info("resolved_case", model.output.resolved_case);
  last_history_cycle_ = mark.last_history_cycle;
  audits_.restore(mark.audits, mark.last_audit_cycle);
}

OutputMark FrameOutput::mark() {
  writer_->flush_history();
  OutputMark m;
  m.frames = writer_->frame_count();
  m.history_rows = writer_->history_rows_written();
  m.last_history_cycle = last_history_cycle_;
  m.run_id = writer_->run_id();
  m.audits = audits_.records();
  m.last_audit_cycle = audits_.last_cycle();
  return m;
}

std::vector<PartTopology> FrameOutput::set_up(const Model& model) {
  for (HistoryValue& v : history_values(model)) {
    history_readers_.push_back(std::move(v.value));
  }
  std::vector<PartTopology> parts;
  PartTopology blank;
  blank.name = "blank";
  // Cells numbered as the shell elements: quads, then triangles (one XDMF "Mixed" topology when
  // the blank holds both).
  if (model.blank.part.quads.cols() > 0) {
    blank.nodes_per_cell = 4;
    blank.cells = model.blank.part.quads;
    blank.triangles = model.blank.part.triangles;
  } else {
    blank.nodes_per_cell = 3;
    blank.cells = model.blank.part.triangles;
  }
  blank.reference_nodes = model.blank.mesh.nodes;
  parts.push_back(std::move(blank));
  for (const Tool& t : model.tools) {
    PartTopology tool;
    tool.name = t.name;
    tool.nodes_per_cell = 3;
    tool.cells = t.mesh.triangles;
    tool.reference_nodes = t.mesh.nodes;
    parts.push_back(std::move(tool));
    tool_coordinates_.push_back(t.mesh.nodes);
    tool_displacement_.push_back(Matrix3X::Zero(3, t.mesh.nodes.cols()));
  }
  const Eigen::Index n_elements = element_count(model.blank.part);
  displacement_.resize(3, model.blank.mesh.nodes.cols());
  has_springback_field_ = model.springback.has_value();
  if (has_springback_field_) {
    springback_displacement_ = Matrix3X::Zero(3, model.blank.mesh.nodes.cols());
  }
  plastic_strain_.resize(n_elements);
  if (model.blank.scaling.enabled()) {
    added_mass_percent_.resize(n_elements);
  }
  stress_mid_.resize(6, n_elements);
  stress_top_.resize(6, n_elements);
  stress_bottom_.resize(6, n_elements);
  needs_reactions_ = history_needs_reactions(model);
  contact_fields_.set_up(model);
  formability_fields_.set_up(model);
  reaction_force_ = Matrix3X::Zero(3, model.blank.mesh.nodes.cols());
  reaction_moment_ = Matrix3X::Zero(3, model.blank.mesh.nodes.cols());
  return parts;
}

void FrameOutput::write_frame(const Model& model, const SolutionState& s) {
  audits_.record(model, s);
  displacement_ = s.x - model.blank.mesh.nodes;
  compute_element_stress_output(model.blank.part, stress_geometry_ ? *stress_geometry_ : s.x,
                                s.shell, stress_mid_, stress_top_, stress_bottom_, plastic_strain_);
  std::vector<PartFrameView> frames;
  PartFrameView blank{"blank", s.x, {}};
  blank.fields = {{"displacement", FieldCenter::node, 3, displacement_.data()}};
  // The state's fields written as they are (state_fields.hpp, StateField::result).
  auto add_state_field = [&](const StateField& field, const std::string&, const auto& value) {
    using T = std::remove_cvref_t<decltype(value)>;
    if constexpr (!std::is_arithmetic_v<T>) {
      if (!field.result.empty()) {
        const bool per_node = field.place == FieldPlace::node;
        const auto count = static_cast<std::size_t>(per_node ? s.x.cols() : s.shell.n_elements);
        blank.fields.push_back(
            {std::string(field.result), per_node ? FieldCenter::node : FieldCenter::cell,
             static_cast<int>(static_cast<std::size_t>(value.size()) / count), value.data()});
      }
    }
  };
  visit_state_fields(add_state_field, s);
  blank.fields.push_back({"plastic_strain", FieldCenter::cell, 1, plastic_strain_.data()});
  if (model.blank.parts.size() > 1) {  // a tailor-welded blank: each element's part
    part_index_.resize(s.shell.n_elements);
    for (int e = 0; e < s.shell.n_elements; ++e) {
      part_index_[e] = material_index(model.blank.part, e);
    }
    blank.fields.push_back({"part", FieldCenter::cell, 1, part_index_.data()});
  }
  if (has_springback_field_) {
    if (springback_reference_.cols() > 0) {
      springback_displacement_ = s.x - springback_reference_;
    }
    blank.fields.push_back(
        {"springback_displacement", FieldCenter::node, 3, springback_displacement_.data()});
  }
  if (s.scaling.enabled()) {
    // Per element: 100 (rho_e / rho - 1), the share of its own mass that scaling added.
    const MassScaling& scaling = s.scaling;
    for (Eigen::Index e = 0; e < added_mass_percent_.size(); ++e) {
      added_mass_percent_[e] = 100.0 * (scaling.density_factor[static_cast<std::size_t>(e)] - 1.0);
    }
    blank.fields.push_back(
        {"added_mass_percent", FieldCenter::cell, 1, added_mass_percent_.data()});
  }
  if (model.output.stress_layers) {
    blank.fields.push_back({"stress_mid", FieldCenter::cell, 6, stress_mid_.data()});
    blank.fields.push_back({"stress_top", FieldCenter::cell, 6, stress_top_.data()});
    blank.fields.push_back({"stress_bottom", FieldCenter::cell, 6, stress_bottom_.data()});
  }
  if (!s.shell.back_stress.empty()) {
    compute_element_back_stress_output(model.blank.part, stress_geometry_ ? *stress_geometry_ : s.x,
                                       s.shell, back_stress_top_, back_stress_bottom_);
    blank.fields.push_back({"back_stress_top", FieldCenter::cell, 6, back_stress_top_.data()});
    blank.fields.push_back(
        {"back_stress_bottom", FieldCenter::cell, 6, back_stress_bottom_.data()});
  }
  formability_fields_.add_fields(model, s.x, s.shell.thickness, blank.fields);
  contact_fields_.add_fields(model, s, blank.fields);
  for (const SearchAuditRecord& r : audits_.records()) {
    blank.fields.push_back({"search_miss_" + r.tool, FieldCenter::node, 1, r.miss.data()});
    blank.fields.push_back(
        {"search_gap_error_" + r.tool, FieldCenter::node, 1, r.gap_error.data()});
  }
  frames.push_back(std::move(blank));
  for (std::size_t t = 0; t < model.tools.size(); ++t) {
    const Vec3 d = s.tools[t].displacement;
    const Mat3& turn = s.tools[t].rotation;
    if (turn == Mat3::Identity()) {
      tool_coordinates_[t] = model.tools[t].mesh.nodes.colwise() + d;
      tool_displacement_[t].colwise() = d;
    } else {
      tool_coordinates_[t] = (turn * model.tools[t].mesh.nodes).colwise() + d;
      tool_displacement_[t] = tool_coordinates_[t] - model.tools[t].mesh.nodes;
    }
    PartFrameView tool{model.tools[t].name, tool_coordinates_[t], {}};
    tool.fields = {{"displacement", FieldCenter::node, 3, tool_displacement_[t].data()}};
    frames.push_back(std::move(tool));
  }
  writer_->write_frame(s.time, static_cast<int>(s.cycle), frames);
}

void FrameOutput::append_history(const Model& model, const SolutionState& s) {
  if (s.cycle == last_history_cycle_) {
    return;  // this cycle's row is there already
  }
  last_history_cycle_ = s.cycle;
  audits_.record(model, s);
  std::size_t k = 0;
  for (const HistoryReader& read : history_readers_) {
    row_[k++] = read(model, s, audits_);
  }
  if (needs_reactions_) {
    compute_reactions(model, s, reaction_force_, reaction_moment_);
  }
  record_history_groups(model, s, {reaction_force_, reaction_moment_},
                        std::span<double>(row_).subspan(k));
  writer_->append_history(row_);
}

void FrameOutput::set_springback_reference(const Matrix3X& x_formed) {
  has_springback_field_ = true;
  springback_reference_ = x_formed;
  springback_displacement_.setZero(3, x_formed.cols());
}

std::string FrameOutput::write_stop_state(const Model& model, const SolutionState& s,
                                          double last_frame_time) {
  std::string last_frame;
  append_history(model, s);
  if (s.x.allFinite() && s.time > last_frame_time) {
    try {
      write_frame(model, s);
      last_frame = fmt::format(
          "; the last frame in the results (t = {:.6e} s) is the state at the stop", s.time);
    } catch (const std::exception& write_error) {
      last_frame =
          fmt::format("; the state at the stop could not be written ({})", write_error.what());
    }
  }
  flush();
  return last_frame;
}

void FrameOutput::flush() {
  writer_->flush_history();
}

}  // namespace sf
