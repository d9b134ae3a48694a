// MPI check of the corner exchange (issue 17): every rank builds the same mixed quad/triangle
// blank, rank 0 partitions it and broadcasts the parts (as the solver will), each rank fills only
// its own elements' corners (the others stay zero, proving they are never read), exchanges with
// its neighbours and gathers its held nodes. Every held node must equal, bit for bit, the serial
// assembly (all the node's corners, ascending slot, from 0.0); nodes not held must be untouched.
// Run by ctest at 1, 2 and 3 ranks; exit code 0 when every rank agrees.
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <limits>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include "parallel/corner_exchange.hpp"
#include "parallel/mesh_partition.hpp"
#include "parallel/rank_plan.hpp"

namespace {

using sf::BlankTopology;

// An nx x ny grid of quads with a strip of 2 ny triangles along its right side; node ids
// scrambled by a multiplier prime to the node count. (6, 5) is test_rank_plan.cpp's mesh.
struct Mesh {
  std::vector<int> quads;
  std::vector<int> triangles;
  int n_nodes = 0;

  BlankTopology topology() const { return BlankTopology{quads, triangles, n_nodes}; }
};

Mesh mixed_mesh(int nx, int ny) {
  Mesh m;
  m.n_nodes = (nx + 2) * (ny + 1);
  int multiplier = 11;
  while (std::gcd(multiplier, m.n_nodes) != 1) {
    ++multiplier;
  }
  const auto id = [&](int i, int j) {
    const int plain = i <= nx ? j * (nx + 1) + i : (nx + 1) * (ny + 1) + j;
    return static_cast<int>((static_cast<long>(multiplier) * plain) % m.n_nodes);
  };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      m.quads.insert(m.quads.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  for (int j = 0; j < ny; ++j) {
    m.triangles.insert(m.triangles.end(), {id(nx, j), id(nx + 1, j), id(nx + 1, j + 1)});
    m.triangles.insert(m.triangles.end(), {id(nx, j), id(nx + 1, j + 1), id(nx, j + 1)});
  }
  return m;
}

// Mixed magnitudes (1e-6 .. 1e6, both signs), so that any change of summation order shows.
std::vector<double> random_values(std::size_t n, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-6, 6);
  std::vector<double> values(n);
  for (double& x : values) {
    x = mantissa(random) * std::pow(10.0, exponent(random));
  }
  return values;
}

// Serial assembly: every slot in ascending order added to its node, from 0.0.
std::vector<double> serial_gather(const BlankTopology& t, const std::vector<double>& corners,
                                  int width) {
  const auto w = static_cast<std::size_t>(width);
  std::vector<double> nodes(w * static_cast<std::size_t>(t.n_nodes), 0.0);
  for (int s = 0; s < t.n_corners(); ++s) {
    for (std::size_t c = 0; c < w; ++c) {
      nodes[w * static_cast<std::size_t>(t.node_of_slot(s)) + c] +=
          corners[w * static_cast<std::size_t>(s) + c];
    }
  }
  return nodes;
}

// This rank's own slots of `all`; every other slot zero.
std::vector<double> own_corners(const BlankTopology& t, const sf::RankPlan& plan,
                                const std::vector<double>& all, int width) {
  const auto w = static_cast<std::size_t>(width);
  std::vector<double> mine(all.size(), 0.0);
  for (const int e : plan.elements) {
    const auto begin = w * static_cast<std::size_t>(t.first_slot(e));
    const auto end = begin + w * static_cast<std::size_t>(t.corner_count(e));
    std::copy(all.begin() + static_cast<long>(begin), all.begin() + static_cast<long>(end),
              mine.begin() + static_cast<long>(begin));
  }
  return mine;
}

// Held nodes: the serial bits; other nodes: the NaN they started with.
bool same_bits_where_held(const sf::RankPlan& plan, const std::vector<double>& got,
                          const std::vector<double>& serial, int width) {
  const auto w = static_cast<std::size_t>(width);
  std::vector<char> held(static_cast<std::size_t>(plan.n_nodes), 0);
  for (const int n : plan.nodes) {
    held[static_cast<std::size_t>(n)] = 1;
  }
  for (std::size_t n = 0; n < held.size(); ++n) {
    for (std::size_t c = w * n; c < w * n + w; ++c) {
      const bool ok =
          held[n] ? std::memcmp(&got[c], &serial[c], sizeof(double)) == 0 : std::isnan(got[c]);
      if (!ok) {
        std::fprintf(stderr, "rank %d: node %zu value %zu: %.17g, serial %.17g (%s)\n", plan.rank,
                     n, c - w * n, got[c], serial[c], held[n] ? "held" : "not held");
        return false;
      }
    }
  }
  return true;
}

// Two rounds with one CornerExchange (the second reuses its scratch), new values each round.
bool check_exchange(const BlankTopology& t, const std::vector<int>& part, int width,
                    MPI_Comm comm) {
  int rank = 0;
  int ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  const sf::RankPlan plan = sf::build_rank_plan(t, part, rank, ranks);
  sf::CornerExchange exchange(plan, width);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  bool ok = true;
  for (unsigned round = 0; round < 2; ++round) {
    const auto w = static_cast<std::size_t>(width);
    const std::vector<double> all = random_values(w * static_cast<std::size_t>(t.n_corners()),
                                                  29 + round);  // the same on every rank
    const std::vector<double> mine = own_corners(t, plan, all, width);
    std::vector<double> received(w * static_cast<std::size_t>(plan.receive_size), nan);
    exchange.exchange(mine, received, comm);
    std::vector<double> nodes(w * static_cast<std::size_t>(t.n_nodes), nan);
    sf::gather_node_values(plan, mine, received, width, nodes);
    ok = same_bits_where_held(plan, nodes, serial_gather(t, all, width), width) && ok;
  }
  return ok;
}

// Rank 0 partitions with METIS and broadcasts, as the solver will.
std::vector<int> broadcast_metis_parts(const BlankTopology& t, MPI_Comm comm) {
  int rank = 0;
  int ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  std::vector<int> part(static_cast<std::size_t>(t.n_elements()));
  if (rank == 0) {
    part = sf::partition_elements(t, {}, ranks, 17);
  }
  MPI_Bcast(part.data(), t.n_elements(), MPI_INT, 0, comm);
  return part;
}

std::vector<int> scattered_parts(const BlankTopology& t, int ranks) {
  std::vector<int> part;
  for (int e = 0; e < t.n_elements(); ++e) {
    part.push_back((5 * e + e / 3) % ranks);  // no contiguity: every rank neighbours every other
  }
  return part;
}

// The small mesh with METIS and scattered parts, widths 6 (force and moment) and 1; a larger
// mesh (about 10k elements) whose messages exceed the eager limit of shared-memory transports.
bool run_checks(MPI_Comm comm) {
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  bool ok = true;
  for (const auto& [nx, ny] : {std::pair{6, 5}, std::pair{120, 80}}) {
    const Mesh mesh = mixed_mesh(nx, ny);
    const BlankTopology t = mesh.topology();
    const std::vector<int> metis = broadcast_metis_parts(t, comm);
    const std::vector<int> scattered = scattered_parts(t, ranks);
    for (const int width : {6, 1}) {
      ok = check_exchange(t, metis, width, comm) && ok;
      ok = check_exchange(t, scattered, width, comm) && ok;
    }
  }
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  int ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  int ok_here = 0;
  try {
    ok_here = run_checks(MPI_COMM_WORLD) ? 1 : 0;
  } catch (const std::exception& e) {
    // Other ranks may wait in an exchange for this one: abort rather than hang.
    std::fprintf(stderr, "rank %d: %s\n", rank, e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  int ok_everywhere = 0;
  MPI_Allreduce(&ok_here, &ok_everywhere, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (rank == 0) {
    std::printf("%d ranks: corner exchange and node gather %s the serial assembly\n", ranks,
                ok_everywhere ? "give the same bits as" : "DIFFER from");
  }
  MPI_Finalize();
  return ok_everywhere ? 0 : 1;
}
