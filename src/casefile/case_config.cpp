// read_case: case.toml -> CaseConfig. The reader starts from default-constructed structs (the
// defaults live in case_config.hpp) and overwrites what the file gives, checking every key.
#include "casefile/case_config.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>

#include "casefile/case_config_common.hpp"
#include "casefile/case_config_constraints.hpp"
#include "casefile/case_config_drawbeads.hpp"
#include "casefile/case_config_history.hpp"
#include "casefile/case_config_implicit.hpp"
#include "casefile/case_config_node_groups.hpp"
#include "casefile/case_config_operations.hpp"
#include "casefile/case_fields.hpp"
#include "casefile/case_overrides.hpp"
#include "casefile/toml_reader.hpp"
#include "core/errors.hpp"

namespace sf {

namespace fs = std::filesystem;

namespace {

void read_material(const TomlSection& s, MaterialConfig& material) {
  s.check_keys(field_keys(material_fields(), {"hardening", "kinematic", "cowper_symonds"}));
  read_fields(material_fields(), s, material);
  if (material.type == MaterialConfig::Type::elastic) {
    for (const auto* key : {"hardening", "kinematic", "cowper_symonds"}) {
      if (s.has(key)) {
        s.fail_forbidden(key,
                         "an elastic material has no hardening (remove the table or set type = "
                         "\"von_mises\", \"hill48\", \"yld2000\" or \"yld89\")");
      }
    }
    return;
  }
  read_table(*s.sub_table("hardening", Presence::required), hardening_fields(), material.hardening);
  if (const auto kinematic = s.sub_table("kinematic", Presence::optional)) {
    read_table(*kinematic, kinematic_fields(), material.kinematic);
  }
  if (const auto rate = s.sub_table("cowper_symonds", Presence::optional)) {
    read_table(*rate, cowper_symonds_fields(), material.cowper_symonds);
  }
}

void read_materials(const TomlSection& top, std::vector<MaterialConfig>& materials) {
  const TomlSection all = *top.sub_table("materials", Presence::required);
  for (const auto& [key, node] : all.table()) {
    const std::string name(key.str());
    const std::string path = fmt::format("materials.{}", name);
    const auto* table = node.as_table();
    if (!table) {
      all.fail_at(node, path,
                  fmt::format("expected a table [{}], got {}", path, describe_value(node)));
    }
    MaterialConfig material;
    material.name = name;
    read_material(TomlSection(*table, path, all.file()), material);
    materials.push_back(std::move(material));
  }
  if (materials.empty()) {
    all.fail_at(all.table(), "materials", "expected at least one [materials.NAME] table, got none");
  }
}

// Fails at `s`'s key "material" unless it names one of the case's materials.
void check_material_name(const TomlSection& s, const CaseConfig& config, const std::string& name) {
  bool found = false;
  std::string names;
  for (const auto& material : config.materials) {
    found = found || material.name == name;
    names += fmt::format("{}{}", names.empty() ? "" : ", ", quote_toml_string(material.name));
  }
  if (!found) {
    s.fail_value("material", fmt::format("the name of a [materials.NAME] table ({})", names));
  }
}

// [[blank.parts]]: read before the blank's own keys, which depend on whether there are parts.
// Returns the parts' tables.
std::vector<TomlSection> read_blank_parts(const TomlSection& s, const CaseConfig& config,
                                          BlankConfig& blank) {
  std::vector<TomlSection> tables = s.table_array("parts");
  for (const TomlSection& p : tables) {
    BlankPartConfig part;
    read_table(p, blank_part_fields(), part);
    part.line = static_cast<int>(p.table().source().begin.line);
    check_material_name(p, config, part.material);
    for (const BlankPartConfig& other : blank.parts) {
      if (other.name == part.name) {
        p.fail_value("name", fmt::format("a name no other part has (\"{}\" is taken)", part.name));
      }
      if (!part.group.empty() && other.group == part.group) {
        p.fail_value("group", fmt::format("a group no other part has (part \"{}\" has \"{}\")",
                                          other.name, part.group));
      }
    }
    blank.parts.push_back(std::move(part));
  }
  if (blank.parts.size() == 1) {
    s.fail_at(s.table(), s.key_path("parts"),
              "a blank of one part gives its thickness and material in [blank]; expected two or "
              "more [[blank.parts]]");
  }
  return tables;
}

// A part's group names its elements in the blank's mesh; a blank that is a formed part's own
// mesh (no `mesh`) has its elements' parts by name from the formed part.
void check_blank_part_groups(const std::vector<TomlSection>& tables, const BlankConfig& blank) {
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const TomlSection& p = tables[i];
    const bool has_mesh = !blank.mesh.file.empty();
    if (has_mesh && blank.parts[i].group.empty()) {
      p.fail_at(p.table(), p.key_path("group"),
                "missing: a 2-D physical group of the blank's mesh holding the part's elements");
    }
    if (!has_mesh && !blank.parts[i].group.empty()) {
      p.fail_value("group",
                   "none: the blank is the formed part's own mesh, whose elements are in "
                   "the part of this name already");
    }
  }
}

void read_blank(const TomlSection& top, const CaseConfig& config, BlankConfig& blank) {
  const TomlSection s = *top.sub_table("blank", Presence::required);
  const std::vector<TomlSection> part_tables = read_blank_parts(s, config, blank);
  read_table(s, blank_fields(), blank, {"parts"});
  check_blank_part_groups(part_tables, blank);
  if (blank.parts.empty()) {
    check_material_name(s, config, blank.material);
    return;
  }
  for (const BlankPartConfig& part : blank.parts) {
    blank.thickness = std::max(blank.thickness, part.thickness);
  }
}

void read_tools(const TomlSection& top, std::vector<ToolConfig>& tools) {
  const std::vector<TomlSection> sections = top.table_array("tools");
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const TomlSection& s = sections[i];
    ToolConfig tool;
    read_table(s, tool_fields(), tool, {"motion"});
    for (std::size_t j = 0; j < i; ++j) {
      if (tools[j].name == tool.name) {
        s.fail_at(*s.find("name"), s.key_path("name"),
                  fmt::format("duplicate tool name {} (already used by tools[{}])",
                              quote_toml_string(tool.name), j));
      }
    }
    if (!s.has("group")) {
      tool.mesh.group = tool.name;  // the default group is the tool's name
    }
    if (const auto motion = s.sub_table("motion", Presence::optional)) {
      read_table(*motion, motion_fields(), tool.motion);
    }
    if (tool.position == ToolConfig::Position::touch &&
        tool.motion.type == MotionConfig::Type::fixed) {
      s.fail_value("position",
                   "\"as_meshed\" for a fixed tool (\"touch\" moves a tool along its motion's "
                   "direction: give it a [tools.motion])");
    }
    if (tool.position == ToolConfig::Position::touch && tool.motion.turns() &&
        tool.motion.angle.values.front() != 0.0) {
      s.fail_value("position",
                   "\"as_meshed\" for a tool that starts turned (its angle at time 0 is not 0: "
                   "\"touch\" moves the tool as meshed)");
    }
    tools.push_back(std::move(tool));
  }
}

