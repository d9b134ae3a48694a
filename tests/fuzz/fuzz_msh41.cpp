// Fuzz target: the MSH 4.1 binary reader (src/meshing/msh_file.cpp), the parser of what the
// sandboxed gmsh hands back: the one reader of bytes that crossed from the child, so it must hold
// against any bytes a child taken over could write.
// Checks: parse_msh41_binary returns or throws sf::InputError, nothing else; a model it returns
// is consistent (every element's node has coordinates, node_index matches node_tags, groups
// sorted by (dim, tag) with sorted unique node tags, blocks of whole elements).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/errors.hpp"
#include "fuzz_support.hpp"
#include "meshing/msh_file.hpp"

namespace {

void check_model(const sf::GmshModel& model) {
  if (static_cast<std::size_t>(model.node_coords.cols()) != model.node_tags.size() ||
      model.node_index.size() != model.node_tags.size()) {
    sf::fuzz::broken("model: node arrays disagree", "nodes");
  }
  for (std::size_t g = 0; g < model.groups.size(); ++g) {
    const sf::GmshPhysicalGroup& group = model.groups[g];
    if (g > 0 && !(std::pair(model.groups[g - 1].dim, model.groups[g - 1].tag) <
                   std::pair(group.dim, group.tag))) {
      sf::fuzz::broken("model: groups not sorted", group.name);
    }
    if (!std::is_sorted(group.node_tags.begin(), group.node_tags.end()) ||
        std::adjacent_find(group.node_tags.begin(), group.node_tags.end()) !=
            group.node_tags.end()) {
      sf::fuzz::broken("model: group nodes not sorted and unique", group.name);
    }
    for (const auto& block : group.elements) {
      if (block.nodes_per_element <= 0 ||
          block.node_tags.size() !=
              block.element_tags.size() * static_cast<std::size_t>(block.nodes_per_element)) {
        sf::fuzz::broken("model: a block of broken elements", group.name);
      }
      for (const std::size_t node : block.node_tags) {
        if (model.node_index.count(node) == 0) {
          sf::fuzz::broken("model: an element node without coordinates", group.name);
        }
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  sf::fuzz::quiet();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    check_model(sf::parse_msh41_binary(std::string_view(reinterpret_cast<const char*>(data), size),
                                       "mesh.msh"));
  } catch (const sf::InputError&) {
    return 0;
  } catch (const std::exception& e) {
    sf::fuzz::unexpected_exception("the MSH 4.1 reader", &e);
  } catch (...) {
    sf::fuzz::unexpected_exception("the MSH 4.1 reader", nullptr);
  }
  return 0;
}
