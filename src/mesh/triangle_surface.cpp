#include "mesh/triangle_surface.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <utility>

#include "core/errors.hpp"
#include "mesh/consistent_orientation.hpp"

namespace sf {

namespace {

/// A triangle is degenerate when |e1 x e2| (twice its area) is below this fraction of its longest
/// edge squared, i.e. its smallest height is below ~1e-12 of its longest edge: such a triangle
/// has no usable normal and makes the projection system [e1 e2 n] singular.
constexpr double degenerate_area_ratio = 1e-12;

}  // namespace

TriangleSurface::TriangleSurface(std::string name, Matrix3X nodes, TriConn triangles)
    : name_(std::move(name)), nodes_(std::move(nodes)), triangles_(std::move(triangles)) {
  const int nn = num_nodes();
  const int nt = num_triangles();
  for (int t = 0; t < nt; ++t) {
    for (int a = 0; a < 3; ++a) {
      const int v = triangles_(a, t);
      if (v < 0 || v >= nn) {
        throw InputError(fmt::format("tool '{}': triangle {} has node index {} outside [0, {})",
                                     name_, t, v, nn));
      }
    }
    if (triangles_(0, t) == triangles_(1, t) || triangles_(1, t) == triangles_(2, t) ||
        triangles_(0, t) == triangles_(2, t)) {
      throw InputError(fmt::format("tool '{}': triangle {} repeats a node ({}, {}, {})", name_, t,
                                   triangles_(0, t), triangles_(1, t), triangles_(2, t)));
    }
    const Vec3 x1 = nodes_.col(triangles_(0, t));
    const Vec3 e1 = nodes_.col(triangles_(1, t)) - x1;
    const Vec3 e2 = nodes_.col(triangles_(2, t)) - x1;
    const double longest2 = std::max({e1.squaredNorm(), e2.squaredNorm(), (e2 - e1).squaredNorm()});
    if (!(e1.cross(e2).norm() > degenerate_area_ratio * longest2)) {
      throw InputError(
          fmt::format("tool '{}': triangle {} (nodes {}, {}, {}) is degenerate (zero area)", name_,
                      t, triangles_(0, t), triangles_(1, t), triangles_(2, t)));
    }
  }

  // Node -> triangle adjacency, CSR, triangles ascending within each node.
  node_triangle_offsets_.assign(nn + 1, 0);
  for (int t = 0; t < nt; ++t) {
    for (int a = 0; a < 3; ++a) {
      ++node_triangle_offsets_[triangles_(a, t) + 1];
    }
  }
  for (int i = 0; i < nn; ++i) {
    node_triangle_offsets_[i + 1] += node_triangle_offsets_[i];
  }
  node_triangles_.assign(node_triangle_offsets_[nn], 0);
  std::vector<int> fill(node_triangle_offsets_.begin(), node_triangle_offsets_.end() - 1);
  for (int t = 0; t < nt; ++t) {
    for (int a = 0; a < 3; ++a) {
      node_triangles_[fill[triangles_(a, t)]++] = t;
    }
  }
  compute_normals();
  compute_neighbours();
}

void TriangleSurface::compute_neighbours() {
  const int nt = num_triangles();
  triangle_neighbours_.setConstant(3, nt, -1);
  for (int t = 0; t < nt; ++t) {
    for (int a = 0; a < 3; ++a) {
      const int u = triangles_(a, t), v = triangles_((a + 1) % 3, t);
      // The other triangles holding both u and v: scan the triangles of u.
      int found = -1, count = 0;
      for (int k = node_triangle_offsets_[u]; k < node_triangle_offsets_[u + 1]; ++k) {
        const int w = node_triangles_[k];
        if (w != t && (triangles_.col(w).array() == v).any()) {
          found = w;
          ++count;
        }
      }
      triangle_neighbours_(a, t) = count == 1 ? found : -1;
    }
  }
}

void TriangleSurface::compute_normals() {
  const int nn = num_nodes();
  const int nt = num_triangles();
  triangle_normals_.resize(3, nt);
  for (int t = 0; t < nt; ++t) {
    const Vec3 x1 = nodes_.col(triangles_(0, t));
    const Vec3 n = (nodes_.col(triangles_(1, t)) - x1).cross(nodes_.col(triangles_(2, t)) - x1);
    triangle_normals_.col(t) = n.normalized();
  }
  node_normals_.setZero(3, nn);
  for (int i = 0; i < nn; ++i) {
    Vec3 sum = Vec3::Zero();
    for (int k = node_triangle_offsets_[i]; k < node_triangle_offsets_[i + 1]; ++k) {
      sum += triangle_normals_.col(node_triangles_[k]);
    }
    const double len = sum.norm();
    if (len > 1e-12) {
      node_normals_.col(i) = sum / len;
    }
  }
}

void TriangleSurface::flip_triangles(const std::vector<char>& flip) {
  for (int t = 0; t < num_triangles(); ++t) {
    if (flip[t]) {
      std::swap(triangles_(1, t), triangles_(2, t));
    }
  }
  compute_normals();
  compute_neighbours();
}

namespace {

/// Closest point of triangle (a, b, c) to p: squared distance and whether the point lies inside
/// the triangle (a face hit). Orthogonal projection with barycentric coordinates from the 2x2
/// Gram system; outside, the least of the three clamped edge projections.
std::pair<double, bool> closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                            const Vec3& c, Vec3& closest) {
  const Vec3 e1 = b - a, e2 = c - a, r = p - a;
  const double g11 = e1.dot(e1), g12 = e1.dot(e2), g22 = e2.dot(e2);
  const double r1 = r.dot(e1), r2 = r.dot(e2);
  const double det = g11 * g22 - g12 * g12;
  const double s = (g22 * r1 - g12 * r2) / det;
  const double u = (g11 * r2 - g12 * r1) / det;
  if (s >= 0 && u >= 0 && s + u <= 1) {
    closest = a + s * e1 + u * e2;
    return {(p - closest).squaredNorm(), true};
  }
  double best = std::numeric_limits<double>::infinity();
  const std::array<std::pair<Vec3, Vec3>, 3> edges{{{a, b}, {b, c}, {c, a}}};
  for (const auto& [q0, q1] : edges) {
    const Vec3 e = q1 - q0;
    const double t = std::clamp((p - q0).dot(e) / e.squaredNorm(), 0.0, 1.0);
    const Vec3 q = q0 + t * e;
    const double d2 = (p - q).squaredNorm();
    if (d2 < best) {
      best = d2;
      closest = q;
    }
  }
  return {best, false};
}

/// InputError naming the tool, how many edges more than two triangles share, and the end points
/// of the first few (mm). `edges` holds (node, node, triangles) per edge.
[[noreturn]] void throw_non_manifold(const TriangleSurface& surface,
                                     const std::vector<std::array<int, 3>>& edges) {
  constexpr std::size_t kListed = 3;
  const Matrix3X& x = surface.nodes();
  const auto point = [&x](int node) {
    return fmt::format("({:.4g}, {:.4g}, {:.4g})", x(0, node), x(1, node), x(2, node));
  };
  std::string list;
  for (std::size_t k = 0; k < std::min(kListed, edges.size()); ++k) {
    list += fmt::format("{}{} triangles on the edge {} - {}", k == 0 ? "" : ", ", edges[k][2],
                        point(edges[k][0]), point(edges[k][1]));
  }
  throw InputError(fmt::format(
      "tool '{}': the surface is non-manifold: {} {} shared by more than two triangles ({}{}, "
      "mm): a face meshed twice, or faces meeting in a T; contact needs each edge between at "
      "most two triangles: remove the duplicate faces or give the branches as separate tools",
      surface.name(), edges.size(), edges.size() == 1 ? "edge is" : "edges are", list,
      edges.size() > kListed ? ", ..." : ""));
}

// Bounding spheres of triangles (centre: the mean of the vertices; radius: the farthest vertex),
// structure of arrays, so that a search for the closest triangle can pass over a triangle whose
// sphere lies farther than a triangle already found.
struct TriangleSpheres {
  std::vector<double> cx, cy, cz, radius;

