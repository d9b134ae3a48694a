#pragma once
// The blank's elements shared out among MPI ranks (issue 17; research/parallel.md §2, §6.3):
// METIS cuts the dual graph of the mixed quad/triangle mesh (elements sharing an edge are
// neighbours). Rank 0 partitions once and broadcasts; the partition decides speed only, never
// results (the rank plans reproduce the serial assembly order whatever it is).
#include <span>
#include <vector>

#include "core/types.hpp"
#include "element/element_block.hpp"

namespace sf {

/// The blank's connectivity as the parallel module sees it (views, no copies): its element
/// blocks give the global element ids and corner slots (element/element_block.hpp).
struct BlankTopology {
  std::span<const int> quads;      ///< 4 x nq node ids (0-based), column-major
  std::span<const int> triangles;  ///< 3 x nt node ids (0-based), column-major
  int n_nodes = 0;
  ElementBlocks blocks;  ///< of quads and triangles

  BlankTopology(std::span<const int> quad_nodes, std::span<const int> triangle_nodes, int nodes)
      : quads(quad_nodes),
        triangles(triangle_nodes),
        n_nodes(nodes),
        blocks(element_blocks(quad_nodes, triangle_nodes)) {}

  int n_elements() const { return blocks.element_count(); }
  int n_corners() const { return blocks.corner_count(); }
  int corner_count(int element) const { return blocks.of(element).nodes_per_element(); }
  int first_slot(int element) const { return blocks.of(element).corner_slot(element, 0); }
  int element_of_slot(int slot) const { return blocks.of_slot(slot).element_of_slot(slot); }
  int node_of_slot(int slot) const { return blocks.of_slot(slot).node_of_slot(slot); }
};

/// A view of the solver's connectivity matrices (they must outlive the view).
BlankTopology blank_topology(const QuadConn& quads, const TriConn& triangles, int n_nodes);

/// Throws std::invalid_argument naming the problem: connectivity sizes not a multiple of 4 (3),
/// a node id outside [0, n_nodes), or more corners than an int can count.
void check_topology(const BlankTopology& t);

/// Part (0..parts-1) of every global element, by METIS_PartMeshDual: k-way, ncommon = 2, the
/// given METIS_OPTION_SEED (the same inputs give the same parts: METIS's random numbers come only
/// from the seed), contiguous parts when the mesh is edge-connected. element_weights (one per
/// element, > 0, or empty for all equal) become integer vertex weights round(100 w / min w),
/// at least 1. parts == 1 gives all zeros without METIS. A part may come back empty when parts
/// is close to the element count; the rank plans accept that.
/// Throws std::invalid_argument on bad input (parts < 1 or > elements, weights), and
/// std::runtime_error with METIS's status name when METIS fails.
std::vector<int> partition_elements(const BlankTopology& t, std::span<const double> element_weights,
                                    int parts, int seed);

}  // namespace sf
