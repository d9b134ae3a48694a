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

}  // namespace

std::vector<Vec3> closed_curve_points(const GmshModel& model, const std::string& group,
                                      double tolerance) {
  const GmshPhysicalGroup* curve = model.find_group(group, 1);
  const std::string where = fmt::format("{}: curve group '{}'", quoted(model.file), group);
  if (!curve) {
    throw InputError(
        fmt::format("{}: no 1-D physical group '{}' (a Physical Curve) in the file; "
                    "its groups: {}",
                    quoted(model.file), group, model.list_groups()));
  }
  std::vector<std::array<int, 2>> segments = line_segments(model, *curve);
  const std::vector<int> same = merged_nodes(model, segments, tolerance);
  std::erase_if(segments, [&](std::array<int, 2>& s) {
    s = {same[s[0]], same[s[1]]};
    return s[0] == s[1];  // shorter than the tolerance
  });
  if (segments.size() < 3) {
    throw InputError(fmt::format("{}: {} line elements, expected a closed line of at least 3",
                                 where, segments.size()));
  }
  // Per point, the segments that meet there (two on a closed line).
  std::vector<std::vector<int>> at(same.size());
  for (std::size_t k = 0; k < segments.size(); ++k) {
    for (const int p : segments[k]) {
      at[static_cast<std::size_t>(p)].push_back(static_cast<int>(k));
    }
  }
  for (std::size_t p = 0; p < at.size(); ++p) {
    if (!at[p].empty() && at[p].size() != 2) {
      const auto c = model.node_coords.col(static_cast<Eigen::Index>(p));
      throw InputError(fmt::format(
          "{}: {} at ({:g}, {:g}, {:g}) mm: expected a closed line, each point joining two "
          "lines",
          where,
          at[p].size() == 1 ? "the line is not closed: an end meets no other"
                            : fmt::format("{} lines meet", at[p].size()),
          c.x(), c.y(), c.z()));
    }
  }
  std::vector<Vec3> points;
  std::vector<char> walked(segments.size(), 0);
  int segment = 0, point = segments[0][0];
  for (std::size_t n = 0; n < segments.size() && !walked[static_cast<std::size_t>(segment)]; ++n) {
    walked[static_cast<std::size_t>(segment)] = 1;
    points.push_back(model.node_coords.col(point));
    const auto& s = segments[static_cast<std::size_t>(segment)];
    point = s[0] == point ? s[1] : s[0];
    const auto& next = at[static_cast<std::size_t>(point)];
    segment = next[0] == segment ? next[1] : next[0];
  }
  if (points.size() != segments.size()) {
    throw InputError(
        fmt::format("{}: more than one closed line ({} of its {} line elements in "
                    "the first); expected one",
                    where, points.size(), segments.size()));
  }
  return points;
}

}  // namespace sf