std::string tool_names(const CaseConfig& config) {
  std::string names;
  for (const auto& tool : config.tools) {
    names += fmt::format("{}{}", names.empty() ? "" : ", ", quote_toml_string(tool.name));
  }
  return names.empty() ? "none defined" : names;
}

void read_contacts(const TomlSection& top, const CaseConfig& config,
                   std::vector<ContactConfig>& contacts) {
  const std::vector<TomlSection> sections = top.table_array("contact");
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const TomlSection& s = sections[i];
    ContactConfig contact;
    s.check_keys(field_keys(contact_fields()));
    s.read_string("tool", contact.tool, Presence::required);
    if (!config.find_tool(contact.tool)) {
      s.fail_value("tool", fmt::format("the name of a [[tools]] entry ({})", tool_names(config)));
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (contacts[j].tool == contact.tool) {
        s.fail_at(*s.find("tool"), s.key_path("tool"),
                  fmt::format("a second [[contact]] for tool {} (the first is contact[{}])",
                              quote_toml_string(contact.tool), j));
      }
    }
    read_fields(contact_fields(), s, contact);
    contacts.push_back(std::move(contact));
  }
}

void read_draw_ins(const TomlSection& top, std::vector<DrawInConfig>& draw_ins) {
  for (const TomlSection& s : top.table_array("draw_in")) {
    DrawInConfig draw_in;
    read_table(s, draw_in_fields(), draw_in);
    for (const auto& other : draw_ins) {
      if (other.name == draw_in.name) {
        s.fail_value("name", "a name not used by another [[draw_in]]");
      }
    }
    draw_ins.push_back(std::move(draw_in));
  }
}

