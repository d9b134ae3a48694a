#include "mesh/tool_diagnosis.hpp"

#include <algorithm>

namespace sf {
namespace {

void sort_by_value(std::vector<ToolFinding>& findings, bool largest_first) {
  std::stable_sort(findings.begin(), findings.end(),
                   [largest_first](const ToolFinding& a, const ToolFinding& b) {
                     return largest_first ? a.value > b.value : a.value < b.value;
                   });
}

}  // namespace

ToolDiagnosis diagnose_tool(const TriangleSurface& surface, double blank_thickness) {
  ToolDiagnosis d;
  find_face_gaps(surface, blank_thickness, d);
  d.overlaps = find_face_overlaps(surface);
  find_slivers(surface, d);
  d.folds = find_folds(surface);
  d.boundary = surface_boundary(surface);
  sort_by_value(d.gaps, true);
  sort_by_value(d.flipped, true);
  sort_by_value(d.slivers, false);
  sort_by_value(d.folds, true);
  return d;
}

}  // namespace sf
