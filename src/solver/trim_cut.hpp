#pragma once
// Trimming a formed part by cutting it cleanly along the trim line (issue 32, item 3): the
// elements the line crosses are split along it, so that the part's edge is where the line runs.
//
// Seen along the line's direction (solver/trim_outline.hpp), each node is on the kept or the
// scrap side. Where an element edge joins the two sides, the line crosses it: the crossing is
// found on the edge as it stands, by bisection to round-off, and becomes a node. An element
// with nodes on both sides keeps the polygon of its kept nodes and crossings, split into a
// quadrilateral, a quadrilateral and a triangle, or two quadrilaterals (the split whose smallest
// piece is largest, every piece convex). Slivers are avoided by moving nodes onto the line: a
// crossing nearer than `sliver_fraction` of its edge to an end moves that end onto the line
// instead of making a node, and while a piece is smaller than `sliver_fraction` of its parent's
// area, the end nearest to one of the element's crossings moves onto it. A node moves only to a
// crossing nearer to it than to the edge's other end, and only along an edge whose other end
// shares all its node groups (a node on a symmetry plane stays on it); a sliver no node may be
// moved away from stays, and the summary reports the smallest piece. Elements wholly on the
// scrap side go, as do nodes no kept element uses.
//
// The state follows by solver/part_remap.hpp: a piece inherits its parent's point states, turned
// into its own frame; the nodes made on an edge and the nodes moved along one take the values
// interpolated there.
#include "solver/formed_part.hpp"
#include "solver/trim.hpp"
#include "solver/trim_outline.hpp"

namespace sf {

/// The default of sliver_fraction: no piece smaller than a tenth of its parent.
inline constexpr double kDefaultSliverFraction = 0.1;

/// The part cut along the outline. Throws InputError naming the part's file for an outline
/// TrimRegion refuses, a line that crosses no element and removes nothing, one that leaves no
/// part, or a sliver_fraction outside [0, 0.5).
FormedPart trim_by_cutting(const FormedPart& part, const TrimOutline& outline,
                           double sliver_fraction = kDefaultSliverFraction,
                           TrimSummary* summary = nullptr);

}  // namespace sf