void read_loads(const TomlSection& top, std::vector<LoadConfig>& loads) {
  for (const TomlSection& s : top.table_array("load")) {
    read_table(s, load_fields(), loads.emplace_back());
  }
}

void read_initial_velocities(const TomlSection& top, std::vector<InitialVelocityConfig>& out) {
  for (const TomlSection& s : top.table_array("initial_velocity")) {
    if (!s.has("velocity") && !s.has("angular_velocity")) {
      s.check_keys(field_keys(initial_velocity_fields()));
      s.fail_missing("velocity",
                     "an array of 3 numbers (mm/s), or angular_velocity (rad/s), or both");
    }
    read_table(s, initial_velocity_fields(), out.emplace_back());
  }
}

void read_control(const TomlSection& top, const CaseConfig& config, ControlConfig& control) {
  const TomlSection s = *top.sub_table("control", Presence::required);
  read_table(s, control_fields(), control);
  if (control.end_time > 0.0 && control.stroke > 0.0) {
    s.fail_at(*s.find("stroke"), s.key_path("stroke"),
              fmt::format("expected exactly one of end_time and stroke > 0, got end_time = {} "
                          "and stroke = {}",
                          control.end_time, control.stroke));
  }
  if (!(control.end_time > 0.0) && !(control.stroke > 0.0) && !top.has("operations")) {
    s.fail_at(s.table(), "control.end_time/control.stroke",
              "expected exactly one of end_time (s) and stroke (mm) > 0, got neither");
  }
  if (!control.stroke_tool.empty()) {
    const ToolConfig* tool = config.find_tool(control.stroke_tool);
    if (!tool) {
      s.fail_value("stroke_tool",
                   fmt::format("the name of a [[tools]] entry ({})", tool_names(config)));
    }
    if (tool->motion.type == MotionConfig::Type::force) {
      s.fail_at(*s.find("stroke_tool"), s.key_path("stroke_tool"),
                fmt::format("tool {} is force-controlled (type = \"force\": its travel follows "
                            "from the force), so it cannot define the stroke; expected a tool "
                            "with a prescribed motion (type = \"velocity\" or \"displacement\")",
                            quote_toml_string(tool->name)));
    }
    if (control.stroke > 0.0 && tool->motion.type == MotionConfig::Type::fixed) {
      s.fail_value("stroke_tool", "the name of a tool whose motion is not fixed (stroke > 0)");
    }
    return;
  }
  for (const auto& tool : config.tools) {
    if (tool.motion.type == MotionConfig::Type::velocity ||
        tool.motion.type == MotionConfig::Type::displacement) {
      control.stroke_tool = tool.name;
      return;
    }
  }
  if (control.stroke > 0.0) {
    s.fail_at(*s.find("stroke"), s.key_path("stroke"),
              "stroke > 0 needs a moving tool, but no [[tools]] entry has a prescribed motion "
              "(type = \"velocity\" or \"displacement\")");
  }
}

void read_output(const TomlSection& top, const fs::path& folder, OutputConfig& output) {
  if (const auto s = top.sub_table("output", Presence::optional)) {
    read_table(*s, output_fields(), output);
  }
  const fs::path directory(output.directory);
  if (directory.is_relative()) {
    output.directory = (folder / directory).lexically_normal().string();
  }
}

void read_formability(const TomlSection& top, FormabilityConfig& formability) {
  if (const auto s = top.sub_table("formability", Presence::optional)) {
    read_table(*s, formability_fields(), formability);
  }
}

