#include "element/element_block.hpp"

namespace sf {

ElementBlocks element_blocks(const QuadConn& quads, const TriConn& triangles) {
  ElementBlocks blocks;
  const int n_quads = static_cast<int>(quads.cols());
  const int n_triangles = static_cast<int>(triangles.cols());
  if (n_quads > 0) {
    blocks.block[blocks.size++] = {ElementShape::quad, 0, n_quads, 0, quads.data()};
  }
  if (n_triangles > 0) {
    blocks.block[blocks.size++] = {ElementShape::triangle, n_quads, n_triangles, 4 * n_quads,
                                   triangles.data()};
  }
  return blocks;
}

}  // namespace sf
