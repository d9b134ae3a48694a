#include "parallel/mpi_domain.hpp"

#include <algorithm>
#include <climits>
#include <limits>
#include <stdexcept>
#include <string>

#include "parallel/exact_allreduce.hpp"
#include "parallel/mesh_partition.hpp"
#include "solver/phase_times.hpp"  // PhaseTimer: the time in messages

namespace sf {

namespace {

// METIS's seed: the same partition on every run (it decides speed only, never results).
constexpr int kPartitionSeed = 17;

int comm_rank(MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  return rank;
}

int comm_size(MPI_Comm comm) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  return size;
}

// The part of every element: METIS on rank 0, broadcast (one partition, whatever METIS would do
// on another rank's build).
std::vector<int> broadcast_partition(const BlankTopology& topology, MPI_Comm comm) {
  const int ranks = comm_size(comm);
  const int n = topology.n_elements();
  if (n < ranks) {
    throw std::invalid_argument("the blank has " + std::to_string(n) + " element" +
                                (n == 1 ? "" : "s") + " for " + std::to_string(ranks) +
                                " MPI ranks: run with at most " + std::to_string(n) +
                                (n == 1 ? " rank" : " ranks"));
  }
  std::vector<int> parts(static_cast<std::size_t>(n), 0);
  if (comm_rank(comm) == 0) {
    parts = partition_elements(topology, {}, ranks, kPartitionSeed);
  }
  MPI_Bcast(parts.data(), n, MPI_INT, 0, comm);
  return parts;
}

RankPlan make_plan(const QuadConn& quads, const TriConn& triangles, int n_nodes, MPI_Comm comm) {
  const BlankTopology topology = blank_topology(quads, triangles, n_nodes);
  check_topology(topology);
  const std::vector<int> parts = broadcast_partition(topology, comm);
  return build_rank_plan(topology, parts, comm_rank(comm), comm_size(comm));
}

}  // namespace

MpiDomain::MpiDomain(const QuadConn& quads, const TriConn& triangles, int n_nodes, MPI_Comm comm)
    : comm_(comm),
      plan_(make_plan(quads, triangles, n_nodes, comm)),
      runs_(sf::element_runs(plan_.elements, element_blocks(quads, triangles))),
      forces_(plan_, kCornerWidth),
      thickness_(plan_, 1),
      masses_(plan_, kMassCornerWidth),
      loads_(plan_, kLoadCornerWidth),
      received_forces_(static_cast<std::size_t>(plan_.receive_size) * kCornerWidth),
      received_masses_(static_cast<std::size_t>(plan_.receive_size) * kMassCornerWidth),
      received_loads_(static_cast<std::size_t>(plan_.receive_size) * kLoadCornerWidth),
      received_thickness_(static_cast<std::size_t>(plan_.receive_size)),
      thickness_corners_(static_cast<std::size_t>(plan_.n_corners), 0.0),
      node_layout_(gather_layout(plan_.owned_nodes, comm, plan_.rank, plan_.ranks)),
      element_layout_(gather_layout(plan_.elements, comm, plan_.rank, plan_.ranks)) {
  std::set_difference(plan_.nodes.begin(), plan_.nodes.end(), plan_.owned_nodes.begin(),
                      plan_.owned_nodes.end(), std::back_inserter(ghost_nodes_));
}

void MpiDomain::assemble_corners(const NodeCorners& /*nodes*/, std::span<const double> corners,
                                 Matrix3X& f, Matrix3X& m) {
  {
    const PhaseTimer timer(communication_seconds_);
    forces_.exchange(corners, received_forces_, comm_);
  }
  // As gather_corner_forces: from 0, in the node's ascending global slot order.
  sum_at_held_nodes<kCornerWidth>(plan_, corners.data(), received_forces_.data(),
                                  [&](int node, const double* sum) {
                                    for (int c = 0; c < 3; ++c) {
                                      f(c, node) = sum[c];
                                      m(c, node) = sum[3 + c];
                                    }
                                  });
}

