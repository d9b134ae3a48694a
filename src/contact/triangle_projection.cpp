#include "contact/triangle_projection.hpp"

#include <Eigen/LU>

namespace sf::detail {

std::vector<TriangleProjector> make_projectors(const TriangleSurface& surface) {
  const int nt = surface.num_triangles();
  std::vector<TriangleProjector> out(nt);
  for (int t = 0; t < nt; ++t) {
    TriangleProjector& tp = out[t];
    for (int a = 0; a < 3; ++a) {
      tp.x[a] = surface.nodes().col(surface.triangles()(a, t));
    }
    Mat3 m;
    m.col(0) = tp.x[1] - tp.x[0];
    m.col(1) = tp.x[2] - tp.x[0];
    m.col(2) = surface.triangle_normals().col(t);
    tp.inverse = m.inverse();  // non-singular: the surface rejects degenerate triangles
    for (int a = 0; a < 3; ++a) {
      tp.inv_len2[a] = 1.0 / (tp.x[(a + 1) % 3] - tp.x[a]).squaredNorm();
    }
  }
  return out;
}

double project(const TriangleProjector& tp, const Vec3& p, Vec3& point, Vec3& barycentric) {
  const Vec3 s = tp.inverse * (p - tp.x[0]);
  const double t3 = 1.0 - s[0] - s[1];
  if (s[0] >= 0 && s[1] >= 0 && t3 >= 0) {
    barycentric = Vec3(s[0], s[1], t3);
    point = tp.x[0] + s[0] * (tp.x[1] - tp.x[0]) + s[1] * (tp.x[2] - tp.x[0]);
    return s[2] * s[2];
  }
  double best = std::numeric_limits<double>::infinity();
  double t;
  if (t3 < 0) {  // edge x2 -> x3: point = (1 - t) x2 + t x3
    const double d2 = squared_distance_to_segment(p, tp.x[1], tp.x[2] - tp.x[1], tp.inv_len2[1], t);
    if (d2 < best) {
      best = d2;
      barycentric = Vec3(1 - t, t, 0);
    }
  }
  if (s[0] < 0) {  // edge x3 -> x1: point = (1 - t) x3 + t x1
    const double d2 = squared_distance_to_segment(p, tp.x[2], tp.x[0] - tp.x[2], tp.inv_len2[2], t);
    if (d2 < best) {
      best = d2;
      barycentric = Vec3(0, 1 - t, t);
    }
  }
  if (s[1] < 0) {  // edge x1 -> x2: point = (1 - t) x1 + t x2
    const double d2 = squared_distance_to_segment(p, tp.x[0], tp.x[1] - tp.x[0], tp.inv_len2[0], t);
    if (d2 < best) {
      best = d2;
      barycentric = Vec3(t, 0, 1 - t);
    }
  }
  point = barycentric[2] * tp.x[0] + barycentric[0] * tp.x[1] + barycentric[1] * tp.x[2];
  return best;
}

TieTolerance make_tie_tolerance(const TriangleSurface& surface) {
  TieTolerance tol;
  if (surface.num_nodes() > 0) {
    const Matrix3X& x = surface.nodes();
    const double diagonal = (x.rowwise().maxCoeff() - x.rowwise().minCoeff()).norm();
    tol.absolute = 1e-12 * std::max(diagonal, x.cwiseAbs().maxCoeff());
  }
  return tol;
}

void TieSet::fill(const std::vector<TriangleProjector>& projectors, const TriangleSurface& surface,
                  const Vec3& p, double cutoff, ClosestPoint& out) const {
  out.set_size = 0;
  out.set_truncated = false;
  if (size_ == 0 || !(best_ <= cutoff)) {
    out.triangle = -1;
    return;
  }
  // The set, ascending (insertion sort of at most 8).
  out.set_size = size_;
  out.set_truncated = truncated();
  for (int i = 0; i < size_; ++i) {
    int j = i;
    while (j > 0 && out.set[j - 1] > tri_[i]) {
      out.set[j] = out.set[j - 1];
      --j;
    }
    out.set[j] = tri_[i];
  }
  const int t = out.set[0];
  out.triangle = t;
  out.distance = std::sqrt(project(projectors[t], p, out.point, out.barycentric));

  constexpr double zero_coordinate = 1e-12;
  int zeros = 0;
  for (int a = 0; a < 3; ++a) {
    zeros += std::abs(out.barycentric[a]) <= zero_coordinate ? 1 : 0;
  }
  out.feature = zeros == 0
                    ? ClosestPoint::Feature::face
                    : (zeros == 1 ? ClosestPoint::Feature::edge : ClosestPoint::Feature::vertex);

  Vec3 mean = Vec3::Zero();
  for (int i = 0; i < out.set_size; ++i) {
    mean += surface.triangle_normals().col(out.set[i]);
  }
  const double mean_len = mean.norm();
  mean = mean_len > 1e-12 ? Vec3(mean / mean_len) : Vec3(surface.triangle_normals().col(t));

  const Vec3 v = p - out.point;
  if (out.distance <= tol_.absolute) {
    // On the surface: no direction from p - point; the mean normal of the set.
    out.normal = mean;
    out.signed_distance = v.dot(mean) >= 0 ? out.distance : -out.distance;
  } else if (out.feature == ClosestPoint::Feature::face) {
    out.normal = surface.triangle_normals().col(t);
    out.signed_distance = v.dot(out.normal) >= 0 ? out.distance : -out.distance;
  } else {
    const double sign = v.dot(mean) >= 0 ? 1.0 : -1.0;
    out.normal = (sign / out.distance) * v;
    out.signed_distance = sign * out.distance;
  }
}

}  // namespace sf::detail
