#pragma once
// What `sheetform check` and the start of a run say about each tool's mesh and how far it is from
// the blank at the start (docs/tool-diagnosis.md): gaps and overlaps between its faces, triangles
// of near-zero area, folded or flipped normals, each named by the tool and positions, and the
// clearance beside the penetration the run estimate reports. Warnings: a run is not refused for
// them.
#include <string>
#include <vector>

#include "casefile/case_config.hpp"
#include "casefile/unit_system.hpp"
#include "mesh/surface_approach.hpp"
#include "mesh/tool_diagnosis.hpp"
#include "model/model.hpp"

namespace sf {

/// One tool's diagnosis and its clearance to the blank at time 0.
struct ToolMeshReport {
  std::string tool;
  int triangles = 0;
  ToolDiagnosis diagnosis;
  /// What orient_surface did (Tool::orientation), with the elements the mesh reader reversed
  /// (PartMesh::reoriented) counted in made_consistent.
  SurfaceOrientation orientation;
  SurfaceApproach approach;        ///< to the blank's mid-surface, the tool where it is at time 0
  double clearance = 0.0;          ///< length: approach.distance less half the blank's thickness
  double check_seconds = 0.0;      ///< wall time of the mesh checks
  double clearance_seconds = 0.0;  ///< wall time of the clearance
};

/// Every tool of the model, in the case's order.
std::vector<ToolMeshReport> diagnose_tool_meshes(const Model& model);

/// What is printed for one tool: information lines ("Tool mesh", "Clearance") and warnings (one
/// per kind of finding, naming at most a few positions), in the case's length unit.
struct ToolMeshLines {
  std::vector<std::string> info;
  std::vector<std::string> warnings;
};
ToolMeshLines describe_tool_mesh(const ToolMeshReport& report, double thickness,
                                 const std::string& length_unit);

/// Diagnoses every tool and prints the lines (log_info, log_warning); the time each took with
/// --verbose.
void report_tool_meshes(const CaseConfig& config, const Model& model);

}  // namespace sf