void MpiDomain::add_corner_masses(const NodeCorners& /*nodes*/, std::span<const double> corner_mass,
                                  VectorX& mass, VectorX& inertia) {
  {
    const PhaseTimer timer(communication_seconds_);
    masses_.exchange(corner_mass, received_masses_, comm_);
  }
  // As sf::add_corner_masses: onto the node's value, one corner at a time in serial slot order.
  for_each_held_node_entry<kMassCornerWidth>(plan_, corner_mass.data(), received_masses_.data(),
                                             [&](int node, const double* corner) {
                                               mass[node] += corner[0];
                                               inertia[node] += corner[1];
                                             });
}

void MpiDomain::add_flagged_corner_forces(const NodeCorners& /*nodes*/,
                                          std::span<const double> corners, Matrix3X& f) {
  {
    const PhaseTimer timer(communication_seconds_);
    loads_.exchange(corners, received_loads_, comm_);
  }
  // As sf::add_flagged_corner_forces: onto the node's value, in serial slot order.
  for_each_held_node_entry<kLoadCornerWidth>(
      plan_, corners.data(), received_loads_.data(), [&](int node, const double* corner) {
        if (corner[3] != 0.0) {
          f.col(node) += Vec3(corner[0], corner[1], corner[2]);
        }
      });
}

void MpiDomain::assemble_half_thickness(const ElementBlocks& blocks, const NodeCorners& /*nodes*/,
                                        std::span<const double> thickness,
                                        const VectorX& inverse_element_count,
                                        VectorX& half_thickness) {
  // Each own corner carries half its element's thickness, as gather_half_thickness adds it.
  for (const ElementRun& run : runs_) {
    const ElementBlock& block = blocks.of(run.begin);  // a run lies in one block
    for (int e = run.begin; e < run.end; ++e) {
      const double half = 0.5 * thickness[static_cast<std::size_t>(e)];
      for (int a = 0; a < block.nodes_per_element(); ++a) {
        thickness_corners_[static_cast<std::size_t>(block.corner_slot(e, a))] = half;
      }
    }
  }
  {
    const PhaseTimer timer(communication_seconds_);
    thickness_.exchange(thickness_corners_, received_thickness_, comm_);
  }
  sum_at_held_nodes<1>(plan_, thickness_corners_.data(), received_thickness_.data(),
                       [&](int node, const double* sum) {
                         half_thickness[node] = sum[0] * inverse_element_count[node];
                       });
}

void MpiDomain::reduce(std::span<ExactSum> sums) {
  const PhaseTimer timer(communication_seconds_);
  for (std::size_t begin = 0; begin < sums.size(); begin += kMaxExactAllreduce) {
    const std::size_t count = std::min<std::size_t>(kMaxExactAllreduce, sums.size() - begin);
    allreduce_exact(sums.subspan(begin, count), comm_);
  }
}

StableStep MpiDomain::smallest_time_step(std::span<const double> element_dt) {
  // This rank's smallest (the first in element order on a tie), then the global one: MINLOC
  // takes the lowest element on a tie, as a serial pass does.
  struct {
    double dt;
    int element;
  } mine{std::numeric_limits<double>::infinity(), INT_MAX}, global{};
  for (const ElementRun& run : runs_) {
    for (int e = run.begin; e < run.end; ++e) {
      if (element_dt[static_cast<std::size_t>(e)] < mine.dt) {
        mine = {element_dt[static_cast<std::size_t>(e)], e};
      }
    }
  }
  {
    const PhaseTimer timer(communication_seconds_);
    MPI_Allreduce(&mine, &global, 1, MPI_DOUBLE_INT, MPI_MINLOC, comm_);
  }
  return {global.dt, global.element == INT_MAX ? -1 : global.element};
}

