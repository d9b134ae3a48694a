// Triangles that lie on, or cross, triangles they share no node with (ToolDiagnosis::overlaps):
// docs/tool-diagnosis.md.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "mesh/box_tree.hpp"
#include "mesh/tool_diagnosis.hpp"
#include "mesh/triangle_distance.hpp"

namespace sf {
namespace {

Tri3 corners(const TriangleSurface& s, int t) {
  Tri3 c;
  for (int a = 0; a < 3; ++a) {
    c.col(a) = s.nodes().col(s.triangles()(a, t));
  }
  return c;
}

double longest_edge(const Tri3& t) {
  return std::max(
      {(t.col(1) - t.col(0)).norm(), (t.col(2) - t.col(1)).norm(), (t.col(0) - t.col(2)).norm()});
}

Vec3 unit_normal(const Tri3& t) {
  return (t.col(1) - t.col(0)).cross(t.col(2) - t.col(0)).normalized();
}

bool share_node(const TriConn& tri, int a, int b) {
  for (int i = 0; i < 3; ++i) {
    if ((tri.col(b).array() == tri(i, a)).any()) {
      return true;
    }
  }
  return false;
}

/// A convex polygon in a plane: a triangle clipped by up to six half-planes keeps at most nine
/// vertices.
struct Polygon {
  std::array<Vec3, 12> v;
  int n = 0;
};

/// The part of `poly` where m . (p - origin) > offset (Sutherland-Hodgman, one half-plane).
Polygon clip(const Polygon& poly, const Vec3& m, const Vec3& origin, double offset) {
  Polygon out;
  for (int i = 0; i < poly.n; ++i) {
    const Vec3& p = poly.v[i];
    const Vec3& q = poly.v[(i + 1) % poly.n];
    const double dp = m.dot(p - origin) - offset, dq = m.dot(q - origin) - offset;
    if (dp > 0.0) {
      out.v[out.n++] = p;
    }
    if ((dp > 0.0) != (dq > 0.0)) {
      out.v[out.n++] = p + dp / (dp - dq) * (q - p);
    }
  }
  return out;
}

/// The part of `poly` (in t's plane) inside triangle t by more than `margin`.
Polygon clip_inside(Polygon poly, const Tri3& t, double margin) {
  const Vec3 n = unit_normal(t);
  for (int i = 0; i < 3 && poly.n > 0; ++i) {
    const Vec3 edge = t.col((i + 1) % 3) - t.col(i);
    poly = clip(poly, n.cross(edge).normalized(), t.col(i), margin);
  }
  return poly;
}

/// A point inside both a and b by more than `margin`, b's nodes lying in a's plane (normal na,
/// within the plane tolerance): b is moved into the plane, then clipped by both triangles.
std::optional<Vec3> coplanar_overlap(const Tri3& a, const Vec3& na, Tri3 b, double margin) {
  Polygon poly;
  for (int i = 0; i < 3; ++i) {
    b.col(i) -= na.dot(b.col(i) - a.col(0)) * na;
    poly.v[poly.n++] = b.col(i);
  }
  poly = clip_inside(clip_inside(poly, a, margin), b, margin);
  if (poly.n < 3) {
    return std::nullopt;
  }
  Vec3 area = Vec3::Zero(), sum = Vec3::Zero();
  for (int i = 0; i < poly.n; ++i) {
    area += poly.v[i].cross(poly.v[(i + 1) % poly.n]);
    sum += poly.v[i];
  }
  // A sliver of round-off along a clipping line is no overlap.
  if (!(area.norm() > 1e-12 * longest_edge(a) * longest_edge(a))) {
    return std::nullopt;
  }
  return sum / poly.n;
}

/// A triangle with what every pair test needs of it.
struct Facet {
  Tri3 corners;
  Vec3 normal;     ///< unit
  double longest;  ///< its longest edge
};

Facet facet(const TriangleSurface& s, int t) {
  const Tri3 c = corners(s, t);
  return {c, s.triangle_normals().col(t), longest_edge(c)};
}

/// Signed distances of b's corners from a's plane.
Vec3 heights(const Facet& b, const Facet& a) {
  return (b.corners.colwise() - a.corners.col(0)).transpose() * a.normal;
}

/// Whether every height lies beyond `tolerance` on the same side.
bool one_side(const Vec3& h, double tolerance) {
  return h.minCoeff() > tolerance || h.maxCoeff() < -tolerance;
}

/// Where an edge of b goes through a: its ends beyond `tolerance` on either side of a's plane
/// (heights h), through a point inside a by more than `tolerance`.
std::optional<Vec3> edge_through(const Facet& a, const Facet& b, const Vec3& h, double tolerance) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if ((h[i] > tolerance && h[j] < -tolerance) || (h[i] < -tolerance && h[j] > tolerance)) {
      const Vec3 crossing =
          b.corners.col(i) + h[i] / (h[i] - h[j]) * (b.corners.col(j) - b.corners.col(i));
      if (inside_margin(crossing, a.corners) > tolerance) {
        return crossing;
      }
    }
  }
  return std::nullopt;
}

