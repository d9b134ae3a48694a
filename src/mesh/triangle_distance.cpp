#include "mesh/triangle_distance.hpp"

#include <algorithm>
#include <limits>

namespace sf {

ClosestPair closest_segment_points(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  // Ericson 5.1.9: minimise |p0 + s d1 - q0 - t d2| over s, t in [0, 1].
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  constexpr double tiny = std::numeric_limits<double>::min();
  double s = 0.0, t = 0.0;
  if (a <= tiny && e <= tiny) {
    s = t = 0.0;
  } else if (a <= tiny) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= tiny) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;  // parallel: s = 0
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  ClosestPair pair;
  pair.first = p0 + s * d1;
  pair.second = q0 + t * d2;
  pair.distance = (pair.first - pair.second).norm();
  return pair;
}

Vec3 closest_point_on_triangle(const Vec3& p, const Tri3& t) {
  // Ericson 5.1.5: the Voronoi regions of the vertices, then of the edges, else the face.
  const Vec3 a = t.col(0), b = t.col(1), c = t.col(2);
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) {
    return a;
  }
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) {
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    return a + d1 / (d1 - d3) * ab;
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) {
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    return a + d2 / (d2 - d6) * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  }
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

double inside_margin(const Vec3& p, const Tri3& t) {
  const Vec3 n = (t.col(1) - t.col(0)).cross(t.col(2) - t.col(0)).normalized();
  double margin = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const Vec3 v = t.col(i), edge = t.col((i + 1) % 3) - v;
    margin = std::min(margin, edge.cross(p - v).dot(n) / edge.norm());
  }
  return margin;
}

std::optional<Vec3> segment_triangle_crossing(const Vec3& p0, const Vec3& p1, const Tri3& t) {
  const Vec3 n = (t.col(1) - t.col(0)).cross(t.col(2) - t.col(0));
  const double s0 = n.dot(p0 - t.col(0)), s1 = n.dot(p1 - t.col(0));
  if ((s0 > 0.0 && s1 > 0.0) || (s0 < 0.0 && s1 < 0.0) || s0 == s1) {
    return std::nullopt;  // one side, or in the plane
  }
  const Vec3 p = p0 + s0 / (s0 - s1) * (p1 - p0);
  for (int i = 0; i < 3; ++i) {
    const Vec3 v = t.col(i), edge = t.col((i + 1) % 3) - v;
    if (edge.cross(p - v).dot(n) < 0.0) {
      return std::nullopt;
    }
  }
  return p;
}

ClosestPair closest_triangle_points(const Tri3& a, const Tri3& b) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (const auto p = segment_triangle_crossing(a.col(i), a.col(j), b)) {
      return {*p, *p, 0.0};
    }
    if (const auto p = segment_triangle_crossing(b.col(i), b.col(j), a)) {
      return {*p, *p, 0.0};
    }
  }
  ClosestPair best;
  best.distance = std::numeric_limits<double>::infinity();
  const auto consider = [&best](const Vec3& first, const Vec3& second) {
    const double d = (first - second).norm();
    if (d < best.distance) {
      best = {first, second, d};
    }
  };
  for (int i = 0; i < 3; ++i) {
    consider(a.col(i), closest_point_on_triangle(a.col(i), b));
    consider(closest_point_on_triangle(b.col(i), a), b.col(i));
    for (int k = 0; k < 3; ++k) {
      const ClosestPair e =
          closest_segment_points(a.col(i), a.col((i + 1) % 3), b.col(k), b.col((k + 1) % 3));
      consider(e.first, e.second);
    }
  }
  return best;
}

}  // namespace sf
