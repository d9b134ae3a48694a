#include "meshing/curve_loop.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <numeric>

#include "core/errors.hpp"
#include "core/quoted.hpp"

namespace sf {
namespace {

// The line elements' end nodes (columns of model.node_coords), a pair per element.
std::vector<std::array<int, 2>> line_segments(const GmshModel& model,
                                              const GmshPhysicalGroup& group) {
  std::vector<std::array<int, 2>> segments;
  for (const GmshElementBlock& block : group.elements) {
    if (block.nodes_per_element < 2) {
      continue;  // points of the group
    }
    const std::size_t n = block.element_tags.size();
    for (std::size_t e = 0; e < n; ++e) {
      const std::size_t* nodes =
          &block.node_tags[e * static_cast<std::size_t>(block.nodes_per_element)];
      segments.push_back({model.node_index.at(nodes[0]), model.node_index.at(nodes[1])});
    }
  }
  return segments;
}

// Each node's representative: the lowest-numbered node within `tolerance` of it (a sweep along
// x over the nodes the segments use).
std::vector<int> merged_nodes(const GmshModel& model,
                              const std::vector<std::array<int, 2>>& segments, double tolerance) {
  std::vector<int> used;
  for (const auto& s : segments) {
    used.insert(used.end(), s.begin(), s.end());
  }
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  const auto x = [&](int i) { return model.node_coords.col(i); };
  std::sort(used.begin(), used.end(), [&](int a, int b) { return x(a).x() < x(b).x(); });
  std::vector<int> same(static_cast<std::size_t>(model.node_coords.cols()));
  std::iota(same.begin(), same.end(), 0);
  for (std::size_t i = 0; i < used.size(); ++i) {
    for (std::size_t j = i + 1; j < used.size() && x(used[j]).x() - x(used[i]).x() <= tolerance;
         ++j) {
      if ((x(used[j]) - x(used[i])).norm() <= tolerance) {
        const int low = std::min(same[used[i]], same[used[j]]);
        same[used[i]] = same[used[j]] = low;
      }
    }
  }
  for (int i : used) {  // chains of near points: follow to the lowest
    while (same[same[i]] != same[i]) {
      same[i] = same[same[i]];
    }
  }
  return same;
}

// The group's line elements as segments between merged points, and per point the segments that
// meet there. Throws InputError when the group is missing or has fewer than `least` segments.
struct CurveGraph {
  std::vector<std::array<int, 2>> segments;
  std::vector<std::vector<int>> at;
  std::string where;
};

CurveGraph curve_graph(const GmshModel& model, const std::string& group, double tolerance,
                       std::size_t least, const char* expected) {
  const GmshPhysicalGroup* curve = model.find_group(group, 1);
  CurveGraph g;
  g.where = fmt::format("{}: curve group '{}'", quoted(model.file), group);
  if (!curve) {
    throw InputError(
        fmt::format("{}: no 1-D physical group '{}' (a Physical Curve) in the file; "
                    "its groups: {}",
                    quoted(model.file), group, model.list_groups()));
  }
  g.segments = line_segments(model, *curve);
  const std::vector<int> same = merged_nodes(model, g.segments, tolerance);
  std::erase_if(g.segments, [&](std::array<int, 2>& s) {
    s = {same[s[0]], same[s[1]]};
    return s[0] == s[1];  // shorter than the tolerance
  });
  if (g.segments.size() < least) {
    throw InputError(
        fmt::format("{}: {} line elements, expected {}", g.where, g.segments.size(), expected));
  }
  g.at.resize(same.size());
  for (std::size_t k = 0; k < g.segments.size(); ++k) {
    for (const int p : g.segments[k]) {
      g.at[static_cast<std::size_t>(p)].push_back(static_cast<int>(k));
    }
  }
  return g;
}

// The points met walking from `point` along `segment` until the line ends or closes.
std::vector<Vec3> walk(const GmshModel& model, const CurveGraph& g, int segment, int point) {
  std::vector<Vec3> points;
  std::vector<char> walked(g.segments.size(), 0);
  while (segment >= 0 && !walked[static_cast<std::size_t>(segment)]) {
    walked[static_cast<std::size_t>(segment)] = 1;
    points.push_back(model.node_coords.col(point));
    const auto& s = g.segments[static_cast<std::size_t>(segment)];
    point = s[0] == point ? s[1] : s[0];
    const auto& next = g.at[static_cast<std::size_t>(point)];
    segment = next.size() < 2 ? -1 : (next[0] == segment ? next[1] : next[0]);
  }
  return points;
}

// "WHERE: WHAT at (x, y, z) mm: EXPECTED".
[[noreturn]] void fail_at_point(const GmshModel& model, const CurveGraph& g, std::size_t p,
                                const std::string& what, const char* expected) {
  const auto c = model.node_coords.col(static_cast<Eigen::Index>(p));
  throw InputError(fmt::format("{}: {} at ({:g}, {:g}, {:g}) mm: {}", g.where, what, c.x(), c.y(),
                               c.z(), expected));
}

}  // namespace

std::vector<Vec3> closed_curve_points(const GmshModel& model, const std::string& group,
                                      double tolerance) {
  const CurveGraph g = curve_graph(model, group, tolerance, 3, "a closed line of at least 3");
  for (std::size_t p = 0; p < g.at.size(); ++p) {
    if (!g.at[p].empty() && g.at[p].size() != 2) {
      fail_at_point(model, g, p,
                    g.at[p].size() == 1
                        ? std::string("the line is not closed: an end meets no other")
                        : fmt::format("{} lines meet", g.at[p].size()),
                    "expected a closed line, each point joining two lines");
    }
  }
  std::vector<Vec3> points = walk(model, g, 0, g.segments[0][0]);
  if (points.size() != g.segments.size()) {
    throw InputError(
        fmt::format("{}: more than one closed line ({} of its {} line elements in "
                    "the first); expected one",
                    g.where, points.size(), g.segments.size()));
  }
  return points;
}

std::vector<Vec3> open_curve_points(const GmshModel& model, const std::string& group,
                                    double tolerance) {
  const CurveGraph g = curve_graph(model, group, tolerance, 1, "an open line of at least 1");
  std::vector<std::size_t> ends;
  for (std::size_t p = 0; p < g.at.size(); ++p) {
    if (g.at[p].size() > 2) {
      fail_at_point(model, g, p, fmt::format("{} lines meet", g.at[p].size()),
                    "expected one open line");
    }
    if (g.at[p].size() == 1) {
      ends.push_back(p);
    }
  }
  if (ends.size() != 2) {
    throw InputError(fmt::format(
        "{}: {} ends, expected one open line (2 ends){}", g.where, ends.size(),
        ends.empty() ? " (the line is closed)" : " (more than one line, or a gap between curves)"));
  }
  const int first = static_cast<int>(ends.front());
  std::vector<Vec3> points = walk(model, g, g.at[ends.front()][0], first);
  points.push_back(model.node_coords.col(static_cast<Eigen::Index>(ends.back())));
  if (points.size() != g.segments.size() + 1) {
    throw InputError(
        fmt::format("{}: more than one line ({} of its {} line elements in the "
                    "first); expected one",
                    g.where, points.size() - 1, g.segments.size()));
  }
  return points;
}

}  // namespace sf
