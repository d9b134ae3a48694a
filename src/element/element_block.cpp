#include "element/element_block.hpp"

namespace sf {

ElementBlocks element_blocks(std::span<const int> quads, std::span<const int> triangles) {
  ElementBlocks blocks;
  const int n_quads = static_cast<int>(quads.size() / 4);
  const int n_triangles = static_cast<int>(triangles.size() / 3);
  if (n_quads > 0) {
    blocks.block[blocks.size++] = {ElementShape::quad, 0, n_quads, 0, quads.data()};
  }
  if (n_triangles > 0) {
    blocks.block[blocks.size++] = {ElementShape::triangle, n_quads, n_triangles, 4 * n_quads,
                                   triangles.data()};
  }
  return blocks;
}

ElementBlocks element_blocks(const QuadConn& quads, const TriConn& triangles) {
  return element_blocks(
      std::span<const int>(quads.data(), static_cast<std::size_t>(quads.size())),
      std::span<const int>(triangles.data(), static_cast<std::size_t>(triangles.size())));
}

}  // namespace sf
