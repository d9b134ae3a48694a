#include "model/node_selection.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/errors.hpp"

namespace sf {
namespace {

/// Calls f(a, b) for each edge of each element (quads, then triangles), in element order.
template <class F>
void for_each_edge(const PartMesh& blank, F&& f) {
  for (Eigen::Index e = 0; e < blank.quads.cols(); ++e) {
    for (int k = 0; k < 4; ++k) {
      f(blank.quads(k, e), blank.quads((k + 1) % 4, e));
    }
  }
  for (Eigen::Index e = 0; e < blank.triangles.cols(); ++e) {
    for (int k = 0; k < 3; ++k) {
      f(blank.triangles(k, e), blank.triangles((k + 1) % 3, e));
    }
  }
}

Vec3 vec(const std::vector<double>& v) {
  return Vec3(v[0], v[1], v[2]);
}

std::string point_text(const Vec3& p) {
  return fmt::format("({:.6g}, {:.6g}, {:.6g})", p.x(), p.y(), p.z());
}

/// "on the plane through (0, 0, 0) with normal (1, 0, 0), inside ..., on the outline"
std::string criteria_text(const NodeGroupConfig& c, double tolerance) {
  std::string text;
  const auto add = [&text](const std::string& part) { text += (text.empty() ? "" : ", ") + part; };
  if (!c.normal.empty()) {
    add(fmt::format("within {:.3g} mm of the plane through {} with normal {}", tolerance,
                    point_text(c.point.empty() ? Vec3::Zero() : vec(c.point)),
                    point_text(vec(c.normal))));
  }
  if (!c.box.empty()) {
    add(fmt::format("inside the box {} - {} (give or take {:.3g} mm)",
                    point_text(Vec3(c.box[0], c.box[1], c.box[2])),
                    point_text(Vec3(c.box[3], c.box[4], c.box[5])), tolerance));
  }
  if (c.outline) {
    add("on the blank's outline");
  }
  return text;
}

}  // namespace

double default_node_tolerance(const PartMesh& blank) {
  double shortest = std::numeric_limits<double>::infinity();
  for_each_edge(blank, [&](int a, int b) {
    shortest = std::min(shortest, (blank.nodes.col(a) - blank.nodes.col(b)).norm());
  });
  return std::isfinite(shortest) ? 0.01 * shortest : 0.0;
}

std::vector<char> outline_nodes(const PartMesh& blank) {
  std::vector<std::pair<int, int>> edges;
  for_each_edge(blank, [&](int a, int b) { edges.emplace_back(std::min(a, b), std::max(a, b)); });
  std::sort(edges.begin(), edges.end());
  std::vector<char> on(static_cast<std::size_t>(blank.nodes.cols()), 0);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) {
      ++j;
    }
    if (j - i == 1) {
      on[static_cast<std::size_t>(edges[i].first)] = 1;
      on[static_cast<std::size_t>(edges[i].second)] = 1;
    }
    i = j;
  }
  return on;
}

NodeGroup select_nodes(const NodeGroupConfig& config, const PartMesh& blank,
                       const std::string& where) {
  NodeGroup group;
  group.name = config.name;
  const Eigen::Index n = blank.nodes.cols();
  if (config.nearest()) {
    const Vec3 p = vec(config.point);
    Eigen::Index best = -1;
    double best_d2 = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < n; ++i) {
      const double d2 = (blank.nodes.col(i) - p).squaredNorm();
      if (d2 < best_d2) {  // the lowest index on a tie
        best_d2 = d2;
        best = i;
      }
    }
    if (best >= 0) {
      group.nodes.push_back(static_cast<int>(best));
    }
    return group;
  }
  const double tolerance =
      config.tolerance > 0.0 ? config.tolerance : default_node_tolerance(blank);
  const Vec3 origin = config.point.empty() ? Vec3::Zero() : vec(config.point);
  const Vec3 normal = config.normal.empty() ? Vec3::Zero() : vec(config.normal);
  const std::vector<char> outline =
      config.outline ? outline_nodes(blank) : std::vector<char>(static_cast<std::size_t>(n), 1);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Vec3 x = blank.nodes.col(i);
    bool chosen = outline[static_cast<std::size_t>(i)] != 0;
    if (chosen && !config.normal.empty()) {
      chosen = std::abs((x - origin).dot(normal)) <= tolerance;
    }
    for (int k = 0; chosen && k < 3 && !config.box.empty(); ++k) {
      const auto kk = static_cast<std::size_t>(k);
      chosen = x[k] >= config.box[kk] - tolerance && x[k] <= config.box[kk + 3] + tolerance;
    }
    if (chosen) {
      group.nodes.push_back(static_cast<int>(i));
    }
  }
  if (group.nodes.empty()) {
    const Vec3 lo = blank.nodes.rowwise().minCoeff(), hi = blank.nodes.rowwise().maxCoeff();
    throw InputError(fmt::format(
        "{}: node group '{}' chooses no blank node ({}); the blank's nodes span {} - {} mm", where,
        config.name, criteria_text(config, tolerance), point_text(lo), point_text(hi)));
  }
  return group;
}

}  // namespace sf
