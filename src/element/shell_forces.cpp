#include "element/shell_forces.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "core/errors.hpp"
#include "core/simd_block.hpp"
#include "element/element_block.hpp"
#include "element/shell_quad_assumed_strain.hpp"
#include "element/shell_quad_bt.hpp"
#include "element/shell_triangle.hpp"

namespace sf {

namespace {

constexpr int kMinElementsPerThread = 256;

void check_sizes(const ShellPart& part, const ElementInputs& in, const ShellState& state,
                 std::span<double> element_dt) {
  const auto n_nodes = in.x.cols();
  const auto n_el = static_cast<std::size_t>(element_count(part));
  const auto n_points = static_cast<std::size_t>(part.section.n_points);
  const bool directors = part.formulation == ShellFormulation::assumed_strain;
  if (in.v.cols() != n_nodes || in.omega.cols() != n_nodes ||
      state.n_points != part.section.n_points ||
      static_cast<std::size_t>(state.n_elements) != n_el || state.sxx.size() != n_el * n_points ||
      state.thickness.size() != n_el || state.hourglass.size() != n_el * kHourglassModes ||
      (directors && state.director.size() != n_el * 3 * kDirectorNodes) ||
      (!part.material_angle.empty() && part.material_angle.size() != n_el) ||
      (!part.element_material.empty() && part.element_material.size() != n_el) ||
      (!element_dt.empty() && element_dt.size() != n_el)) {
    throw std::invalid_argument("run_element_pass: inconsistent array sizes");
  }
}

// Share t of `count` items over `shares`, its first item rounded down to a multiple of `align`.
int share_begin(int count, int t, int shares, int align) {
  if (t >= shares) {
    return count;
  }
  const long first = static_cast<long>(count) * t / shares;
  return static_cast<int>(first - first % align);
}

// The elements at positions [first, last) of the concatenated runs, run piece by run piece, to
// `piece(begin, end)` (state indices). Stops when the share has failed.
template <class Piece>
void for_each_piece(std::span<const ElementRun> runs, int first, int last,
                    const ElementOutputs& out, const Piece& piece) {
  int offset = 0;  // position of the run's first element
  for (const ElementRun& run : runs) {
    const int length = run.end - run.begin;
    const int a = std::max(first, offset);
    const int b = std::min(last, offset + length);
    if (a < b && !out.failure.failed()) {
      piece(run.begin + (a - offset), run.begin + (b - offset));
    }
    offset += length;
  }
}

int run_length(std::span<const ElementRun> runs) {
  int n = 0;
  for (const ElementRun& run : runs) {
    n += run.end - run.begin;
  }
  return n;
}

// The runs (ascending, none across a block's border) that lie in `block`.
std::span<const ElementRun> runs_in(std::span<const ElementRun> runs, const ElementBlock& block) {
  const auto first = std::find_if(runs.begin(), runs.end(),
                                  [&](const ElementRun& r) { return r.begin >= block.first; });
  const auto last =
      std::find_if(first, runs.end(), [&](const ElementRun& r) { return r.begin >= block.end(); });
  return {first, last};
}

// The element loop of a block's shape and the part's formulation (element_loop.hpp).
using BlockRunner = void (*)(const ElementBlock&, const ShellPart&, const ShellMaterial&,
                             const ElementInputs&, ShellState&, int, int, ElementOutputs&);

BlockRunner runner_for(const ElementBlock& block, ShellFormulation formulation) {
  const bool assumed_strain = formulation == ShellFormulation::assumed_strain;
  if (block.shape == ElementShape::quad) {
    return assumed_strain ? run_assumed_strain_quads : run_bt_quads;
  }
  return assumed_strain ? run_assumed_strain_triangles : run_c0_triangles;
}

// One thread's share: its positions among each block's runs, block after block. The quads'
// shares start at a multiple of kBlockLanes (their geometry comes kBlockLanes elements at a time).
// A failure is a code the loop records; an exception reaching here is a program error, recorded
// as an internal failure, never thrown out of the parallel region.
void run_share(const ShellPart& part, const ElementInputs& in, ShellState& state,
               const ElementBlocks& blocks, std::span<const ElementRun> runs, int t, int shares,
               ElementOutputs& out) {
  int running = 0;  // the first element of the piece being run
  try {
    for (const ElementBlock& block : blocks) {
      const std::span<const ElementRun> block_runs = runs_in(runs, block);
      const int count = run_length(block_runs);
      const int align = block.shape == ElementShape::quad ? kBlockLanes : 1;
      const BlockRunner run = runner_for(block, part.formulation);
      // A piece of one material at a time (the loop takes one law).
      auto piece = [&](int e0, int e1) {
        for_each_material_run(part, e0, e1, [&](int b, int e, const ShellMaterial& m) {
          if (!out.failure.failed()) {
            running = b;
            run(block, part, m, in, state, b, e, out);
          }
        });
      };
      for_each_piece(block_runs, share_begin(count, t, shares, align),
                     share_begin(count, t + 1, shares, align), out, piece);
    }
  } catch (const std::exception& error) {
    out.fail(running, ElementFailure::Kind::internal);
    out.failure.internal_text = std::string("internal error in the element loop: ") + error.what();
  }
}

}  // namespace

std::vector<ElementRun> element_runs(std::span<const int> elements, const ElementBlocks& blocks) {
  std::vector<ElementRun> runs;
  for (const int e : elements) {
    if (!runs.empty() && runs.back().end == e && blocks.of(e).first != e) {
      runs.back().end = e + 1;  // consecutive, and not the first element of the next block
    } else {
      runs.push_back({e, e + 1});
    }
  }
  return runs;
}

ShellForceResult run_element_pass(const ShellPart& part, const ElementInputs& in, ShellState& state,
                                  ElementPass& pass, std::span<double> element_dt,
                                  std::span<const ElementRun> runs) {
  check_sizes(part, in, state, element_dt);
  // No runs: every element, one run per block (element_runs never lets one cross a border).
  const ElementBlocks blocks = element_blocks(part);
  std::array<ElementRun, 2> all{};
  for (int b = 0; b < blocks.size; ++b) {
    all[b] = {blocks.block[b].first, blocks.block[b].end()};
  }
  const std::span<const ElementRun> given =
      runs.empty() ? std::span<const ElementRun>(all.data(), blocks.size) : runs;

  const auto slots = static_cast<std::size_t>(corner_count(part)) * kCornerWidth;
  if (pass.corners.size() != slots) {
    pass.corners.assign(slots, 0.0);
  }
  // Small parts on one thread: a parallel region costs microseconds, a few hundred elements'
  // work (the results are the same bits on any number of threads).
  const int threads =
      std::max(1, std::min(omp_get_max_threads(), element_count(part) / kMinElementsPerThread));
  if (pass.shares.size() < static_cast<std::size_t>(threads)) {
    pass.shares.resize(static_cast<std::size_t>(threads));
  }
  // The directors' turn at each node, once per pass instead of once per element corner.
  ElementInputs with_turns = in;
  if (part.formulation == ShellFormulation::assumed_strain) {
    compute_node_turns(in.omega, in.dt, pass.turns);
    with_turns.turns = &pass.turns;
  }
  int used = 1;
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    const int shares = omp_get_num_threads();
    if (t == 0) {
      used = shares;
    }
    ElementOutputs& out = pass.shares[static_cast<std::size_t>(t)];
    out.reset(pass.corners.data(), element_dt.empty() ? nullptr : element_dt.data());
    run_share(part, with_turns, state, blocks, given, t, shares, out);
  }
  // Exact sums and the lowest failure: the same whatever the number of shares.
  ElementOutputs& total = pass.shares[0];
  for (int t = 1; t < used; ++t) {
    const ElementOutputs& share = pass.shares[static_cast<std::size_t>(t)];
    total.internal_work.merge(share.internal_work);
    total.plastic_work.merge(share.plastic_work);
    total.hourglass_work.merge(share.hourglass_work);
    total.failure.keep_lowest(share.failure);
  }
  if (total.failure.failed()) {
    if (total.failure.program_error()) {
      throw std::runtime_error(total.failure.message());
    }
    throw InstabilityError(total.failure.message());
  }
  return {.hourglass_work = total.hourglass_work.round(),
          .internal_work = total.internal_work.round(),
          .plastic_work = total.plastic_work.round()};
}

ShellForceResult compute_shell_internal_forces(const ShellPart& part, const Matrix3X& x,
                                               const Matrix3X& v, const Matrix3X& omega, double dt,
                                               ShellState& state, Matrix3X& f_int, Matrix3X& m_int,
                                               std::span<double> element_dt) {
  if (f_int.cols() != x.cols() || m_int.cols() != x.cols()) {
    throw std::invalid_argument("compute_shell_internal_forces: inconsistent array sizes");
  }
  ElementPass pass;
  const ShellForceResult result =
      run_element_pass(part, ElementInputs{x, v, omega, dt}, state, pass, element_dt);
  const NodeCorners nodes = build_node_corners(part, static_cast<int>(x.cols()));
  Matrix3X f(3, x.cols());
  Matrix3X m(3, x.cols());
  gather_corner_forces(nodes, pass.corners, f, m);
  f_int += f;
  m_int += m;
  return result;
}

}  // namespace sf