PhaseError MpiDomain::agree(PhaseError local) {
  const PhaseTimer timer(communication_seconds_);
  struct {
    long key;
    int rank;
  } mine{local.failed() ? std::min(local.key, LONG_MAX - 1) : LONG_MAX, plan_.rank}, first{};
  MPI_Allreduce(&mine, &first, 1, MPI_LONG_INT, MPI_MINLOC, comm_);
  if (first.key == LONG_MAX) {
    return {};
  }
  // The failing rank with the lowest key tells the others its kind and message.
  int header[2] = {static_cast<int>(local.kind), static_cast<int>(local.message.size())};
  MPI_Bcast(header, 2, MPI_INT, first.rank, comm_);
  PhaseError agreed{static_cast<PhaseError::Kind>(header[0]), first.key,
                    std::string(static_cast<std::size_t>(header[1]), ' ')};
  if (plan_.rank == first.rank) {
    agreed.message = local.message;
  }
  MPI_Bcast(agreed.message.data(), header[1], MPI_CHAR, first.rank, comm_);
  return agreed;
}

int MpiDomain::agree_flags(int flags) {
  const PhaseTimer timer(communication_seconds_);
  int all = 0;
  MPI_Allreduce(&flags, &all, 1, MPI_INT, MPI_BOR, comm_);
  return all;
}

MpiDomain::RootLayout MpiDomain::gather_layout(std::span<const int> mine, MPI_Comm comm, int rank,
                                               int ranks) {
  RootLayout layout;
  const int count = static_cast<int>(mine.size());
  if (rank == 0) {
    layout.counts.resize(static_cast<std::size_t>(ranks));
  }
  MPI_Gather(&count, 1, MPI_INT, layout.counts.data(), 1, MPI_INT, 0, comm);
  if (rank == 0) {
    layout.displacements.assign(static_cast<std::size_t>(ranks), 0);
    for (std::size_t r = 1; r < static_cast<std::size_t>(ranks); ++r) {
      layout.displacements[r] = layout.displacements[r - 1] + layout.counts[r - 1];
    }
    layout.indices.resize(
        static_cast<std::size_t>(layout.displacements.back() + layout.counts.back()));
  }
  MPI_Gatherv(mine.data(), count, MPI_INT, layout.indices.data(), layout.counts.data(),
              layout.displacements.data(), MPI_INT, 0, comm);
  return layout;
}

void MpiDomain::gather(std::span<double> data, int width, std::span<const int> mine,
                       const RootLayout& layout) {
  const PhaseTimer timer(communication_seconds_);
  const auto w = static_cast<std::size_t>(width);
  send_.resize(w * mine.size());
  for (std::size_t i = 0; i < mine.size(); ++i) {
    std::copy_n(data.data() + w * static_cast<std::size_t>(mine[i]), w, send_.data() + w * i);
  }
  std::vector<int> counts, displacements;
  if (plan_.rank == 0) {
    receive_.resize(w * layout.indices.size());
    for (std::size_t r = 0; r < layout.counts.size(); ++r) {
      counts.push_back(width * layout.counts[r]);
      displacements.push_back(width * layout.displacements[r]);
    }
  }
  MPI_Gatherv(send_.data(), static_cast<int>(send_.size()), MPI_DOUBLE, receive_.data(),
              counts.data(), displacements.data(), MPI_DOUBLE, 0, comm_);
  if (plan_.rank == 0) {
    for (std::size_t i = 0; i < layout.indices.size(); ++i) {
      std::copy_n(receive_.data() + w * i, w,
                  data.data() + w * static_cast<std::size_t>(layout.indices[i]));
    }
  }
}

void MpiDomain::gather_nodes(std::span<double> data, int width) {
  gather(data, width, plan_.owned_nodes, node_layout_);
}

void MpiDomain::gather_elements(std::span<double> data, int width) {
  gather(data, width, plan_.elements, element_layout_);
}

std::vector<double> MpiDomain::gather_values(std::span<const double> values) {
  const int n = static_cast<int>(values.size());
  std::vector<double> all(plan_.rank == 0 ? values.size() * static_cast<std::size_t>(plan_.ranks)
                                          : 0);
  MPI_Gather(values.data(), n, MPI_DOUBLE, all.data(), n, MPI_DOUBLE, 0, comm_);
  return all;
}

}  // namespace sf