void read_limits(const TomlSection& top, LimitsConfig& limits) {
  if (const auto s = top.sub_table("limits", Presence::optional)) {
    read_table(*s, limits_fields(), limits);
  }
}

std::string read_text_file(const fs::path& file) {
  std::error_code error;
  if (!fs::exists(file, error)) {
    throw InputError(fmt::format("{}: case file not found", file.string()));
  }
  if (!fs::is_regular_file(file, error)) {
    throw InputError(fmt::format("{}: case file is not a regular file", file.string()));
  }
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) {
    throw InputError(fmt::format("{}: cannot read the case file", file.string()));
  }
  return text.str();
}

toml::table parse_toml(const std::string& text, const std::string& file) {
  try {
    return toml::parse(std::string_view(text), std::string_view(file));
  } catch (const toml::parse_error& error) {
    throw InputError(fmt::format("{}: TOML syntax error: {}", format_location(file, error.source()),
                                 error.description()));
  }
}

}  // namespace

const MaterialConfig& CaseConfig::blank_material() const {
  if (!blank.parts.empty()) {
    throw InputError(fmt::format(
        "{}: the blank has {} parts, each of its own material; expected a blank of one material",
        file.string(), blank.parts.size()));
  }
  return material_named(blank.material);
}

double CaseConfig::largest_blank_thickness() const {
  double largest = 0.0;
  for (const BlankPartConfig& p : blank_parts()) {
    largest = std::max(largest, p.thickness);
  }
  return largest;
}

const MaterialConfig& CaseConfig::material_named(const std::string& name) const {
  for (const auto& material : materials) {
    if (material.name == name) {
      return material;
    }
  }
  throw InputError(fmt::format("{}: no material named \"{}\"", file.string(), name));
}

std::vector<BlankPartConfig> CaseConfig::blank_parts() const {
  if (!blank.parts.empty()) {
    return blank.parts;
  }
  return {BlankPartConfig{.name = "blank",
                          .group = blank.mesh.group,
                          .thickness = blank.thickness,
                          .material = blank.material,
                          .line = 0}};
}

const ToolConfig* CaseConfig::find_tool(const std::string& name) const {
  for (const auto& tool : tools) {
    if (tool.name == name) {
      return &tool;
    }
  }
  return nullptr;
}

CaseConfig read_case(const fs::path& case_file, const std::vector<std::string>& overrides) {
  return read_case(case_file, CaseOptions{.set = overrides});
}

CaseConfig read_case(const fs::path& case_file, const CaseOptions& options) {
  CaseConfig config;
  config.file = fs::absolute(case_file).lexically_normal();
  const std::string file = config.file.string();
  toml::table root = parse_toml(read_text_file(config.file), file);
  apply_case_overrides(root, options.set);
  apply_run_options(root, options, file);
  const fs::path folder = config.file.parent_path();

  const TomlSection top(root, "", file);
  read_table(top, top_level_fields(), config,
             {"blank",
              "materials",
              "tools",
              "contact",
              "boundary",
              "draw_in",
              "load",
              "initial_velocity",
              "prescribed_velocity",
              "prescribed_motion",
              "control",
              "output",
              "analysis",
              "implicit",
              "springback",
              "history",
              "node_group",
              "limits",
              "formability",
              "operations",
              "drawbeads"});
  read_materials(top, config.materials);
  read_blank(top, config, config.blank);
  read_tools(top, config.tools);
  read_contacts(top, config, config.contacts);
  read_draw_ins(top, config.draw_ins);
  read_loads(top, config.loads);
  read_initial_velocities(top, config.initial_velocities);
  read_constraint_sections(top, config);
  read_control(top, config, config.control);
  read_limits(top, config.limits);
  read_output(top, folder, config.output);
  read_formability(top, config.formability);
  read_implicit_sections(top, config);
  check_constraints_for_analysis(top, config);
  read_history_groups(top, config);
  read_node_groups(top, config);
  read_operations(top, config);
  read_drawbeads(top, config);
  return config;
}

}  // namespace sf
