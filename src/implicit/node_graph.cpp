#include "implicit/node_graph.hpp"

#include <algorithm>

namespace sf {

NodeGraph make_node_graph(const ShellPart& part, int node_count) {
  std::vector<std::vector<int>> lists(static_cast<std::size_t>(node_count));
  auto add_element = [&](const int* nodes, int n) {
    for (int a = 0; a < n; ++a) {
      for (int b = 0; b < n; ++b) {
        lists[static_cast<std::size_t>(nodes[a])].push_back(nodes[b]);
      }
    }
  };
  for (Eigen::Index e = 0; e < part.quads.cols(); ++e) {
    add_element(part.quads.col(e).data(), 4);
  }
  for (Eigen::Index e = 0; e < part.triangles.cols(); ++e) {
    add_element(part.triangles.col(e).data(), 3);
  }
  NodeGraph g;
  g.start.assign(static_cast<std::size_t>(node_count) + 1, 0);
  for (int i = 0; i < node_count; ++i) {
    auto& list = lists[static_cast<std::size_t>(i)];
    list.push_back(i);  // a node without elements still couples to itself
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    g.start[static_cast<std::size_t>(i) + 1] =
        g.start[static_cast<std::size_t>(i)] + static_cast<int>(list.size());
  }
  g.neighbour.reserve(static_cast<std::size_t>(g.start.back()));
  for (const auto& list : lists) {
    g.neighbour.insert(g.neighbour.end(), list.begin(), list.end());
  }
  return g;
}

NodeColouring colour_distance_two(const NodeGraph& g) {
  const int n = g.node_count();
  NodeColouring c;
  c.colour.assign(static_cast<std::size_t>(n), -1);
  std::vector<int> used_by(64, -1);  // used_by[colour] = the last node that saw it nearby
  for (int i = 0; i < n; ++i) {
    for (int a = g.start[i]; a < g.start[i + 1]; ++a) {
      const int j = g.neighbour[static_cast<std::size_t>(a)];
      for (int b = g.start[j]; b < g.start[j + 1]; ++b) {
        const int colour =
            c.colour[static_cast<std::size_t>(g.neighbour[static_cast<std::size_t>(b)])];
        if (colour >= 0) {
          used_by[static_cast<std::size_t>(colour)] = i;
        }
      }
    }
    int colour = 0;
    while (colour < static_cast<int>(used_by.size()) &&
           used_by[static_cast<std::size_t>(colour)] == i) {
      ++colour;
    }
    if (colour == static_cast<int>(used_by.size())) {
      used_by.resize(2 * used_by.size(), -1);
    }
    c.colour[static_cast<std::size_t>(i)] = colour;
    c.colour_count = std::max(c.colour_count, colour + 1);
  }
  c.member_start.assign(static_cast<std::size_t>(c.colour_count) + 1, 0);
  for (int i = 0; i < n; ++i) {
    ++c.member_start[static_cast<std::size_t>(c.colour[static_cast<std::size_t>(i)]) + 1];
  }
  for (int k = 0; k < c.colour_count; ++k) {
    c.member_start[static_cast<std::size_t>(k) + 1] += c.member_start[static_cast<std::size_t>(k)];
  }
  c.members.resize(static_cast<std::size_t>(n));
  std::vector<int> fill(c.member_start.begin(), c.member_start.end() - 1);
  for (int i = 0; i < n; ++i) {
    c.members[static_cast<std::size_t>(
        fill[static_cast<std::size_t>(c.colour[static_cast<std::size_t>(i)])]++)] = i;
  }
  return c;
}

}  // namespace sf
