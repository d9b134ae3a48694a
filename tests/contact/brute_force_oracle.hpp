#pragma once
// Test oracle: the closest point of a triangle surface to a point, by brute force over all
// triangles with the Voronoi-region closest-point-on-triangle method (Ericson, Real-Time
// Collision Detection, 2005, sec. 5.1.5). Written independently from the production search
// (which solves the paper's 3x3 system with a precomputed inverse and clamps onto edges), so that
// it checks it rather than repeats it.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/types.hpp"

namespace sf::oracle {

/// Closest point of triangle (a, b, c) to p: which Voronoi region of the triangle (3 vertices,
/// 3 edges, the face) holds p, decided by signs of dot products.
inline Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a;
  const Vec3 ap = p - a;
  const double s_ab_a = ab.dot(ap), s_ac_a = ac.dot(ap);
  if (s_ab_a <= 0 && s_ac_a <= 0) {
    return a;  // behind a along both edges from a
  }
  const Vec3 bp = p - b;
  const double s_ab_b = ab.dot(bp), s_ac_b = ac.dot(bp);
  if (s_ab_b >= 0 && s_ac_b <= s_ab_b) {
    return b;
  }
  const Vec3 cp = p - c;
  const double s_ab_c = ab.dot(cp), s_ac_c = ac.dot(cp);
  if (s_ac_c >= 0 && s_ab_c <= s_ac_c) {
    return c;
  }
  // Signed (scaled) areas giving the barycentric coordinates of the projection.
  const double area_c = s_ab_a * s_ac_b - s_ab_b * s_ac_a;  // weight of c
  if (area_c <= 0 && s_ab_a >= 0 && s_ab_b <= 0) {
    return a + (s_ab_a / (s_ab_a - s_ab_b)) * ab;  // edge ab
  }
  const double area_b = s_ab_c * s_ac_a - s_ab_a * s_ac_c;  // weight of b
  if (area_b <= 0 && s_ac_a >= 0 && s_ac_c <= 0) {
    return a + (s_ac_a / (s_ac_a - s_ac_c)) * ac;  // edge ac
  }
  const double area_a = s_ab_b * s_ac_c - s_ab_c * s_ac_b;  // weight of a
  const double along_bc_b = s_ac_b - s_ab_b, along_bc_c = s_ab_c - s_ac_c;
  if (area_a <= 0 && along_bc_b >= 0 && along_bc_c >= 0) {
    return b + (along_bc_b / (along_bc_b + along_bc_c)) * (c - b);  // edge bc
  }
  const double sum = area_a + area_b + area_c;
  return a + (area_b / sum) * ab + (area_c / sum) * ac;
}

inline double distance_to_triangle(const Matrix3X& nodes, const TriConn& tri, int t,
                                   const Vec3& p) {
  const Vec3 q = closest_point_on_triangle(p, nodes.col(tri(0, t)), nodes.col(tri(1, t)),
                                           nodes.col(tri(2, t)));
  return (p - q).norm();
}

struct OracleAnswer {
  double distance = std::numeric_limits<double>::infinity();  ///< least distance, mm
  std::vector<int> ties;  ///< all triangles within `tie` of the least distance, ascending
};

/// Least distance over all triangles; ties: triangles with distance <= least + tie.
inline OracleAnswer closest(const Matrix3X& nodes, const TriConn& tri, const Vec3& p, double tie) {
  OracleAnswer out;
  std::vector<double> d(tri.cols());
  for (int t = 0; t < tri.cols(); ++t) {
    d[t] = distance_to_triangle(nodes, tri, t, p);
    out.distance = std::min(out.distance, d[t]);
  }
  for (int t = 0; t < tri.cols(); ++t) {
    if (d[t] <= out.distance + tie) {
      out.ties.push_back(t);
    }
  }
  return out;
}

}  // namespace sf::oracle
