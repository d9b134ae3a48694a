// The key tables of every section with a field table, for `sheetform schema --markdown`.
#include <fmt/core.h>

#include "casefile/case_fields.hpp"

namespace sf {

std::vector<SchemaSection> case_schema() {
  return {
      {"top level", field_docs(top_level_fields())},
      {"blank", field_docs(blank_fields())},
      {"blank.parts", field_docs(blank_part_fields())},
      {"materials.NAME", field_docs(material_fields())},
      {"materials.NAME.kinematic", field_docs(kinematic_fields())},
      {"materials.NAME.cowper_symonds", field_docs(cowper_symonds_fields())},
      {"materials.NAME.hardening", field_docs(hardening_fields())},
      {"tools", field_docs(tool_fields())},
      {"tools.motion", field_docs(motion_fields())},
      {"contact", field_docs(contact_fields())},
      {"node_group", field_docs(node_group_fields())},
      {"boundary", field_docs(boundary_fields())},
      {"prescribed_motion", field_docs(prescribed_motion_fields())},
      {"draw_in", field_docs(draw_in_fields())},
      {"history", field_docs(history_group_fields())},
      {"control", field_docs(control_fields())},
      {"output", field_docs(output_fields())},
      {"formability", field_docs(formability_fields())},
      {"limits", field_docs(limits_fields())},
      {"load", field_docs(load_fields())},
      {"initial_velocity", field_docs(initial_velocity_fields())},
      {"prescribed_velocity", field_docs(prescribed_velocity_fields())},
      {"analysis", field_docs(analysis_fields())},
      {"implicit", field_docs(implicit_fields())},
      {"springback", field_docs(springback_fields())},
      {"springback.u_channel", field_docs(u_channel_fields())},
      {"operations", field_docs(operation_fields())},
      {"operations.motion", field_docs(operation_motion_fields())},
      {"drawbeads", field_docs(drawbead_fields())},
  };
}

std::string case_schema_markdown() {
  std::string text;
  for (const SchemaSection& section : case_schema()) {
    text += fmt::format("<!-- schema: {} -->\n{}<!-- end schema -->\n\n", section.name,
                        markdown_table(section.fields));
  }
  return text;
}

std::string case_schema_text() {
  std::string text;
  for (const SchemaSection& section : case_schema()) {
    text += fmt::format("[{}]\n", section.name);
    for (const FieldDoc& d : section.fields) {
      text += fmt::format("  {:<24} {:<26} default {:<12} {}\n", d.key, d.type, d.default_text,
                          d.unit.empty() ? "-" : d.unit);
    }
  }
  return text;
}

}  // namespace sf
