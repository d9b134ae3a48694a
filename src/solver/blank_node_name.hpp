#pragma once
// How messages name a blank node: its index and its gmsh tag.
#include <fmt/core.h>

#include <functional>
#include <string>

#include "model/model.hpp"

namespace sf {

/// "node 12 (gmsh 13)"; the model must outlive the function.
inline std::function<std::string(int)> blank_node_namer(const Model& model) {
  return [&tags = model.blank.mesh.gmsh_node_tags](int node) {
    return fmt::format("node {} (gmsh {})", node, tags[static_cast<std::size_t>(node)]);
  };
}

}  // namespace sf