/// A point inside both a and b (sharing no node), when they lie on each other or cross.
std::optional<Vec3> overlap_point(const Facet& a, const Facet& b) {
  const double tolerance = tool_check::kPlaneTolerance * std::max(a.longest, b.longest);
  const Vec3 hb = heights(b, a), ha = heights(a, b);
  if (one_side(hb, tolerance) || one_side(ha, tolerance)) {
    return std::nullopt;  // apart: neither in one plane nor crossing
  }
  const double margin = tool_check::kOverlapMargin * std::min(a.longest, b.longest);
  if (hb.cwiseAbs().maxCoeff() <= tolerance) {
    return coplanar_overlap(a.corners, a.normal, b.corners, margin);
  }
  if (ha.cwiseAbs().maxCoeff() <= tolerance) {
    return coplanar_overlap(b.corners, b.normal, a.corners, margin);
  }
  if (const auto p = edge_through(a, b, hb, tolerance)) {
    return p;
  }
  return edge_through(b, a, ha, tolerance);
}

/// Degrees, 0..90.
double angle_between_planes(const Facet& a, const Facet& b) {
  const double c = std::min(1.0, std::abs(a.normal.dot(b.normal)));
  return std::acos(c) * 180.0 / std::acos(-1.0);
}

}  // namespace

std::vector<ToolFinding> find_face_overlaps(const TriangleSurface& s) {
  const int nt = s.num_triangles();
  std::vector<Facet> facets;
  std::vector<Vec3> lo, hi;
  double longest = 0.0;
  for (int t = 0; t < nt; ++t) {
    facets.push_back(facet(s, t));
    lo.push_back(facets.back().corners.rowwise().minCoeff());
    hi.push_back(facets.back().corners.rowwise().maxCoeff());
    longest = std::max(longest, facets.back().longest);
  }
  const BoxTree tree(std::move(lo), std::move(hi));
  const double reach = tool_check::kPlaneTolerance * longest;  // the largest tolerance
  std::vector<std::optional<ToolFinding>> first(nt);           // per triangle
  for (int t = 0; t < nt; ++t) {
    const Facet& a = facets[t];
    tree.visit(tree.box_lo(t), tree.box_hi(t), reach, [&](int u) {
      if (u > t && !share_node(s.triangles(), t, u)) {
        const Facet& b = facets[u];
        if (const auto p = overlap_point(a, b)) {
          const ToolFinding finding{*p, angle_between_planes(a, b)};
          for (const int k : {t, u}) {
            if (!first[k]) {
              first[k] = finding;
            }
          }
        }
      }
      return reach;
    });
  }
  std::vector<ToolFinding> overlaps;
  for (const auto& finding : first) {
    if (finding) {
      overlaps.push_back(*finding);
    }
  }
  return overlaps;
}

}  // namespace sf
