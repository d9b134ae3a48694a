#pragma once
// The blank's elements shared out among MPI ranks (issue 17; research/parallel.md §2, §6.3):
// METIS cuts the dual graph of the mixed quad/triangle mesh (elements sharing an edge are
// neighbours). Rank 0 partitions once and broadcasts; the partition decides speed only, never
// results (the rank plans reproduce the serial assembly order whatever it is).
#include <span>
#include <vector>

#include "core/types.hpp"

namespace sf {

/// The blank's connectivity as the parallel module sees it (views, no copies).
/// Global element ids: quads 0..nq-1, then triangles nq..nq+nt-1. Global corner slots: quad e
/// corner a -> 4e + a; triangle k corner a -> 4nq + 3k + a. So slot s's node is simply entry s
/// of the quads' connectivity followed by the triangles'.
struct BlankTopology {
  std::span<const int> quads;      ///< 4 x nq node ids (0-based), column-major
  std::span<const int> triangles;  ///< 3 x nt node ids (0-based), column-major
  int n_nodes = 0;

  int n_quads() const { return static_cast<int>(quads.size() / 4); }
  int n_triangles() const { return static_cast<int>(triangles.size() / 3); }
  int n_elements() const { return n_quads() + n_triangles(); }
  int n_corners() const { return static_cast<int>(quads.size() + triangles.size()); }
  int corner_count(int element) const { return element < n_quads() ? 4 : 3; }
  int first_slot(int element) const {
    const int nq = n_quads();
    return element < nq ? 4 * element : 4 * nq + 3 * (element - nq);
  }
  int element_of_slot(int slot) const {
    const int quad_slots = static_cast<int>(quads.size());
    return slot < quad_slots ? slot / 4 : n_quads() + (slot - quad_slots) / 3;
  }
  int node_of_slot(int slot) const {
    const auto s = static_cast<std::size_t>(slot);
    return s < quads.size() ? quads[s] : triangles[s - quads.size()];
  }
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
