#pragma once
// Trimming a formed part by removing the elements on the scrap side of a trim line (issue 32,
// item 3; shared/DESIGN.md R8: a topology change is a function from formed part to formed part
// that maps the state). The trim line (a closed polyline, or a tool's outline grown by an offset:
// solver/trim_outline.hpp) is projected along a direction (the press direction by default) onto
// the part as it stands; an element whose centre (the mean of its nodes' current coordinates)
// projects inside it is kept (or, keep_inside = false, outside it). The nodes no kept element uses
// are dropped and the rest renumbered in their order.
//
// The state follows as solver/part_remap.hpp maps it (every kept node and element as it was);
// solver/trim_cut.hpp cuts the elements the line crosses instead.
#include <vector>

#include "core/types.hpp"
#include "solver/formed_part.hpp"
#include "solver/trim_outline.hpp"

namespace sf {

/// What a trim removed and what it left.
struct TrimSummary {
  int elements_before = 0;
  int elements_removed = 0;
  int nodes_removed = 0;
  /// The kept part's connected pieces (elements joined through shared nodes): elements each,
  /// largest first; more than one is a piece that may float free.
  std::vector<int> piece_elements;
  // A clean cut's (solver/trim_cut.hpp); zero for a removal.
  int elements_cut = 0;       ///< elements the line crosses, split along it
  int pieces_made = 0;        ///< the elements their kept sides became
  int elements_reshaped = 0;  ///< kept whole, a node moved onto the line
  int nodes_made = 0;         ///< where the line crosses an edge
  int nodes_moved = 0;        ///< onto the line, a cut having passed too near them
  double largest_move = 0.0;  ///< mm, of a node moved onto the line
  /// -, the smallest area of a piece or of an element with a moved node, over its parent's
  double smallest_fraction = 1.0;
};

/// The part with the elements on the scrap side removed. Throws InputError naming the part's
/// file for an outline TrimRegion refuses, a line that misses the part (nothing removed) or
/// leaves no part.
FormedPart trim_by_removal(const FormedPart& part, const TrimOutline& outline,
                           TrimSummary* summary = nullptr);

}  // namespace sf
