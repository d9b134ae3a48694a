// An MPI rank's Domain (parallel/mpi_domain.hpp) on a warped, distorted mixed mesh of quads and
// triangles, each method against what a serial run computes (issue 17, item 3):
// - the owned nodes of all ranks partition the node set, each owned or ghost node is held;
// - assemble_corners and assemble_half_thickness give the serial bits at every held node;
// - smallest_time_step: the serial smallest step and its element (the lowest on a tie);
// - agree: every rank gets the failure with the lowest key, whichever rank met it, and its
//   message and kind; no failure anywhere gives none;
// - gather_nodes / gather_elements: rank 0 gets every entry from its owner; gather_values the
//   ranks' values in rank order.
// Exit code 0 when every check passes on every rank (run by ctest at 1, 2 and 3 ranks).
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <vector>

#include "element/shell_directors.hpp"
#include "parallel/mpi_domain.hpp"
#include "support/warped_mixed_mesh.hpp"

namespace {

using namespace sf;

int failures = 0;

void check(bool ok, const char* what, int rank) {
  if (!ok) {
    std::printf("FAIL rank %d: %s\n", rank, what);
    ++failures;
  }
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  int ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  {
    const test::Mesh mesh = test::make_mesh(40, 25, 6);
    const ShellPart part = test::make_part(mesh, ShellFormulation::belytschko_tsay);
    const int n_nodes = static_cast<int>(mesh.x.cols());
    const int n_el = element_count(part);
    MpiDomain domain(part.quads, part.triangles, n_nodes, MPI_COMM_WORLD);
    const NodeCorners nodes = build_node_corners(part, n_nodes);

    // Owned nodes: every node exactly once over the ranks.
    std::vector<int> owner_count(static_cast<std::size_t>(n_nodes), 0);
    for (const int i : domain.owned_nodes()) {
      ++owner_count[static_cast<std::size_t>(i)];
    }
    MPI_Allreduce(MPI_IN_PLACE, owner_count.data(), n_nodes, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    check(std::all_of(owner_count.begin(), owner_count.end(), [](int c) { return c == 1; }),
          "every node owned by exactly one rank", rank);

    // Corners: a value per slot that depends on the slot, summed serially and by the domain.
    std::vector<double> corners(static_cast<std::size_t>(kCornerWidth) * nodes.slots.size());
    for (std::size_t k = 0; k < corners.size(); ++k) {
      corners[k] =
          std::sin(0.37 * static_cast<double>(k)) * 1e3 / (1.0 + static_cast<double>(k % 7));
    }
    Matrix3X f_serial(3, n_nodes), m_serial(3, n_nodes);
    gather_corner_forces(nodes, corners, f_serial, m_serial);
    Matrix3X f = Matrix3X::Zero(3, n_nodes), m = Matrix3X::Zero(3, n_nodes);
    domain.assemble_corners(nodes, corners, f, m);
    std::vector<double> thickness(static_cast<std::size_t>(n_el));
    for (int e = 0; e < n_el; ++e) {
      thickness[static_cast<std::size_t>(e)] = 0.8 + 0.01 * std::cos(0.91 * e);
    }
    VectorX inverse_count(n_nodes);
    for (int i = 0; i < n_nodes; ++i) {
      inverse_count[i] = 1.0 / (nodes.offsets[static_cast<std::size_t>(i) + 1] -
                                nodes.offsets[static_cast<std::size_t>(i)]);
    }
    VectorX h_serial(n_nodes), h = VectorX::Zero(n_nodes);
    gather_half_thickness(nodes, thickness, inverse_count, h_serial);
    domain.assemble_half_thickness(nodes, thickness, inverse_count, h);
    bool held_ok = true;
    for (const std::span<const int> list : {domain.owned_nodes(), domain.ghost_nodes()}) {
      for (const int i : list) {
        for (int c = 0; c < 3; ++c) {
          held_ok =
              held_ok && same_bits(f(c, i), f_serial(c, i)) && same_bits(m(c, i), m_serial(c, i));
        }
        held_ok = held_ok && same_bits(h[i], h_serial[i]);
      }
    }
    check(held_ok, "assembled forces, moments and half thickness: the serial bits", rank);

    // The smallest step, with a tie between two elements on different ends of the mesh.
    std::vector<double> element_dt(static_cast<std::size_t>(n_el));
    for (int e = 0; e < n_el; ++e) {
      element_dt[static_cast<std::size_t>(e)] = 1e-6 * (1.5 + std::sin(1.3 * e));
    }
    element_dt[17] = element_dt[static_cast<std::size_t>(n_el - 5)] = 1e-7;
    const StableStep want = smallest_time_step(element_dt);
    const StableStep got = domain.smallest_time_step(element_dt);
    check(want.element == 17 && got.element == 17 && same_bits(got.dt, want.dt),
          "smallest step: the serial one, the lower element on a tie", rank);

    // Failures: the lowest key wins, on every rank.
    PhaseError none = domain.agree({});
    check(!none.failed(), "no failure anywhere: none", rank);
    PhaseError mine;
    if (rank == ranks - 1) {
      mine = {PhaseError::Kind::instability, 42, "element 42 inverted"};
    }
    if (ranks > 1 && rank == 0) {
      mine = {PhaseError::Kind::input, 99, "node 99 too thin"};
    }
    const PhaseError agreed = domain.agree(mine);
    check(agreed.kind == PhaseError::Kind::instability && agreed.key == 42 &&
              agreed.message == "element 42 inverted",
          "the lowest-keyed failure, its kind and message, on every rank", rank);

    // Gathers: each rank fills its entries with its rank-independent truth; rank 0 gets all.
    std::vector<double> node_field(static_cast<std::size_t>(3 * n_nodes), -1.0);
    for (const int i : domain.owned_nodes()) {
      for (int c = 0; c < 3; ++c) {
        node_field[static_cast<std::size_t>(3 * i + c)] = 10.0 * i + c;
      }
    }
    domain.gather_nodes(node_field, 3);
    std::vector<double> element_field(static_cast<std::size_t>(2 * n_el), -1.0);
    for (const int e : domain.plan().elements) {
      element_field[static_cast<std::size_t>(2 * e)] = e;
      element_field[static_cast<std::size_t>(2 * e + 1)] = -e;
    }
    domain.gather_elements(element_field, 2);
    const double value = 100.0 + rank;
    const std::vector<double> values = domain.gather_values(std::span<const double>(&value, 1));
    if (rank == 0) {
      bool gathered = true;
      for (int i = 0; i < n_nodes; ++i) {
        for (int c = 0; c < 3; ++c) {
          gathered = gathered && node_field[static_cast<std::size_t>(3 * i + c)] == 10.0 * i + c;
        }
      }
      for (int e = 0; e < n_el; ++e) {
        gathered = gathered && element_field[static_cast<std::size_t>(2 * e)] == e &&
                   element_field[static_cast<std::size_t>(2 * e + 1)] == -e;
      }
      check(gathered, "rank 0 holds every node's and element's entries", rank);
      bool in_order = values.size() == static_cast<std::size_t>(ranks);
      for (int r = 0; in_order && r < ranks; ++r) {
        in_order = values[static_cast<std::size_t>(r)] == 100.0 + r;
      }
      check(in_order, "gather_values: every rank's value in rank order", rank);
    }
  }
  int all_failures = 0;
  MPI_Allreduce(&failures, &all_failures, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0) {
    std::printf("%d ranks: MpiDomain %s\n", ranks,
                all_failures == 0 ? "matches the serial run" : "FAILED checks");
  }
  MPI_Finalize();
  return all_failures == 0 ? 0 : 1;
}