  TriangleSpheres(const Matrix3X& x, const TriConn& tri) {
    const auto nt = static_cast<std::size_t>(tri.cols());
    cx.resize(nt);
    cy.resize(nt);
    cz.resize(nt);
    radius.resize(nt);
    for (Eigen::Index t = 0; t < tri.cols(); ++t) {
      const Vec3 c = (x.col(tri(0, t)) + x.col(tri(1, t)) + x.col(tri(2, t))) / 3.0;
      double r2 = 0.0;
      for (int a = 0; a < 3; ++a) {
        r2 = std::max(r2, (x.col(tri(a, t)) - c).squaredNorm());
      }
      const auto k = static_cast<std::size_t>(t);
      cx[k] = c(0);
      cy[k] = c(1);
      cz[k] = c(2);
      radius[k] = std::sqrt(r2);
    }
  }

  // Whether every point of triangle t is farther from p than sqrt(d2), by a margin (1e-9
  // relative) far above the round-off of this test and of the exact distance: a triangle passed
  // over could never have been the strictly closer one.
  bool beyond(std::size_t t, const Vec3& p, double d2) const {
    const double dx = p(0) - cx[t], dy = p(1) - cy[t], dz = p(2) - cz[t];
    const double lower = std::sqrt(dx * dx + dy * dy + dz * dz) - radius[t];
    return lower > 0.0 && lower * lower > d2 * (1.0 + 1e-9);
  }
};

}  // namespace

