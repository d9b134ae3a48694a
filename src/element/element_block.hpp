#pragma once
// Element blocks (shared/DESIGN.md section 6, R6): a part's elements as contiguous ranges of one
// shape each, the only place that knows how a part orders its quads and triangles. A block names
// its elements' range in the part's state (per-element and per-point arrays are indexed by that
// state index), its node indices and its corner-force slots; the element loop
// (element_loop.hpp) runs one block at a time.
#include <array>
#include <cstddef>
#include <span>

#include "element/shell_part.hpp"

namespace sf {

/// The shape of a block's elements.
enum class ElementShape { quad, triangle };

/// A contiguous range of a part's elements of one shape (the formulation is the part's).
struct ElementBlock {
  ElementShape shape = ElementShape::quad;
  int first = 0;               ///< state index of the block's first element
  int count = 0;               ///< its elements
  int first_slot = 0;          ///< corner slot of its first element's first corner
  const int* nodes = nullptr;  ///< node ids, nodes_per_element() per element

  int end() const { return first + count; }
  int nodes_per_element() const { return shape == ElementShape::quad ? 4 : 3; }
  bool holds(int e) const { return e >= first && e < end(); }
  /// Position of state element e within the block (0 .. count - 1).
  int local(int e) const { return e - first; }
  /// Node ids of state element e.
  const int* element_nodes(int e) const {
    return nodes + static_cast<std::ptrdiff_t>(nodes_per_element()) * local(e);
  }
  /// Corner slot of corner a of state element e.
  int corner_slot(int e, int a) const { return first_slot + nodes_per_element() * local(e) + a; }
  /// One past the corner slot of its last element's last corner.
  int slot_end() const { return first_slot + nodes_per_element() * count; }
  bool holds_slot(int slot) const { return slot >= first_slot && slot < slot_end(); }
  /// The state element of one of its corner slots.
  int element_of_slot(int slot) const { return first + (slot - first_slot) / nodes_per_element(); }
  /// The node of one of its corner slots.
  int node_of_slot(int slot) const { return nodes[slot - first_slot]; }
};

/// A part's blocks in state order (empty shapes left out): no allocation, so the time loop may
/// ask for them every cycle.
struct ElementBlocks {
  std::array<ElementBlock, 2> block{};
  int size = 0;

  const ElementBlock* begin() const { return block.data(); }
  const ElementBlock* end() const { return block.data() + size; }
  /// The block holding state element e (which must be one of the part's).
  const ElementBlock& of(int e) const {
    return size > 1 && block[1].holds(e) ? block[1] : block[0];
  }
  /// The block holding corner slot s (which must be one of the part's).
  const ElementBlock& of_slot(int s) const {
    return size > 1 && block[1].holds_slot(s) ? block[1] : block[0];
  }
  int element_count() const { return size == 0 ? 0 : block[size - 1].end(); }
  int corner_count() const { return size == 0 ? 0 : block[size - 1].slot_end(); }
};

/// The blocks of a mesh given as its connectivity (a part's, a formed part's, a blank mesh's):
/// its quads, then its triangles, which is how every state array, corner slot and output cell
/// numbers them.
ElementBlocks element_blocks(const QuadConn& quads, const TriConn& triangles);
/// The same for connectivity given as flat node ids: 4 per quad, then 3 per triangle (views:
/// the blocks point into them). A trailing partial element (a size not a multiple of 4 or 3) is
/// left out; check such input before.
ElementBlocks element_blocks(std::span<const int> quads, std::span<const int> triangles);
/// The part's blocks: its quads, then its triangles.
inline ElementBlocks element_blocks(const ShellPart& part) {
  return element_blocks(part.quads, part.triangles);
}

/// The block holding state element e of the part (for one element; a loop over many asks
/// element_blocks once and then ElementBlocks::of).
inline ElementBlock block_of(const ShellPart& part, int e) {
  return element_blocks(part).of(e);
}

}  // namespace sf
