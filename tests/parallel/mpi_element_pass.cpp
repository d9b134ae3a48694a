// The solver's element pass split over MPI ranks (issue 17, item 3): rank 0 partitions a warped,
// distorted mixed mesh of quads and triangles with METIS and broadcasts the parts; each rank runs
// the pass over its elements only (element runs), exchanges its boundary corners with its
// neighbours and sums every held node's corners in the serial order. Over three yielding steps
// of both formulations, every held node's forces and moments, every own element's state and
// critical step, and the exactly all-reduced works must equal the serial pass's, bit for bit, on
// every rank, on a part of one material and of two. Exit code 0 when they do (run by ctest at 1,
// 2 and 3 ranks).
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "element/shell_directors.hpp"
#include "element/shell_forces.hpp"
#include "parallel/corner_exchange.hpp"
#include "parallel/exact_allreduce.hpp"
#include "parallel/mesh_partition.hpp"
#include "parallel/rank_plan.hpp"
#include "support/warped_mixed_mesh.hpp"

namespace {

using namespace sf;

bool same_bits(const double* a, const double* b, std::size_t n) {
  return std::memcmp(a, b, n * sizeof(double)) == 0;
}

// The velocities of the threads test: stretching, bending and twisting, enough to yield.
void set_velocities(const Matrix3X& x0, Matrix3X& v, Matrix3X& w) {
  for (Eigen::Index i = 0; i < x0.cols(); ++i) {
    const Vec3 p = x0.col(i);
    v.col(i) = Vec3(2e3 * p.y() * 0.05, 1e3 * std::sin(p.x()), 5e2 * p.x() * p.y() * 0.01);
    w.col(i) = Vec3(10.0 * p.y(), -20.0 * p.x(), 5.0);
  }
}

// Whether this rank's distributed pass gives the serial bits for one formulation, on a part of
// one material or of two (a tailor-welded blank's, whose runs the ranks' runs cut again).
bool check_formulation(ShellFormulation formulation, bool two_materials, int rank, int ranks) {
  const test::Mesh mesh = test::make_mesh(50, 30, 7);
  const ShellPart part = two_materials ? test::two_material_part(mesh, formulation)
                                       : test::make_part(mesh, formulation);
  const int n_el = element_count(part);
  const int n_nodes = static_cast<int>(mesh.x.cols());
  const BlankTopology topology = blank_topology(part.quads, part.triangles, n_nodes);
  std::vector<int> parts(static_cast<std::size_t>(n_el));
  if (rank == 0) {
    parts = partition_elements(topology, {}, ranks, 17);
  }
  MPI_Bcast(parts.data(), n_el, MPI_INT, 0, MPI_COMM_WORLD);
  const RankPlan plan = build_rank_plan(topology, parts, rank, ranks);
  const std::vector<ElementRun> runs = element_runs(plan.elements, element_blocks(part));
  CornerExchange exchange(plan, kCornerWidth);
  std::vector<double> received(static_cast<std::size_t>(plan.receive_size) * kCornerWidth);
  std::vector<double> node_values(static_cast<std::size_t>(n_nodes) * kCornerWidth);

  ShellState serial = make_shell_state(n_el, 5, 0.8);
  initialize_directors(part, mesh.x, serial);
  ShellState mine = serial;
  Matrix3X x = mesh.x;
  Matrix3X v(3, n_nodes);
  Matrix3X w(3, n_nodes);
  set_velocities(mesh.x, v, w);
  const NodeCorners all_nodes = build_node_corners(part, n_nodes);
  ElementPass serial_pass;
  ElementPass my_pass;
  std::vector<double> serial_dt(static_cast<std::size_t>(n_el));
  std::vector<double> my_dt(static_cast<std::size_t>(n_el));
  Matrix3X f(3, n_nodes);
  Matrix3X m(3, n_nodes);
  bool ok = true;
  const double dt = 1e-6;
  for (int step = 0; step < 3; ++step) {
    x += dt * v;
    const ElementInputs in{x, v, w, dt};
    const ShellForceResult reference = run_element_pass(part, in, serial, serial_pass, serial_dt);
    gather_corner_forces(all_nodes, serial_pass.corners, f, m);
    // Only this rank's elements: the other corner slots keep what they had (never read).
    run_element_pass(part, in, mine, my_pass, my_dt, runs);
    exchange.exchange(my_pass.corners, received, MPI_COMM_WORLD);
    gather_node_values(plan, my_pass.corners, received, kCornerWidth, node_values);
    for (const int node : plan.nodes) {
      const double* got = node_values.data() + kCornerWidth * static_cast<std::size_t>(node);
      ok = ok && same_bits(got, f.col(node).data(), 3) && same_bits(got + 3, m.col(node).data(), 3);
    }
    // The pass leaves its exact sums over this rank's elements in its first share: all-reduced,
    // they round to the serial pass's works.
    ExactSum works[3] = {my_pass.shares[0].internal_work, my_pass.shares[0].plastic_work,
                         my_pass.shares[0].hourglass_work};
    allreduce_exact(works, MPI_COMM_WORLD);
    const double got[3] = {works[0].round(), works[1].round(), works[2].round()};
    const double want[3] = {reference.internal_work, reference.plastic_work,
                            reference.hourglass_work};
    ok = ok && same_bits(got, want, 3) && (step < 2 || reference.plastic_work > 0.0);
  }
  const int points = part.section.n_points;
  for (const int e : plan.elements) {
    const auto i = static_cast<std::size_t>(e);
    const auto p = i * static_cast<std::size_t>(points);
    ok = ok && same_bits(&mine.sxx[p], &serial.sxx[p], static_cast<std::size_t>(points)) &&
         same_bits(&mine.eps_p[p], &serial.eps_p[p], static_cast<std::size_t>(points)) &&
         same_bits(&mine.thickness[i], &serial.thickness[i], 1) &&
         same_bits(&my_dt[i], &serial_dt[i], 1);
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
  int ok_here = 1;
  for (const ShellFormulation f :
       {ShellFormulation::belytschko_tsay, ShellFormulation::assumed_strain}) {
    for (const bool two_materials : {false, true}) {
      ok_here = ok_here && check_formulation(f, two_materials, rank, ranks) ? 1 : 0;
    }
  }
  int ok_everywhere = 0;
  MPI_Allreduce(&ok_here, &ok_everywhere, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (rank == 0) {
    std::printf("%d ranks: the distributed element pass %s\n", ranks,
                ok_everywhere ? "gives the serial bits" : "DIFFERS from the serial pass");
  }
  MPI_Finalize();
  return ok_everywhere ? 0 : 1;
}
