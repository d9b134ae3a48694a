#pragma once
// What is wrong with a tool's triangle mesh, found before a run (docs/tool-diagnosis.md): gaps
// between faces that should meet, faces lying on or crossing each other, triangles of near-zero
// area, and normals that disagree with their neighbours'. Pure geometry on the surface in its
// reference configuration (mm), as orient_surface left it. Each check searches a tree of boxes
// (no O(n^2) pass): about 0.2 s for 100,000 triangles.
#include <vector>

#include "core/types.hpp"
#include "mesh/surface_boundary.hpp"
#include "mesh/triangle_surface.hpp"

namespace sf {

/// The thresholds of the checks (docs/tool-diagnosis.md says why these values).
namespace tool_check {
/// Two free edges are the two sides of one gap only when they run within this angle of each
/// other (either way along).
inline constexpr double kGapParallelDegrees = 30.0;
/// ... and when their faces lie on different sides of the gap: the directions from each edge
/// into its own triangle make at least this angle (below it, the faces are stacked: an overlap).
inline constexpr double kGapSidesDegrees = 60.0;
/// A triangle lies in another's plane when its nodes are within this fraction of the longer of
/// the two triangles' longest edges of that plane; an edge crosses a triangle when its end points
/// lie beyond it on either side, through a point inside the triangle by as much.
inline constexpr double kPlaneTolerance = 1e-3;
/// Triangles in one plane overlap when a point lies inside both by more than this fraction of the
/// shorter of their longest edges (less is the facets of two faces meeting along a curve).
inline constexpr double kOverlapMargin = 0.05;
/// A triangle is a sliver when its least height is below this fraction of its longest edge
/// (an angle below about 0.6 degrees, or above about 178.9)...
inline constexpr double kSliverHeightRatio = 0.01;
/// ... or tiny when its area is below this fraction of the tool's median triangle area.
inline constexpr double kTinyAreaRatio = 1e-4;
/// Adjacent triangles fold when their normals differ by more than this angle.
inline constexpr double kFoldDegrees = 120.0;
}  // namespace tool_check

/// One finding: where (mm) and how much (the unit of its list, below).
struct ToolFinding {
  Vec3 position = Vec3::Zero();  ///< mm
  double value = 0.0;
};

/// The findings of every check, each list in order of severity.
struct ToolDiagnosis {
  /// Free edges that run along another free edge of the tool, on the far side of a gap, within
  /// max(blank thickness, the longer edge) and without sharing a node or a triangle's worth of
  /// neighbourhood: value = the gap's width there (mm), position = the middle of the gap.
  /// Widest first.
  std::vector<ToolFinding> gaps;
  /// Gap edges whose faces on the two sides are oriented opposite ways (the two edges run the same
  /// way, where a surface oriented consistently runs them opposite ways): one of the faces faces
  /// away from the blank. value = the angle between the two triangles' normals (degrees),
  /// position = the middle of the gap. Largest angle first.
  std::vector<ToolFinding> flipped;
  /// Triangles that lie on, or cross, a triangle they share no node with: value = the angle
  /// between their planes (degrees, 0..90: about 0 for a face given twice), position = a point
  /// inside both. In triangle order.
  std::vector<ToolFinding> overlaps;
  /// Triangles of near-zero area (slivers, or tiny beside the median): value = area (mm^2),
  /// position = centroid. Smallest first.
  std::vector<ToolFinding> slivers;
  /// Edges between two triangles whose normals differ by more than kFoldDegrees: value = that
  /// angle (degrees), position = the edge's mid-point. Largest first.
  std::vector<ToolFinding> folds;
  double median_area = 0.0;  ///< mm^2, of the tool's triangles
  SurfaceBoundary boundary;  ///< closed or open, and its free edges (a statement, not a warning)

  bool clean() const {
    return gaps.empty() && flipped.empty() && overlaps.empty() && slivers.empty() && folds.empty();
  }
};

/// Every check on `surface`. blank_thickness (mm) is the least width of a gap that is reported
/// whatever the edge lengths (a gap narrower than the blank's thickness catches its nodes).
ToolDiagnosis diagnose_tool(const TriangleSurface& surface, double blank_thickness);

/// Gaps between faces and the faces oriented opposite ways across them (ToolDiagnosis::gaps and
/// ::flipped, unsorted).
void find_face_gaps(const TriangleSurface& surface, double blank_thickness, ToolDiagnosis& out);

/// ToolDiagnosis::overlaps.
std::vector<ToolFinding> find_face_overlaps(const TriangleSurface& surface);

/// ToolDiagnosis::slivers (unsorted); sets out.median_area.
void find_slivers(const TriangleSurface& surface, ToolDiagnosis& out);

/// ToolDiagnosis::folds (unsorted).
std::vector<ToolFinding> find_folds(const TriangleSurface& surface);

}  // namespace sf
