#pragma once
// What one MPI rank holds of a partitioned blank and how it assembles its nodes with the same
// bits as a serial run (issue 17; research/parallel.md §2 "Parith/ON", §6.3).
//
// Serial assembly sums, at every node, its corners' contributions in ascending global corner
// slot order, starting from 0.0. A rank holds every node its elements touch; for each held node
// it gathers ALL the node's corners in that same order: its own corners from its corner buffer,
// the others from the values its neighbours sent (corner_exchange.hpp). Every holder of a node
// thus adds the same numbers in the same order, and gets the serial bits.
//
// Every rank can build every rank's plan from the global partition (no messages): a rank knows
// the order in which each neighbour sends, because it is the neighbour's own send order.
#include <span>
#include <vector>

#include "element/corner_forces.hpp"
#include "parallel/mesh_partition.hpp"

namespace sf {

/// The serial node-to-corner lists of the whole blank (element/corner_forces.hpp: node n's global
/// corner slots, ascending, at slots[offsets[n], offsets[n+1])), after check_topology.
NodeCorners node_corner_lists(const BlankTopology& t);

/// A rank that shares at least one node with this one.
struct RankNeighbour {
  int rank = 0;
  /// Global corner slots of this rank's elements at nodes the neighbour also holds, ascending:
  /// the values sent to the neighbour, in this order.
  std::vector<int> send_slots;
  /// Where the neighbour's values land in this rank's receive buffer (in corners, not doubles):
  /// the neighbour's send_slots to this rank, in its order.
  int receive_offset = 0;
  int receive_count = 0;
};

/// One rank's share of the blank and its assembly order.
struct RankPlan {
  int rank = 0;
  int ranks = 1;
  int n_nodes = 0;               ///< of the whole blank (full-size node arrays)
  int n_corners = 0;             ///< of the whole blank (full-size corner buffers)
  std::vector<int> elements;     ///< this rank's global element ids, ascending
  std::vector<int> nodes;        ///< held: the nodes its elements touch, ascending
  std::vector<int> owned_nodes;  ///< held nodes whose lowest holding rank is this one, ascending
  /// Node gather lists (CSR over `nodes`): held node nodes[i]'s entries at
  /// gather_entries[gather_offsets[i], gather_offsets[i+1]), one per corner of the whole mesh at
  /// that node, in ascending global slot order. Entry >= 0: a global corner slot of this rank's
  /// own elements; entry < 0: -(1 + j), j the corner's index in the receive buffer.
  std::vector<int> gather_offsets;
  std::vector<int> gather_entries;
  std::vector<RankNeighbour> neighbours;  ///< ascending rank
  int receive_size = 0;                   ///< corners received from all neighbours
};

/// The plan of `rank` (0..ranks-1) for the partition part_of_element (one part per global
/// element, each in [0, ranks)). Nodes that no element touches are held and owned by rank 0, so
/// that the owned nodes of all ranks partition the node set; with ranks == 1 the plan is the
/// identity (every node held and owned, every entry local, no neighbours). A rank without
/// elements gets an empty plan (apart from those nodes on rank 0).
/// Throws std::invalid_argument naming the problem on bad input. Costs O(corners) time and
/// memory (the whole mesh's node lists are built, then dropped).
RankPlan build_rank_plan(const BlankTopology& t, std::span<const int> part_of_element, int rank,
                         int ranks);

}  // namespace sf
