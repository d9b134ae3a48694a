// Triangles of near-zero area (ToolDiagnosis::slivers) and folds between adjacent triangles
// (ToolDiagnosis::folds): docs/tool-diagnosis.md.
#include <algorithm>
#include <cmath>

#include "mesh/tool_diagnosis.hpp"

namespace sf {

namespace {

/// A triangle's area (mm^2) and its least height over its longest edge (twice the area over the
/// longest edge squared).
struct Shape {
  double area = 0.0;
  double height_ratio = 0.0;
};

Shape shape(const TriangleSurface& s, int t) {
  const Vec3 x1 = s.nodes().col(s.triangles()(0, t));
  const Vec3 e1 = s.nodes().col(s.triangles()(1, t)) - x1;
  const Vec3 e2 = s.nodes().col(s.triangles()(2, t)) - x1;
  const double longest2 = std::max({e1.squaredNorm(), e2.squaredNorm(), (e2 - e1).squaredNorm()});
  const double twice_area = e1.cross(e2).norm();
  return {0.5 * twice_area, twice_area / longest2};
}

}  // namespace

void find_slivers(const TriangleSurface& s, ToolDiagnosis& out) {
  const int nt = s.num_triangles();
  if (nt == 0) {
    return;
  }
  std::vector<Shape> shapes;
  std::vector<double> areas;
  for (int t = 0; t < nt; ++t) {
    shapes.push_back(shape(s, t));
    areas.push_back(shapes.back().area);
  }
  std::nth_element(areas.begin(), areas.begin() + nt / 2, areas.end());
  out.median_area = areas[nt / 2];
  for (int t = 0; t < nt; ++t) {
    if (shapes[t].height_ratio < tool_check::kSliverHeightRatio ||
        shapes[t].area < tool_check::kTinyAreaRatio * out.median_area) {
      Vec3 centroid = Vec3::Zero();
      for (int a = 0; a < 3; ++a) {
        centroid += s.nodes().col(s.triangles()(a, t)) / 3.0;
      }
      out.slivers.push_back({centroid, shapes[t].area});
    }
  }
}

std::vector<ToolFinding> find_folds(const TriangleSurface& s) {
  std::vector<ToolFinding> folds;
  const double limit = std::cos(tool_check::kFoldDegrees * std::acos(-1.0) / 180.0);
  for (int t = 0; t < s.num_triangles(); ++t) {
    for (int a = 0; a < 3; ++a) {
      const int u = s.triangle_neighbours()(a, t);
      if (u <= t) {
        continue;  // a boundary edge, or counted from u
      }
      const double c = s.triangle_normals().col(t).dot(s.triangle_normals().col(u));
      if (c < limit) {
        const Vec3 mid = 0.5 * (s.nodes().col(s.triangles()(a, t)) +
                                s.nodes().col(s.triangles()((a + 1) % 3, t)));
        folds.push_back({mid, std::acos(std::max(c, -1.0)) * 180.0 / std::acos(-1.0)});
      }
    }
  }
  return folds;
}

}  // namespace sf
