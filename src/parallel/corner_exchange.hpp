#pragma once
// The per-cycle message of a parallel run (issue 17; research/parallel.md §2, "Parith/ON"): each
// rank sends its neighbours the per-corner contributions (not node sums) at the nodes they share,
// then every holder of a node sums all the node's corners in serial order (rank_plan.hpp).
//
// Buffers are corner-slot-major and full size: the values of global corner slot s are at
// [width*s, width*s + width) of a buffer of width x n_corners doubles. A rank writes and reads
// only its own elements' slots; the rest of the buffer is never touched.
#include <mpi.h>

#include <cstddef>
#include <span>
#include <vector>

#include "parallel/rank_plan.hpp"

namespace sf {

/// The exchange of one rank's boundary corner values with its neighbours. It copies what it needs
/// from the plan and owns its scratch (send buffer, requests), so exchange() allocates nothing.
/// Call it from one thread at a time (MPI_THREAD_FUNNELED is enough) on every rank of the
/// plan's partition, as a collective over the neighbours.
class CornerExchange {
 public:
  /// width: doubles per corner (e.g. 6: force and moment). Throws std::invalid_argument when
  /// width < 1 or the message sizes overflow an int.
  explicit CornerExchange(const RankPlan& plan, int width);

  /// Sends width values per send slot to each neighbour and receives theirs: received (width x
  /// plan.receive_size) gets neighbour k's values at [width * receive_offset, ...) in its send
  /// order. comm must have plan.ranks ranks, this one being plan.rank. Throws
  /// std::invalid_argument on wrong sizes, std::runtime_error when an MPI call returns an error
  /// (only with an error handler that returns, e.g. MPI_ERRORS_RETURN; the default aborts).
  void exchange(std::span<const double> corners, std::span<double> received, MPI_Comm comm);

  int width() const { return width_; }

 private:
  int width_;
  int rank_;
  int ranks_;
  int n_corners_;
  int receive_size_;
  std::vector<int> neighbour_ranks_;
  std::vector<int> send_offsets_;  ///< neighbour k's slots at send_slots_[send_offsets_[k], ...)
  std::vector<int> send_slots_;
  std::vector<int> receive_offsets_;
  std::vector<int> receive_counts_;
  std::vector<double> send_buffer_;  ///< width x send_slots_.size()
  std::vector<MPI_Request> requests_;
};

/// For every held node of the plan, its entries (rank_plan.hpp) summed in list order from 0.0,
/// W values each, handed to out(node, sums): the serial assembly's bits at every held node.
/// corners: W per global corner slot; received: W per received corner, as
/// CornerExchange::exchange left it. Threads share out the nodes (out writes node-own data).
template <int W, typename Out>
void sum_at_held_nodes(const RankPlan& plan, const double* corners, const double* received,
                       const Out& out) {
  const int n = static_cast<int>(plan.nodes.size());
#pragma omp parallel for schedule(static) if (n >= 1024)
  for (int i = 0; i < n; ++i) {
    double sum[W] = {};
    for (int k = plan.gather_offsets[static_cast<std::size_t>(i)];
         k < plan.gather_offsets[static_cast<std::size_t>(i) + 1]; ++k) {
      const int entry = plan.gather_entries[static_cast<std::size_t>(k)];
      const double* value = entry >= 0 ? corners + W * static_cast<std::ptrdiff_t>(entry)
                                       : received + W * static_cast<std::ptrdiff_t>(-1 - entry);
      for (int c = 0; c < W; ++c) {
        sum[c] += value[c];
      }
    }
    out(plan.nodes[static_cast<std::size_t>(i)], sum);
  }
}

/// For every held node of the plan, each of its entries (rank_plan.hpp) in list order (the serial
/// slot order) handed to visit(node, values), W values each: for sums onto a value the node
/// already has. corners and received as for sum_at_held_nodes. Threads share out the nodes
/// (visit writes node-own data).
template <int W, typename Visit>
void for_each_held_node_entry(const RankPlan& plan, const double* corners, const double* received,
                              const Visit& visit) {
  const int n = static_cast<int>(plan.nodes.size());
#pragma omp parallel for schedule(static) if (n >= 1024)
  for (int i = 0; i < n; ++i) {
    const int node = plan.nodes[static_cast<std::size_t>(i)];
    for (int k = plan.gather_offsets[static_cast<std::size_t>(i)];
         k < plan.gather_offsets[static_cast<std::size_t>(i) + 1]; ++k) {
      const int entry = plan.gather_entries[static_cast<std::size_t>(k)];
      visit(node, entry >= 0 ? corners + W * static_cast<std::ptrdiff_t>(entry)
                             : received + W * static_cast<std::ptrdiff_t>(-1 - entry));
    }
  }
}

/// The reference node gather: for every held node of the plan, its entries (rank_plan.hpp)
/// summed in list order from 0.0, per value, into node_values (width x n_nodes, node-major like
/// the corners; written only at held nodes). corners: width x n_corners; received: width x
/// plan.receive_size, as CornerExchange::exchange left it. The result has the bits of the serial
/// assembly at every held node. Throws std::invalid_argument on wrong sizes.
void gather_node_values(const RankPlan& plan, std::span<const double> corners,
                        std::span<const double> received, int width, std::span<double> node_values);

}  // namespace sf