SurfaceOrientation orient_surface(TriangleSurface& surface, const Matrix3X& blank_nodes) {
  const int nt = surface.num_triangles();
  const TriConn& tri = surface.triangles();

  // One orientation per connected piece (mesh/consistent_orientation.hpp).
  std::vector<int> offsets(nt + 1);
  for (int t = 0; t <= nt; ++t) {
    offsets[t] = 3 * t;
  }
  const ConsistentOrientation consistent = orient_consistently(
      offsets, std::span<const int>(tri.data(), 3 * static_cast<std::size_t>(nt)));
  if (!consistent.non_manifold.empty()) {
    std::vector<std::array<int, 3>> edges;
    for (const NonManifoldEdge& e : consistent.non_manifold) {
      edges.push_back({e.lo, e.hi, e.elements});
    }
    throw_non_manifold(surface, edges);
  }
  if (consistent.conflict) {
    const int t = consistent.conflict->element_a, u = consistent.conflict->element_b;
    const Matrix3X& x = surface.nodes();
    const Vec3 at = (x.col(tri(0, u)) + x.col(tri(1, u)) + x.col(tri(2, u))) / 3.0;
    throw InputError(fmt::format(
        "tool '{}': the surface is not orientable (a Moebius-like strip): going round it, "
        "the orientation comes back reversed at ({:.4g}, {:.4g}, {:.4g}) mm, triangles {} "
        "and {}; split the surface there or remove the twisted faces",
        surface.name(), at.x(), at.y(), at.z(), t, u));
  }
  const std::vector<int>& component = consistent.piece;
  const std::vector<char>& flip = consistent.flip;
  const int num_components = consistent.num_pieces;
  SurfaceOrientation result;
  result.components = num_components;
  result.made_consistent = static_cast<int>(std::count(flip.begin(), flip.end(), 1));
  surface.flip_triangles(flip);

  // Side votes per component: face hits (weighted 1/distance) and, as a fall-back, all hits.
  const int nb = static_cast<int>(blank_nodes.cols());
  if (nb == 0 || nt == 0) {
    return result;
  }
  const int stride = std::max(1, (nb + 1999) / 2000);
  std::vector<double> face_vote(num_components, 0.0), any_vote(num_components, 0.0);
  std::vector<double> best_d2(num_components);
  std::vector<int> best_t(num_components);
  std::vector<char> best_face(num_components);
  std::vector<Vec3> best_q(num_components);
  const Matrix3X& x = surface.nodes();
  // Each piece's closest triangle, in ascending triangle order (the first of equals), as trying
  // every triangle finds it; a triangle whose bounding sphere lies beyond the piece's closest
  // so far, or beyond the previous node's closest triangle (a neighbour's: the sampled nodes
  // follow the blank's numbering), is passed over, as it could not have been strictly closer.
  const TriangleSpheres spheres(x, tri);
  std::vector<int> previous_t(num_components, -1);
  std::vector<double> bound(num_components);
  for (int b = 0; b < nb; b += stride) {
    const Vec3 p = blank_nodes.col(b);
    std::fill(best_d2.begin(), best_d2.end(), std::numeric_limits<double>::infinity());
    for (int c = 0; c < num_components; ++c) {
      const int s = previous_t[static_cast<std::size_t>(c)];
      Vec3 q = Vec3::Zero();
      bound[static_cast<std::size_t>(c)] =
          s < 0 ? std::numeric_limits<double>::infinity()
                : closest_on_triangle(p, x.col(tri(0, s)), x.col(tri(1, s)), x.col(tri(2, s)), q)
                      .first;
    }
    for (int t = 0; t < nt; ++t) {
      const auto c_t = static_cast<std::size_t>(component[t]);
      if (spheres.beyond(static_cast<std::size_t>(t), p, std::min(bound[c_t], best_d2[c_t]))) {
        continue;
      }
      Vec3 q = Vec3::Zero();
      const auto [d2, face] =
          closest_on_triangle(p, x.col(tri(0, t)), x.col(tri(1, t)), x.col(tri(2, t)), q);
      const int c = component[t];
      if (d2 < best_d2[c]) {
        best_d2[c] = d2;
        best_t[c] = t;
        best_face[c] = static_cast<char>(face);
        best_q[c] = q;
      }
    }
    for (int c = 0; c < num_components; ++c) {
      previous_t[static_cast<std::size_t>(c)] = std::isfinite(best_d2[c]) ? best_t[c] : -1;
      const double d = std::sqrt(best_d2[c]);
      if (!(d > 0) || !std::isfinite(d)) {
        continue;  // on the surface: no side
      }
      // Side of p w.r.t. the closest triangle's plane (exact for face hits; for edge and vertex
      // hits the plane of one of the triangles there, hence only a fall-back).
      const double side = surface.triangle_normals().col(best_t[c]).dot(p - best_q[c]);
      const double vote = (side > 0 ? 1.0 : (side < 0 ? -1.0 : 0.0)) / d;
      any_vote[c] += vote;
      if (best_face[c]) {
        face_vote[c] += vote;
      }
    }
  }
  std::vector<char> side_flip(nt, 0);
  bool any_flip = false;
  for (int t = 0; t < nt; ++t) {
    const int c = component[t];
    const double vote = face_vote[c] != 0.0 ? face_vote[c] : any_vote[c];
    side_flip[t] = vote < 0 ? 1 : 0;
    any_flip = any_flip || side_flip[t];
  }
  if (any_flip) {
    surface.flip_triangles(side_flip);
  }
  result.turned_to_blank = static_cast<int>(std::count(side_flip.begin(), side_flip.end(), 1));
  return result;
}

}  // namespace sf
