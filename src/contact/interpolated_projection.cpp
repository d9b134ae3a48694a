#include "contact/interpolated_projection.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace sf {

namespace {

/// |m(T)| below this (the nodal normals are unit vectors, so |m| ~ 1 on an ordinary triangle)
/// means the interpolated normal is undefined there: a knife edge, or an extrapolation far
/// outside the triangle.
constexpr double min_normal_length = 1e-6;

/// Newton gives up when a coordinate leaves [-bound, bound]: the iterate ran far from the
/// triangle (the normal field extrapolated that far means nothing).
constexpr double coordinate_bound = 100.0;

/// The smallest of the three barycentric coordinates (T1, T2, T3 = 1 - T1 - T2).
double smallest_coordinate(const Vec3& s) {
  return std::min({s[0], s[1], 1.0 - s[0] - s[1]});
}

}  // namespace

InterpolatedProjector::InterpolatedProjector(const TriangleSurface& surface)
    : surface_(&surface), projectors_(detail::make_projectors(surface)) {
  if (surface.num_nodes() > 0) {
    const Matrix3X& x = surface.nodes();
    const double diagonal = (x.rowwise().maxCoeff() - x.rowwise().minCoeff()).norm();
    tolerance_ = residual_relative * std::max(diagonal, x.cwiseAbs().maxCoeff());
  }
}

bool InterpolatedProjector::solve_on_triangle(int t, const Vec3& p, Vec3& solution,
                                              int& iterations) const {
  const detail::TriangleProjector& tp = projectors_[static_cast<std::size_t>(t)];
  const TriConn& tri = surface_->triangles();
  const Matrix3X& normals = surface_->node_normals();
  const Vec3 n1 = normals.col(tri(0, t));
  const Vec3 dm1 = normals.col(tri(1, t)) - n1;  // dm/dT1
  const Vec3 dm2 = normals.col(tri(2, t)) - n1;  // dm/dT2
  const Vec3 e1 = tp.x[1] - tp.x[0];
  const Vec3 e2 = tp.x[2] - tp.x[0];

  // Start: the orthogonal projection onto the triangle's plane, (T1, T2, D).
  Vec3& s = solution;
  s = tp.inverse * (p - tp.x[0]);
  for (int it = 0;; ++it) {
    const Vec3 m = n1 + s[0] * dm1 + s[1] * dm2;
    const double len = m.norm();
    if (!(len > min_normal_length)) {
      return false;
    }
    const Vec3 n = m / len;
    const Vec3 r = tp.x[0] + s[0] * e1 + s[1] * e2 + s[2] * n - p;
    if (r.norm() <= tolerance_) {
      return true;
    }
    if (it == max_iterations) {
      return false;
    }
    // Jacobian [x2 - x1 + D dn/dT1, x3 - x1 + D dn/dT2, n], dn/dT = (I - n n^T) dm/dT / |m|.
    Mat3 jacobian;
    jacobian.col(0) = e1 + (s[2] / len) * (dm1 - n.dot(dm1) * n);
    jacobian.col(1) = e2 + (s[2] / len) * (dm2 - n.dot(dm2) * n);
    jacobian.col(2) = n;
    const double det = jacobian.determinant();
    const double scale = jacobian.col(0).norm() * jacobian.col(1).norm();
    if (!(std::abs(det) > 1e-12 * scale)) {
      return false;  // the map T -> x + D n is singular here (a focal point of the normals)
    }
    s -= jacobian.inverse() * r;
    ++iterations;
    if (!(std::abs(s[0]) <= coordinate_bound && std::abs(s[1]) <= coordinate_bound &&
          std::isfinite(s[2]))) {
      return false;
    }
  }
}

