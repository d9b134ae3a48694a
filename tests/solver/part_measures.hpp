#pragma once
// Measures of a formed part's mesh as it stands, for the trim tests: a node's coordinates, the
// area seen along z, and the edges that only one element has (the part's edge).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include "solver/part_remap.hpp"

namespace sf::test {

/// Node n's current coordinates (mm).
inline Vec3 node_at(const FormedPart& p, int n) {
  const std::vector<double>& x = p.fields.at("x");
  const auto i = 3 * static_cast<std::size_t>(n);
  return {x[i], x[i + 1], x[i + 2]};
}

/// mm^2, the elements' areas seen along z (counter-clockwise positive).
inline double projected_area(const FormedPart& p) {
  double sum = 0.0;
  for (int e = 0; e < static_cast<int>(p.quads.cols() + p.triangles.cols()); ++e) {
    const std::vector<int> n = part_element_nodes(p, e);
    for (std::size_t k = 1; k + 1 < n.size(); ++k) {
      sum +=
          0.5 *
          (node_at(p, n[k]) - node_at(p, n[0])).cross(node_at(p, n[k + 1]) - node_at(p, n[0]))(2);
    }
  }
  return sum;
}

/// Each edge that one element has, as (lower, higher node); an edge of three or more elements
/// fails the test.
inline std::vector<std::pair<int, int>> free_edges(const FormedPart& p) {
  std::map<std::pair<int, int>, int> count;
  for (int e = 0; e < static_cast<int>(p.quads.cols() + p.triangles.cols()); ++e) {
    const std::vector<int> n = part_element_nodes(p, e);
    for (std::size_t k = 0; k < n.size(); ++k) {
      const int a = n[k], b = n[(k + 1) % n.size()];
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  }
  std::vector<std::pair<int, int>> out;
  for (const auto& [edge, c] : count) {
    EXPECT_LE(c, 2) << "edge " << edge.first << "-" << edge.second;
    if (c == 1) {
      out.push_back(edge);
    }
  }
  return out;
}

}  // namespace sf::test
