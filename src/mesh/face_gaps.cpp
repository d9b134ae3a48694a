// Gaps between the faces of one tool (ToolDiagnosis::gaps) and faces oriented opposite ways
// across them (ToolDiagnosis::flipped): docs/tool-diagnosis.md.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "mesh/box_tree.hpp"
#include "mesh/tool_diagnosis.hpp"
#include "mesh/triangle_distance.hpp"

namespace sf {
namespace {

double cos_degrees(double degrees) {
  return std::cos(degrees * std::acos(-1.0) / 180.0);
}

/// A boundary edge: its triangle, its end nodes in the triangle's order, the triangle's third node.
struct FreeEdge {
  int triangle = -1, from = -1, to = -1, apex = -1;
};

/// The edges without a neighbour across them (TriangleSurface::triangle_neighbours: -1; a tool
/// has no edge shared by more than two triangles, which orient_surface refuses).
std::vector<FreeEdge> free_edges(const TriangleSurface& s) {
  std::vector<FreeEdge> edges;
  const TriConn& tri = s.triangles();
  for (int t = 0; t < s.num_triangles(); ++t) {
    for (int a = 0; a < 3; ++a) {
      if (s.triangle_neighbours()(a, t) < 0) {
        edges.push_back({t, tri(a, t), tri((a + 1) % 3, t), tri((a + 2) % 3, t)});
      }
    }
  }
  return edges;
}

/// Whether `node` belongs to a triangle at an end of e: such edges are the same boundary turning
/// a corner (or the two boundaries of one narrow strip of triangles), not two sides of a gap.
bool near_in_mesh(const TriangleSurface& s, const FreeEdge& e, int node) {
  const auto& offsets = s.node_triangle_offsets();
  for (const int end : {e.from, e.to}) {
    for (int k = offsets[end]; k < offsets[end + 1]; ++k) {
      if ((s.triangles().col(s.node_triangles()[k]).array() == node).any()) {
        return true;
      }
    }
  }
  return false;
}

/// The unit vector from edge e into its own triangle, perpendicular to e.
Vec3 inward(const Matrix3X& x, const FreeEdge& e) {
  const Vec3 along = (x.col(e.to) - x.col(e.from)).normalized();
  const Vec3 to_apex = x.col(e.apex) - x.col(e.from);
  return (to_apex - to_apex.dot(along) * along).normalized();
}

/// Whether f, seen along e's line, covers part of e (f running beside e, not beyond its end).
bool side_by_side(const Matrix3X& x, const FreeEdge& e, const FreeEdge& f) {
  const Vec3 origin = x.col(e.from), along = x.col(e.to) - origin;
  const double s0 = (x.col(f.from) - origin).dot(along) / along.squaredNorm();
  const double s1 = (x.col(f.to) - origin).dot(along) / along.squaredNorm();
  return std::min(1.0, std::max(s0, s1)) - std::max(0.0, std::min(s0, s1)) > 1e-9;
}

/// The two sides of a gap between e and f: their closest points, when f runs beside e (within
/// kGapParallelDegrees, side by side), its face lies across the gap from e's
/// (kGapSidesDegrees), they are not neighbours in the mesh, and they are no farther apart than
/// max(blank thickness, the longer edge).
std::optional<ClosestPair> gap_between(const TriangleSurface& s, const FreeEdge& e,
                                       const FreeEdge& f, double blank_thickness) {
  if (near_in_mesh(s, e, f.from) || near_in_mesh(s, e, f.to)) {
    return std::nullopt;
  }
  const Matrix3X& x = s.nodes();
  const Vec3 de = x.col(e.to) - x.col(e.from), df = x.col(f.to) - x.col(f.from);
  const double le = de.norm(), lf = df.norm();
  if (std::abs(de.dot(df)) < cos_degrees(tool_check::kGapParallelDegrees) * le * lf ||
      !side_by_side(x, e, f) ||
      inward(x, e).dot(inward(x, f)) >= cos_degrees(tool_check::kGapSidesDegrees)) {
    return std::nullopt;
  }
  const ClosestPair c =
      closest_segment_points(x.col(e.from), x.col(e.to), x.col(f.from), x.col(f.to));
  if (c.distance > std::max({blank_thickness, le, lf})) {
    return std::nullopt;
  }
  return c;
}

/// A gap edge's narrowest gap so far: its width, the middle of the gap, the edge across it.
struct GapSide {
  double width = std::numeric_limits<double>::infinity();
  Vec3 position = Vec3::Zero();
  int partner = -1;
};

void record(GapSide& side, const ClosestPair& gap, int partner) {
  if (gap.distance < side.width) {
    side = {gap.distance, 0.5 * (gap.first + gap.second), partner};
  }
}

double angle_degrees(const Vec3& n1, const Vec3& n2) {
  return std::acos(std::clamp(n1.dot(n2), -1.0, 1.0)) * 180.0 / std::acos(-1.0);
}

/// The narrowest gap of each free edge (partner -1: none). Each pair is found from the longer
/// edge's query at least (its bound is the pair's threshold), and recorded on both sides.
std::vector<GapSide> narrowest_gaps(const TriangleSurface& s, const std::vector<FreeEdge>& edges,
                                    double blank_thickness) {
  const Matrix3X& x = s.nodes();
  std::vector<Vec3> lo, hi;
  for (const FreeEdge& e : edges) {
    lo.push_back(x.col(e.from).cwiseMin(x.col(e.to)));
    hi.push_back(x.col(e.from).cwiseMax(x.col(e.to)));
  }
  const BoxTree tree(std::move(lo), std::move(hi));
  std::vector<GapSide> sides(edges.size());
  for (int i = 0; i < static_cast<int>(edges.size()); ++i) {
    const double bound =
        std::max(blank_thickness, (x.col(edges[i].to) - x.col(edges[i].from)).norm());
    tree.visit(tree.box_lo(i), tree.box_hi(i), bound, [&](int j) {
      const auto gap = j != i ? gap_between(s, edges[i], edges[j], blank_thickness) : std::nullopt;
      if (gap) {
        record(sides[i], *gap, j);
        record(sides[j], *gap, i);
      }
      return bound;
    });
  }
  return sides;
}

}  // namespace

void find_face_gaps(const TriangleSurface& s, double blank_thickness, ToolDiagnosis& out) {
  const std::vector<FreeEdge> edges = free_edges(s);
  const std::vector<GapSide> sides = narrowest_gaps(s, edges, blank_thickness);
  const Matrix3X& x = s.nodes();
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (sides[i].partner < 0) {
      continue;
    }
    out.gaps.push_back({sides[i].position, sides[i].width});
    // A consistently oriented surface runs the two sides of a crack opposite ways.
    const FreeEdge& e = edges[i];
    const FreeEdge& f = edges[sides[i].partner];
    if ((x.col(e.to) - x.col(e.from)).dot(x.col(f.to) - x.col(f.from)) > 0.0) {
      out.flipped.push_back(
          {sides[i].position, angle_degrees(s.triangle_normals().col(e.triangle),
                                            s.triangle_normals().col(f.triangle))});
    }
  }
}

}  // namespace sf
