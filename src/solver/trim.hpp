#pragma once
// Trimming a formed part by removing the elements on the scrap side of a trim line (issue 32,
// item 3; shared/DESIGN.md R8: a topology change is a function from formed part to formed part
// that maps the state). The trim line (a closed polyline, or a tool's outline grown by an offset:
// solver/trim_outline.hpp) is projected along a direction (the press direction by default) onto
// the part as it stands; an element whose centre (the mean of its nodes' current coordinates)
// projects inside it is kept (or, keep_inside = false, outside it). The nodes no kept element uses
// are dropped and the rest renumbered in their order.
//
// The state follows by each field's mapping (solver/state_fields.hpp): the run's numbers and
// the tools' are kept; a node field that interpolates (coordinates, velocities, rotations) keeps
// the kept nodes' values; an element or point field keeps the kept elements' values whole (a kept
// element did not change); the node fields made again from the new mesh (forces, masses,
// contact offsets) and the contact pairs' history are left out, for the next model to recompute.
#include <vector>

#include "core/types.hpp"
#include "model/build_model.hpp"
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
};

/// The part with the elements on the scrap side removed. Throws InputError naming the part's
/// file for an outline TrimRegion refuses, a line that misses the part (nothing removed) or
/// leaves no part.
FormedPart trim_by_removal(const FormedPart& part, const TrimOutline& outline,
                           TrimSummary* summary = nullptr);

/// The part's mesh and node groups, for build_model to build the next model on.
BlankMesh blank_mesh_of(const FormedPart& part);

}  // namespace sf
