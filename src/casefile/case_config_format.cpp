// format_resolved_case: CaseConfig -> TOML text that read_case reads back to the same CaseConfig.
// Every key is written (defaults included, paths absolute); the units go in comments.
#include <fmt/core.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "casefile/case_config.hpp"
#include "casefile/case_config_drawbeads.hpp"
#include "casefile/case_config_operations.hpp"
#include "casefile/case_fields.hpp"
#include "casefile/toml_reader.hpp"
#include "casefile/toml_writer.hpp"
#include "core/dof_names.hpp"

namespace sf {

namespace {

/// A key as TOML writes it: bare when it can be, quoted otherwise.
std::string format_key(std::string_view key) {
  const bool bare = !key.empty() && key.find_first_not_of(
                                        "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                        "abcdefghijklmnopqrstuvwxyz"
                                        "0123456789_-") == std::string::npos;
  return bare ? std::string(key) : quote_toml_string(key);
}

void write_material(TomlWriter& w, const MaterialConfig& material) {
  const std::string table = fmt::format("materials.{}", format_key(material.name));
  w.header(table);
  write_fields(material_fields(), w, material);
  if (material.type == MaterialConfig::Type::elastic) {
    return;
  }
  w.header(table + ".hardening");
  write_fields(hardening_fields(), w, material.hardening);
  if (!material.kinematic.C.empty()) {
    w.header(table + ".kinematic");
    write_fields(kinematic_fields(), w, material.kinematic);
  }
  if (material.cowper_symonds.D > 0.0) {
    w.header(table + ".cowper_symonds");
    write_fields(cowper_symonds_fields(), w, material.cowper_symonds);
  }
}

void write_tool(TomlWriter& w, const ToolConfig& tool) {
  w.array_header("tools");
  write_fields(tool_fields(), w, tool);
  w.header("tools.motion");
  write_fields(motion_fields(), w, tool.motion);
}

void write_draw_in(TomlWriter& w, const DrawInConfig& draw_in) {
  w.array_header("draw_in");
  write_fields(draw_in_fields(), w, draw_in);
}

void write_implicit_sections(TomlWriter& w, const CaseConfig& config) {
  w.header("analysis");
  write_fields(analysis_fields(), w, config.analysis);
  w.header("implicit");
  write_fields(implicit_fields(), w, config.implicit);
  if (!config.springback) {
    return;
  }
  w.header("springback");
  write_fields(springback_fields(), w, *config.springback);
  if (config.springback->u_channel) {
    w.header("springback.u_channel");
    write_fields(u_channel_fields(), w, *config.springback->u_channel);
  }
}

}  // namespace

std::string format_resolved_case(const CaseConfig& config) {
  TomlWriter w;
  w.comment(fmt::format("sheetform resolved case; units: {} (length, time, mass, force, stress)",
                        config.units));
  w.comment(fmt::format("read from {}; every default filled in, every path absolute",
                        quote_toml_string(config.file.string())));
  write_fields(top_level_fields(), w, config);
  w.header("blank");
  write_fields(blank_fields(), w, config.blank);
  for (const BlankPartConfig& part : config.blank.parts) {
    w.array_header("blank.parts");
    write_fields(blank_part_fields(), w, part);
  }
  for (const auto& material : config.materials) {
    write_material(w, material);
  }
  for (const auto& tool : config.tools) {
    write_tool(w, tool);
  }
  for (const auto& contact : config.contacts) {
    w.array_header("contact");
    write_fields(contact_fields(), w, contact);
  }
  for (const auto& boundary : config.boundaries) {
    w.array_header("boundary");
    write_fields(boundary_fields(), w, boundary);
  }
  for (const auto& draw_in : config.draw_ins) {
    write_draw_in(w, draw_in);
  }
  for (const auto& load : config.loads) {
    w.array_header("load");
    write_fields(load_fields(), w, load);
  }
  for (const auto& h : config.history_groups) {
    w.array_header("history");
    write_fields(history_group_fields(), w, h);
  }
  for (const auto& g : config.node_groups) {
    w.array_header("node_group");
    write_fields(node_group_fields(), w, g);
  }
  for (const auto& iv : config.initial_velocities) {
    w.array_header("initial_velocity");
    write_fields(initial_velocity_fields(), w, iv);
  }
  for (const auto& pv : config.prescribed_velocities) {
    w.array_header("prescribed_velocity");
    write_fields(prescribed_velocity_fields(), w, pv);
  }
  for (const auto& pm : config.prescribed_motions) {
    w.array_header("prescribed_motion");
    write_fields(prescribed_motion_fields(), w, pm);
  }
  w.header("control");
  write_fields(control_fields(), w, config.control);
  write_implicit_sections(w, config);
  write_operations(w, config);
  write_drawbeads(w, config);
  w.header("output");
  write_fields(output_fields(), w, config.output);
  w.header("formability");
  write_fields(formability_fields(), w, config.formability);
  w.header("limits");
  write_fields(limits_fields(), w, config.limits);
  return w.take();
}

}  // namespace sf
