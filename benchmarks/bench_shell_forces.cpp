// Benchmark of the shell internal-force pass (not a test): a flat 100 x 100 plate of 1 mm
// Belytschko-Lin-Tsay shells, t = 1 mm, 5 Gauss points, steel (E 210 GPa, nu 0.3, Swift
// K 565 MPa, eps0 0.007, n 0.26), under biaxial stretching plus bending. Prints ns per
// element-cycle of the solver's internal-force pass (run_element_pass with its scratch kept,
// then gather_corner_forces with the node lists made once) for: elastic material, J2 staying
// elastic, J2 with every point yielding, and the same two for Hill48 (r 1.79/1.51/2.27, material
// axes at 0.5 rad to e1); each with the Belytschko-Tsay formulation (viscous and stiffness
// hourglass forms) and the assumed-strain formulation.
//
// Each case: the fastest of 5 batches by the wall clock and, beside it, by the thread's CPU time
// (steadier on a shared machine).
//
// Usage: bench_shell_forces [cycles = 200]
//        [case: elastic | j2-elastic | j2-yield | hill48-elastic | hill48-yield | all]
#include <time.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include "bench_host.hpp"
#include "element/shell_directors.hpp"
#include "element/shell_forces.hpp"
#include "element/shell_part.hpp"

namespace {

using namespace sf;

constexpr int kCells = 100;       // elements per side
constexpr double kSize = 1.0;     // mm, element side
constexpr double kThick = 1.0;    // mm
constexpr double kE = 210000.0;   // MPa
constexpr double kNu = 0.3;       // -
constexpr double kRho = 7.85e-9;  // tonne/mm^3
constexpr int kRepeats = 5;       // timed batches per case; the fastest is reported

using bench::machine_name;

struct Plate {
  Matrix3X x;
  QuadConn quads;
};

Plate make_plate() {
  Plate p;
  const int n = kCells + 1;
  p.x.resize(3, n * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      p.x.col(j * n + i) = Vec3(i * kSize, j * kSize, 0.0);
    }
  }
  p.quads.resize(4, kCells * kCells);
  for (int j = 0; j < kCells; ++j) {
    for (int i = 0; i < kCells; ++i) {
      const int a = j * n + i;
      p.quads.col(j * kCells + i) << a, a + 1, a + n + 1, a + n;
    }
  }
  return p;
}

/// Biaxial stretching at `rate` (1/s) plus a spherical bending at curvature rate rate / 10
/// (1/(mm s)) about the plate centre: v = rate (x, y, -(x^2 + y^2) / 20), omega = rate / 10 (-y,
/// x).
void make_velocity(const Matrix3X& x, double rate, Matrix3X& v, Matrix3X& w) {
  const double c = 0.5 * kCells * kSize;
  v.resize(3, x.cols());
  w.resize(3, x.cols());
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    const double px = x(0, i) - c;
    const double py = x(1, i) - c;
    v.col(i) = rate * Vec3(px, py, -0.05 * (px * px + py * py));
    w.col(i) = 0.1 * rate * Vec3(-py, px, 0.0);
  }
}

struct Figures {
  double ns_per_element_cycle;      // wall clock, fastest batch
  double cpu_ns_per_element_cycle;  // this thread's CPU time, fastest batch
  double fraction_yielding;         // points whose eps_p grew in the last cycle
};

// This thread's CPU time (ns): unlike the wall clock it does not count the time slices other
// processes take on a shared machine (their cache pollution still counts).
double thread_cpu_ns() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return 1e9 * static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec);
}

// A quad formulation and, for Belytschko-Tsay, its hourglass form.
struct Variant {
  ShellFormulation formulation;
  HourglassForm form;
  const char* name;
};

