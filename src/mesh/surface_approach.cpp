#include "mesh/surface_approach.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "mesh/box_tree.hpp"
#include "mesh/triangle_distance.hpp"

namespace sf {
namespace {

/// The shell's mid-surface as triangles: each quadrilateral split along its 0-2 diagonal.
std::vector<Tri3> shell_triangles(const Matrix3X& x, const QuadConn& quads, const TriConn& tris) {
  std::vector<Tri3> out;
  out.reserve(static_cast<std::size_t>(2 * quads.cols() + tris.cols()));
  const auto add = [&](int a, int b, int c) {
    Tri3 t;
    t << x.col(a), x.col(b), x.col(c);
    out.push_back(t);
  };
  for (Eigen::Index e = 0; e < quads.cols(); ++e) {
    add(quads(0, e), quads(1, e), quads(2, e));
    add(quads(0, e), quads(2, e), quads(3, e));
  }
  for (Eigen::Index e = 0; e < tris.cols(); ++e) {
    add(tris(0, e), tris(1, e), tris(2, e));
  }
  return out;
}

Tri3 tool_triangle(const TriangleSurface& tool, int t, const Vec3& offset) {
  Tri3 c;
  for (int a = 0; a < 3; ++a) {
    c.col(a) = tool.nodes().col(tool.triangles()(a, t)) + offset;
  }
  return c;
}

/// The tool's averaged nodal normals interpolated at p, a point of triangle t (its corners c).
Vec3 interpolated_normal(const TriangleSurface& tool, int t, const Tri3& c, const Vec3& p) {
  const Vec3 n = (c.col(1) - c.col(0)).cross(c.col(2) - c.col(0));
  Vec3 sum = Vec3::Zero();
  for (int a = 0; a < 3; ++a) {
    // Barycentric coordinate of corner a: the area of the sub-triangle opposite it.
    const double w =
        (c.col((a + 1) % 3) - p).cross(c.col((a + 2) % 3) - p).dot(n) / n.squaredNorm();
    sum += w * tool.node_normals().col(tool.triangles()(a, t));
  }
  return sum.norm() > 1e-12 ? Vec3(sum.normalized()) : Vec3(n.normalized());  // a knife edge
}

}  // namespace

SurfaceApproach closest_approach(const TriangleSurface& tool, const Vec3& tool_offset,
                                 const Matrix3X& shell_nodes, const QuadConn& quads,
                                 const TriConn& triangles) {
  SurfaceApproach best;
  const int nt = tool.num_triangles();
  if (nt == 0) {
    return best;
  }
  std::vector<Vec3> lo, hi;
  for (int t = 0; t < nt; ++t) {
    const Tri3 c = tool_triangle(tool, t, tool_offset);
    lo.push_back(c.rowwise().minCoeff());
    hi.push_back(c.rowwise().maxCoeff());
  }
  const BoxTree tree(std::move(lo), std::move(hi));
  // Only a pair closer than the best so far can change it: the bound is just below the best.
  const auto below = [](double d) { return std::nextafter(d, -1.0); };
  int best_triangle = -1;
  for (const Tri3& s : shell_triangles(shell_nodes, quads, triangles)) {
    tree.visit(s.rowwise().minCoeff(), s.rowwise().maxCoeff(), below(best.distance), [&](int t) {
      const ClosestPair c = closest_triangle_points(tool_triangle(tool, t, tool_offset), s);
      if (c.distance < best.distance) {
        best = {c.distance, c.first, c.second, 0.0};
        best_triangle = t;
      }
      return below(best.distance);
    });
  }
  if (best_triangle >= 0 && best.distance > 0.0) {
    const Tri3 c = tool_triangle(tool, best_triangle, tool_offset);
    best.facing = interpolated_normal(tool, best_triangle, c, best.tool_point)
                      .dot((best.shell_point - best.tool_point) / best.distance);
  }
  return best;
}

}  // namespace sf
