// An MPI rank's Domain (parallel/mpi_domain.hpp) on a warped, distorted mixed mesh of quads and
// triangles, each method against what a serial run computes (issue 17, item 3):
// - the owned nodes of all ranks partition the node set, each owned or ghost node is held;
// - assemble_corners and assemble_half_thickness give the serial bits at every held node;
// - add_corner_masses and add_flagged_corner_forces (mass scaling, pressure loads) add onto the
//   nodes' values with the bits of the serial element-order rule, reading only own slots;
// - smallest_time_step: the serial smallest step and its element (the lowest on a tie);
// - agree: every rank gets the failure with the lowest key, whichever rank met it, and its
//   message and kind; no failure anywhere gives none;
// - gather_nodes / gather_elements: rank 0 gets every entry from its owner; gather_values the
//   ranks' values in rank order.
// Exit code 0 when every check passes on every rank (run by ctest at 1, 2 and 3 ranks).
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
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
    const ElementBlocks blocks = element_blocks(part);
    gather_half_thickness(nodes, thickness, inverse_count, h_serial);
    domain.assemble_half_thickness(blocks, nodes, thickness, inverse_count, h);
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

    // Masses added by elements (mass scaling) and flagged element loads (pressure), onto values
    // the nodes have: the bits of the serial rule, each element's share added to its nodes in
    // element order. Every third element adds nothing (0 / flag 0). Each rank writes only its
    // own elements' slots; the others hold NaN, which would show if they were read.
    const auto slot_of = [&](int e, int a) { return blocks.of(e).corner_slot(e, a); };
    const auto node_of = [&](int e, int a) { return blocks.of(e).element_nodes(e)[a]; };
    const auto corners_of = [&](int e) { return blocks.of(e).nodes_per_element(); };
    const auto share = [](int e, int c) {
      return e % 3 == 2 ? 0.0 : 1e-6 * (1.0 + 0.3 * std::sin(0.71 * e + c));
    };
    VectorX mass0(n_nodes), inertia0(n_nodes);
    for (int i = 0; i < n_nodes; ++i) {
      mass0[i] = 3e-5 * (1.0 + 0.1 * std::cos(1.7 * i));
      inertia0[i] = 2e-4 * (1.0 + 0.1 * std::sin(0.3 * i));
    }
    VectorX mass_want = mass0, inertia_want = inertia0;
    Matrix3X f_want = f_serial;
    for (int e = 0; e < n_el; ++e) {
      for (int a = 0; a < corners_of(e); ++a) {
        const int i = node_of(e, a);
        mass_want[i] += share(e, 0);
        inertia_want[i] += share(e, 1);
        if (e % 3 != 2) {
          f_want.col(i) += Vec3(share(e, 2), -share(e, 3), share(e, 4));
        }
      }
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> all_masses(static_cast<std::size_t>(kMassCornerWidth) * nodes.slots.size());
    std::vector<double> all_loads(static_cast<std::size_t>(kLoadCornerWidth) * nodes.slots.size());
    std::vector<double> own_masses(all_masses.size(), nan), own_loads(all_loads.size(), nan);
    for (int e = 0; e < n_el; ++e) {
      const bool own =
          std::binary_search(domain.plan().elements.begin(), domain.plan().elements.end(), e);
      for (int a = 0; a < corners_of(e); ++a) {
        const auto k = static_cast<std::size_t>(slot_of(e, a));
        const double mass_values[2] = {share(e, 0), share(e, 1)};
        const double load_values[4] = {share(e, 2), -share(e, 3), share(e, 4),
                                       e % 3 == 2 ? 0.0 : 1.0};
        for (int c = 0; c < 2; ++c) {
          all_masses[2 * k + c] = mass_values[c];
          own_masses[2 * k + c] = own ? mass_values[c] : nan;
        }
        for (int c = 0; c < 4; ++c) {
          all_loads[4 * k + c] = load_values[c];
          own_loads[4 * k + c] = own ? load_values[c] : nan;
        }
      }
    }
    VectorX mass_serial = mass0, inertia_serial = inertia0;
    Matrix3X f_loads_serial = f_serial;
    add_corner_masses(nodes, all_masses, mass_serial, inertia_serial);
    add_flagged_corner_forces(nodes, all_loads, f_loads_serial);
    VectorX mass = mass0, inertia = inertia0;
    Matrix3X f_loads = f_serial;
    domain.add_corner_masses(nodes, own_masses, mass, inertia);
    domain.add_flagged_corner_forces(nodes, own_loads, f_loads);
    bool serial_ok = true;
    for (int i = 0; i < n_nodes; ++i) {
      serial_ok = serial_ok && same_bits(mass_serial[i], mass_want[i]) &&
                  same_bits(inertia_serial[i], inertia_want[i]);
      for (int c = 0; c < 3; ++c) {
        serial_ok = serial_ok && same_bits(f_loads_serial(c, i), f_want(c, i));
      }
    }
    check(serial_ok, "serial corner masses and flagged loads: element-order bits", rank);
    bool added_ok = true;
    for (const std::span<const int> list : {domain.owned_nodes(), domain.ghost_nodes()}) {
      for (const int i : list) {
        added_ok =
            added_ok && same_bits(mass[i], mass_want[i]) && same_bits(inertia[i], inertia_want[i]);
        for (int c = 0; c < 3; ++c) {
          added_ok = added_ok && same_bits(f_loads(c, i), f_want(c, i));
        }
      }
    }
    check(added_ok, "corner masses and flagged loads over ranks: the serial bits", rank);

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
