#include "solver/trim.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "element/element_block.hpp"
#include "solver/part_remap.hpp"

namespace sf {
namespace {

// Which elements are kept: those whose current centre projects on the kept side.
std::vector<char> kept_elements(const FormedPart& part, const TrimOutline& outline) {
  const TrimRegion region(outline, part.file);
  const std::vector<double>& x = part.fields.at("x");
  const auto elements = static_cast<int>(part.quads.cols() + part.triangles.cols());
  std::vector<char> kept(static_cast<std::size_t>(elements), 0);
  for (int e = 0; e < elements; ++e) {
    Vec3 centre = Vec3::Zero();
    const std::vector<int> nodes = part_element_nodes(part, e);
    for (int a : nodes) {
      centre += Vec3(x[3 * a], x[3 * a + 1], x[3 * a + 2]);
    }
    centre /= static_cast<double>(nodes.size());
    kept[static_cast<std::size_t>(e)] = region.keeps(centre);
  }
  return kept;
}

void check_trim_leaves_a_part(const FormedPart& part, std::size_t kept, std::size_t elements) {
  if (kept == elements) {
    throw InputError(part.file +
                     ": the trim line misses the part: no element's centre is on the "
                     "scrap side");
  }
  if (kept == 0) {
    throw InputError(part.file +
                     ": the trim line leaves no part: every element's centre is on "
                     "the scrap side");
  }
}

}  // namespace

FormedPart trim_by_removal(const FormedPart& part, const TrimOutline& outline,
                           TrimSummary* summary) {
  const std::vector<char> kept = kept_elements(part, outline);
  check_trim_leaves_a_part(part, static_cast<std::size_t>(std::count(kept.begin(), kept.end(), 1)),
                           kept.size());
  const Eigen::Index n_nodes = part.reference_nodes.cols();
  const ElementBlocks blocks = element_blocks(part.quads, part.triangles);
  std::vector<int> new_node(static_cast<std::size_t>(n_nodes), -1);
  for (std::size_t e = 0; e < kept.size(); ++e) {
    if (kept[e]) {
      for (int a : part_element_nodes(part, static_cast<int>(e))) {
        new_node[static_cast<std::size_t>(a)] = 0;
      }
    }
  }
  PartRemap map;
  for (int i = 0; i < n_nodes; ++i) {
    if (new_node[static_cast<std::size_t>(i)] == 0) {
      new_node[static_cast<std::size_t>(i)] = static_cast<int>(map.nodes.size());
      map.nodes.push_back({.a = i, .b = i, .t = 0.0, .origin = i});
    }
  }
  for (std::size_t e = 0; e < kept.size(); ++e) {
    if (!kept[e]) {
      continue;
    }
    ElementSource element{.nodes = {}, .parent = static_cast<int>(e), .whole = true};
    const std::vector<int> nodes = part_element_nodes(part, static_cast<int>(e));
    for (std::size_t a = 0; a < nodes.size(); ++a) {
      element.nodes[a] = new_node[static_cast<std::size_t>(nodes[a])];
    }
    const bool quad = blocks.of(element.parent).shape == ElementShape::quad;
    (quad ? map.quads : map.triangles).push_back(element);
  }
  FormedPart out = remap_part(part, map);
  if (summary) {
    summary->elements_before = static_cast<int>(kept.size());
    summary->elements_removed =
        static_cast<int>(kept.size() - map.quads.size() - map.triangles.size());
    summary->nodes_removed = static_cast<int>(n_nodes) - static_cast<int>(map.nodes.size());
    summary->piece_elements = part_piece_sizes(out);
  }
  return out;
}

}  // namespace sf
