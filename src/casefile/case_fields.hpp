#pragma once
// The case file's field tables (casefile/case_schema.hpp), one per section: read_case reads by
// them, format_resolved_case writes by them and `sheetform schema --markdown` prints them for
// docs/case-file.md. Not a public interface.
#include <string>
#include <vector>

#include "casefile/case_config.hpp"
#include "casefile/case_schema.hpp"

namespace sf {

// Parts (case_fields_parts.cpp).
const FieldTable<MeshSourceConfig>& mesh_source_fields();
const FieldTable<BlankConfig>& blank_fields();
const FieldTable<BlankPartConfig>& blank_part_fields();
const FieldTable<ToolConfig>& tool_fields();
const FieldTable<MotionConfig>& motion_fields();
const FieldTable<ContactConfig>& contact_fields();

// Run control and output (case_fields_run.cpp).
const FieldTable<CaseConfig>& top_level_fields();
const FieldTable<ControlConfig>& control_fields();
const FieldTable<OutputConfig>& output_fields();
const FieldTable<FormabilityConfig>& formability_fields();
const FieldTable<LimitsConfig>& limits_fields();
const FieldTable<DrawInConfig>& draw_in_fields();

// Constraints on blank nodes (case_config_constraints.cpp).
const FieldTable<BoundaryConfig>& boundary_fields();
const FieldTable<PrescribedVelocityConfig>& prescribed_velocity_fields();
const FieldTable<PrescribedMotionConfig>& prescribed_motion_fields();

// Loads, initial velocities and history groups (case_fields_loads.cpp).
const FieldTable<LoadConfig>& load_fields();
const FieldTable<InitialVelocityConfig>& initial_velocity_fields();
const FieldTable<HistoryGroupConfig>& history_group_fields();

// Blank nodes chosen by position (case_config_node_groups.cpp).
const FieldTable<NodeGroupConfig>& node_group_fields();

// Implicit statics (case_fields_implicit.cpp).
const FieldTable<AnalysisConfig>& analysis_fields();
const FieldTable<ImplicitConfig>& implicit_fields();
const FieldTable<SpringbackConfig>& springback_fields();
const FieldTable<UChannelMeasureConfig>& u_channel_fields();

// The press line's operations (case_config_operations.cpp).
const FieldTable<OperationConfig>& operation_fields();
const FieldTable<OperationMotionConfig>& operation_motion_fields();

// Drawbead lines (case_config_drawbeads.cpp).
const FieldTable<DrawbeadConfig>& drawbead_fields();

// Materials (case_fields_material.cpp).
const FieldTable<MaterialConfig>& material_fields();
const FieldTable<HardeningConfig>& hardening_fields();
const FieldTable<KinematicConfig>& kinematic_fields();
const FieldTable<CowperSymondsConfig>& cowper_symonds_fields();

/// One section's key table as docs/case-file.md shows it.
struct SchemaSection {
  std::string name;  ///< "blank", "tools.motion", "materials.NAME.hardening", ...
  std::vector<FieldDoc> fields;
};

/// Every section with a field table, in the order of docs/case-file.md.
std::vector<SchemaSection> case_schema();

/// The key tables as `sheetform schema --markdown` prints them: each between the marker lines
/// "<!-- schema: NAME -->" and "<!-- end schema -->" that docs/case-file.md holds them in.
std::string case_schema_markdown();

/// The same as plain text: one line per key, "[section] key  type  default  unit".
std::string case_schema_text();

}  // namespace sf