void InterpolatedProjector::project(const Vec3& p, const ClosestPoint& closest,
                                    InterpolatedProjection& out) const {
  out.iterations = 0;
  out.triangles_tried = 0;
  out.fallback = false;
  if (closest.triangle < 0) {
    out.triangle = -1;
    out.fallback = true;
    return;
  }

  // The tie set, ascending (insertion sort of at most max_set_size), or the single triangle.
  constexpr int set_capacity = ClosestPoint::max_set_size;
  std::array<int, set_capacity> set{};
  int set_size = 0;
  if (closest.set_size == 0) {
    set[set_size++] = closest.triangle;
  }
  for (int i = 0; i < closest.set_size; ++i) {
    int j = set_size++;
    while (j > 0 &&
           set[static_cast<std::size_t>(j - 1)] > closest.set[static_cast<std::size_t>(i)]) {
      set[static_cast<std::size_t>(j)] = set[static_cast<std::size_t>(j - 1)];
      --j;
    }
    set[static_cast<std::size_t>(j)] = closest.set[static_cast<std::size_t>(i)];
  }

  std::array<int, set_capacity + max_walk_steps> visited{};
  int visited_count = 0;
  const auto accept = [&](int t, const Vec3& s) {
    const detail::TriangleProjector& tp = projectors_[static_cast<std::size_t>(t)];
    const TriConn& tri = surface_->triangles();
    const Matrix3X& normals = surface_->node_normals();
    const double t3 = 1.0 - s[0] - s[1];
    out.triangle = t;
    out.barycentric = Vec3(s[0], s[1], t3);
    out.distance = s[2];
    out.point = tp.x[0] + s[0] * (tp.x[1] - tp.x[0]) + s[1] * (tp.x[2] - tp.x[0]);
    out.normal = (t3 * normals.col(tri(0, t)) + s[0] * normals.col(tri(1, t)) +
                  s[1] * normals.col(tri(2, t)))
                     .normalized();
  };

  // 1. The tie set in ascending order: the first inside solution wins.
  int start = -1;
  double start_smallest = -std::numeric_limits<double>::infinity();
  Vec3 start_solution = Vec3::Zero();
  for (int i = 0; i < set_size; ++i) {
    const int t = set[static_cast<std::size_t>(i)];
    Vec3 s;
    ++out.triangles_tried;
    visited[static_cast<std::size_t>(visited_count++)] = t;
    if (!solve_on_triangle(t, p, s, out.iterations)) {
      continue;
    }
    const double smallest = smallest_coordinate(s);
    if (smallest >= -inside_tolerance) {
      accept(t, s);
      return;
    }
    if (smallest > start_smallest) {  // strict: ties keep the lower index
      start_smallest = smallest;
      start = t;
      start_solution = s;
    }
  }

  // 2. Walk across the edge opposite the most negative coordinate.
  const auto is_visited = [&](int t) {
    return std::find(visited.begin(), visited.begin() + visited_count, t) !=
           visited.begin() + visited_count;
  };
  int current = start;
  Vec3 s = start_solution;
  for (int step = 0; step < max_walk_steps && current >= 0; ++step) {
    // Local vertex v of the most negative coordinate: T3 -> vertex 0, T1 -> 1, T2 -> 2.
    const double t3 = 1.0 - s[0] - s[1];
    int vertex = 0;
    double most_negative = t3;
    if (s[0] < most_negative) {
      vertex = 1;
      most_negative = s[0];
    }
    if (s[1] < most_negative) {
      vertex = 2;
    }
    // Edge a runs from local node a to a + 1, opposite local node a + 2.
    const int next = surface_->triangle_neighbours()((vertex + 1) % 3, current);
    if (next < 0 || is_visited(next)) {
      break;  // a boundary, or a cycle
    }
    visited[static_cast<std::size_t>(visited_count++)] = next;
    ++out.triangles_tried;
    Vec3 trial;
    if (!solve_on_triangle(next, p, trial, out.iterations)) {
      break;
    }
    if (smallest_coordinate(trial) >= -inside_tolerance) {
      accept(next, trial);
      return;
    }
    current = next;
    s = trial;
  }

  // 3. The fan of the vertex nearest the last solution (its largest coordinate), ascending: a
  //    solution near a vertex may sit in a triangle of the fan that the walk cannot reach across
  //    one edge (it steps back into a visited triangle).
  if (current >= 0) {
    const double t3 = 1.0 - s[0] - s[1];
    const int local = t3 >= s[0] && t3 >= s[1] ? 0 : (s[0] >= s[1] ? 1 : 2);
    const int node = surface_->triangles()(local, current);
    const std::vector<int>& offsets = surface_->node_triangle_offsets();
    const std::vector<int>& fan = surface_->node_triangles();
    for (int k = offsets[static_cast<std::size_t>(node)];
         k < offsets[static_cast<std::size_t>(node) + 1]; ++k) {
      const int t = fan[static_cast<std::size_t>(k)];
      if (is_visited(t)) {
        continue;
      }
      ++out.triangles_tried;
      Vec3 trial;
      if (solve_on_triangle(t, p, trial, out.iterations) &&
          smallest_coordinate(trial) >= -inside_tolerance) {
        accept(t, trial);
        return;
      }
    }
  }

  // 4. Nothing: the orthogonal answer.
  out.fallback = true;
  out.triangle = closest.triangle;
  out.barycentric = closest.barycentric;
  out.distance = closest.signed_distance;
  out.point = closest.point;
  out.normal = closest.normal;
}

}  // namespace sf