Figures run_case(const Material& material, const Variant& variant, bool prestrain, int cycles) {
  const Plate plate = make_plate();
  ShellPart part;
  part.quads = plate.quads;
  part.section = make_gauss_section(5);
  part.materials[0].law = material;
  part.materials[0].density = kRho;
  part.hourglass_coefficient = 0.1;
  part.hourglass_form = variant.form;
  part.formulation = variant.formulation;
  const int n_el = static_cast<int>(part.quads.cols());
  if (std::holds_alternative<Hill48PlaneStress>(material)) {
    part.material_angle.assign(static_cast<std::size_t>(n_el), 0.5);  // rad, RD at 29 deg to e1
  }
  ShellState st = make_shell_state(n_el, 5, kThick);
  initialize_directors(part, plate.x, st);
  Matrix3X f = Matrix3X::Zero(3, plate.x.cols());
  Matrix3X m = Matrix3X::Zero(3, plate.x.cols());
  Matrix3X v;
  Matrix3X w;
  const double dt = 1.0e-7;  // s, about half the stable step of a 1 mm steel shell
  // Membrane strain per cycle 1e-5 (keeps yielding points yielding); the elastic runs use 1e-9.
  make_velocity(plate.x, (prestrain ? 1e-5 : 1e-9) / dt, v, w);
  if (prestrain) {
    // Two large steps (total membrane strain 4e-3, twice the yield strain) load every point.
    Matrix3X v_big;
    Matrix3X w_big;
    make_velocity(plate.x, 2e-3 / dt, v_big, w_big);
    for (int k = 0; k < 2; ++k) {
      compute_shell_internal_forces(part, plate.x, v_big, w_big, dt, st, f, m);
    }
  }
  // The solver's path (solver/step_forces.cpp): the pass's scratch and the nodes' corner lists
  // made once, then per cycle the element pass and the sum at the nodes.
  ElementPass pass;
  const NodeCorners nodes = build_node_corners(part, static_cast<int>(plate.x.cols()));
  const auto cycle = [&] {
    run_element_pass(part, ElementInputs{plate.x, v, w, dt}, st, pass, {});
    gather_corner_forces(nodes, pass.corners, f, m);
  };
  cycle();  // warm-up
  // The machine is shared: time kRepeats batches of `cycles` cycles and keep the fastest batch.
  std::vector<double> eps_before;
  double ns = std::numeric_limits<double>::infinity();
  double cpu_ns = std::numeric_limits<double>::infinity();
  for (int r = 0; r < kRepeats; ++r) {
    const double cpu_start = thread_cpu_ns();
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < cycles; ++k) {
      if (r == kRepeats - 1 && k == cycles - 1) {
        eps_before = st.eps_p;
      }
      cycle();
    }
    const auto stop = std::chrono::steady_clock::now();
    ns = std::min(ns, std::chrono::duration<double, std::nano>(stop - start).count());
    cpu_ns = std::min(cpu_ns, thread_cpu_ns() - cpu_start);
  }
  std::size_t yielding = 0;
  for (std::size_t i = 0; i < st.eps_p.size(); ++i) {
    yielding += st.eps_p[i] > eps_before[i] ? 1 : 0;
  }
  const double element_cycles = static_cast<double>(n_el) * cycles;
  return {ns / element_cycles, cpu_ns / element_cycles,
          static_cast<double>(yielding) / static_cast<double>(st.eps_p.size())};
}

}  // namespace

int main(int argc, char** argv) {
  const int cycles = argc > 1 ? std::max(1, std::atoi(argv[1])) : 200;
  const std::string only = argc > 2 ? argv[2] : "all";
  const ElasticPlaneStress elastic{kE, kNu};
  const J2PlaneStress steel{kE, kNu, SwiftHardening{565.0, 0.007, 0.26}};
  const Hill48PlaneStress hill{kE, kNu, 1.79, 1.51, 2.27, SwiftHardening{565.0, 0.007, 0.26}};
  std::printf(
      "bench_shell_forces: %d x %d BT shells, 5 Gauss points, best of %d batches of %d cycles\n",
      kCells, kCells, kRepeats, cycles);
  std::printf("machine: %s (1 thread)\n", machine_name().c_str());
  std::printf("%-26s %-16s %18s %14s %18s\n", "material", "formulation", "ns/element-cycle",
              "cpu ns", "points yielding");
  struct Case {
    const char* key;
    const char* name;
    Material material;
    bool prestrain;
  };
  const Case cases[] = {{"elastic", "elastic", elastic, false},
                        {"j2-elastic", "J2 Swift, elastic steps", steel, false},
                        {"j2-yield", "J2 Swift, all yielding", steel, true},
                        {"hill48-elastic", "Hill48 Swift, elastic", hill, false},
                        {"hill48-yield", "Hill48 Swift, all yielding", hill, true}};
  for (const Case& c : cases) {
    if (only != "all" && only != c.key) {
      continue;
    }
    const Variant variants[] = {
        {ShellFormulation::belytschko_tsay, HourglassForm::viscous, "BT viscous"},
        {ShellFormulation::belytschko_tsay, HourglassForm::stiffness, "BT stiffness"},
        {ShellFormulation::assumed_strain, HourglassForm::viscous, "assumed strain"}};
    for (const Variant& variant : variants) {
      const Figures fig = run_case(c.material, variant, c.prestrain, cycles);
      std::printf("%-26s %-16s %18.1f %14.1f %17.1f%%\n", c.name, variant.name,
                  fig.ns_per_element_cycle, fig.cpu_ns_per_element_cycle,
                  100.0 * fig.fraction_yielding);
    }
  }
  return 0;
}
