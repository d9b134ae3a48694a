// The element pass at 1, 2 and 3 threads (issue 17): the same bits in the corner forces, the
// element state, the critical steps and the works, on a warped and distorted mixed mesh of quads
// and triangles that yields, with both formulations; and the same failure report (the lowest
// failing element) whatever the thread count.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "element/corner_forces.hpp"
#include "element/shell_directors.hpp"
#include "element/shell_forces.hpp"
#include "support/warped_mixed_mesh.hpp"

namespace sf {
namespace {

using test::make_mesh;
using test::make_part;
using test::Mesh;

struct PassRun {
  std::vector<double> corners, element_dt, state;
  ShellForceResult works;
  std::string failure;
};

// Three steps of a stretching, bending and twisting velocity field large enough to yield; with
// `broken`, the coordinates jump to those at the second step; with `poisoned`, those elements'
// middle point gets a NaN stress before the second step.
PassRun run_passes(const ShellPart& part, const Matrix3X& x0, int threads,
                   const Matrix3X* broken = nullptr, const std::vector<int>* poisoned = nullptr) {
  const int threads_before = omp_get_max_threads();
  omp_set_num_threads(threads);
  ShellState st = make_shell_state(element_count(part), 5, 0.8);
  initialize_directors(part, x0, st);
  Matrix3X x = x0;
  Matrix3X v;
  Matrix3X w;
  test::yielding_motion(x0, v, w);
  const double dt = 1e-6;
  ElementPass pass;
  PassRun run;
  run.element_dt.assign(static_cast<std::size_t>(element_count(part)), 0.0);
  try {
    for (int step = 0; step < 3; ++step) {
      x += dt * v;
      if (broken && step == 1) {
        x = *broken;
      }
      if (poisoned && step == 1) {
        for (const int e : *poisoned) {
          st.sxx[static_cast<std::size_t>(5 * e + 2)] = std::nan("");
        }
      }
      run.works = run_element_pass(part, ElementInputs{x, v, w, dt}, st, pass, run.element_dt);
    }
  } catch (const InstabilityError& error) {
    run.failure = error.what();
  }
  omp_set_num_threads(threads_before);
  run.corners = pass.corners;
  for (const std::vector<double>* a : {&st.sxx, &st.syy, &st.sxy, &st.eps_p, &st.thickness, &st.sxz,
                                       &st.syz, &st.hourglass, &st.director}) {
    run.state.insert(run.state.end(), a->begin(), a->end());
  }
  return run;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

class ElementPassThreads : public ::testing::TestWithParam<ShellFormulation> {};

TEST_P(ElementPassThreads, SameBitsAtOneTwoAndThreeThreads) {
  // 1150 quads and 700 triangles: enough elements for every thread count to take threads.
  const Mesh mesh = make_mesh(50, 30, 7);
  const ShellPart part = make_part(mesh, GetParam());
  const PassRun one = run_passes(part, mesh.x, 1);
  ASSERT_TRUE(one.failure.empty()) << one.failure;
  ASSERT_GT(one.works.plastic_work, 0.0);  // the field yields: the return mapping is exercised
  for (int threads : {2, 3}) {
    const PassRun many = run_passes(part, mesh.x, threads);
    ASSERT_TRUE(many.failure.empty()) << many.failure;
    EXPECT_TRUE(same_bits(one.corners, many.corners)) << threads << " threads";
    EXPECT_TRUE(same_bits(one.state, many.state)) << threads << " threads";
    EXPECT_TRUE(same_bits(one.element_dt, many.element_dt)) << threads << " threads";
    EXPECT_TRUE(same_bits(one.works.internal_work, many.works.internal_work));
    EXPECT_TRUE(same_bits(one.works.plastic_work, many.works.plastic_work));
    EXPECT_TRUE(same_bits(one.works.hourglass_work, many.works.hourglass_work));
  }
}

TEST_P(ElementPassThreads, ReportsTheLowestFailingElementAtAnyThreadCount) {
  const Mesh mesh = make_mesh(50, 30, 7);
  const ShellPart part = make_part(mesh, GetParam());
  Matrix3X broken = mesh.x;
  // Collapse a quad in the last share and a triangle in the first: element 1100's nodes 2 and 3
  // onto 0 and 1, and triangle 40 (element 1190) flat onto one of its edges.
  auto collapse_quad = [&](int e) {
    broken.col(mesh.quads(3, e)) = broken.col(mesh.quads(0, e));
    broken.col(mesh.quads(2, e)) = broken.col(mesh.quads(1, e));
  };
  collapse_quad(1100);
  broken.col(mesh.triangles(2, 40)) = broken.col(mesh.triangles(1, 40));
  std::vector<std::string> reports;
  for (int threads : {1, 2, 3}) {
    reports.push_back(run_passes(part, mesh.x, threads, &broken).failure);
  }
  // The lowest failing element is the collapsed quad or one of its neighbours (they share its
  // moved nodes), the same one at every count, and it is a quad (below the triangles' 1150).
  ASSERT_FALSE(reports[0].empty());
  std::printf("reported: %s\n", reports[0].c_str());
  EXPECT_EQ(reports[0].rfind("shell element ", 0), 0u) << reports[0];
  EXPECT_LT(std::stoi(reports[0].substr(14)), 1150) << reports[0];
  EXPECT_EQ(reports[1], reports[0]);
  EXPECT_EQ(reports[2], reports[0]);
}

// A material update that fails (a point's stress made NaN: the J2 return meets a non-finite
// trial stress) is a code the element loop records, not an exception: the pass reports the
// lowest such element with the law's message, at every thread count; a triangle is named with
// its index among the triangles too.
TEST_P(ElementPassThreads, ReportsAMaterialFailureOfTheLowestElementAtAnyThreadCount) {
  const Mesh mesh = make_mesh(50, 30, 7);  // 1150 quads, then 700 triangles
  const ShellPart part = make_part(mesh, GetParam());
  const std::vector<int> quad_and_triangle = {1700, 600};
  const std::vector<int> triangle = {1700};
  const std::string law = "J2 plane stress: non-finite trial stress";
  for (int threads : {1, 2, 3}) {
    EXPECT_EQ(run_passes(part, mesh.x, threads, nullptr, &quad_and_triangle).failure,
              "shell element 600: " + law)
        << threads << " threads";
    EXPECT_EQ(run_passes(part, mesh.x, threads, nullptr, &triangle).failure,
              "shell element 1700 (triangle 550): " + law)
        << threads << " threads";
  }
}

// A part of two materials (a tailor-welded blank's), their runs cut at odd places (not at the
// SIMD blocks' boundaries): each element gets the bits it gets in a part wholly of its material,
// at every thread count.
TEST_P(ElementPassThreads, EachElementOfTwoMaterialsAsInAPartOfItsOwn) {
  const Mesh mesh = make_mesh(50, 30, 7);
  const ShellPart base = make_part(mesh, GetParam());
  const int n = element_count(base);
  const ElementBlocks blocks = element_blocks(base);
  std::vector<int> which;
  const ShellPart mixed = test::two_material_part(mesh, GetParam(), &which);
  ShellPart all_second = base;
  all_second.materials = {test::second_material()};
  const PassRun alone[2] = {run_passes(base, mesh.x, 1), run_passes(all_second, mesh.x, 1)};
  // An element's corner slots (its forces and moments before they are summed at the nodes).
  const auto corners_of = [&blocks](const std::vector<double>& corners, int e) {
    const int first = blocks.of(e).corner_slot(e, 0);
    const int count = blocks.of(e).nodes_per_element();
    return std::vector<double>(corners.begin() + static_cast<long>(kCornerWidth) * first,
                               corners.begin() + static_cast<long>(kCornerWidth) * (first + count));
  };
  for (int threads : {1, 2, 3}) {
    const PassRun run = run_passes(mixed, mesh.x, threads);
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    int differing = 0;
    for (int e = 0; e < n; ++e) {
      const PassRun& own = alone[which[static_cast<std::size_t>(e)]];
      differing += !same_bits(corners_of(run.corners, e), corners_of(own.corners, e)) ||
                   run.element_dt[static_cast<std::size_t>(e)] !=
                       own.element_dt[static_cast<std::size_t>(e)];
    }
    EXPECT_EQ(differing, 0) << threads << " threads";
  }
}

INSTANTIATE_TEST_SUITE_P(Formulations, ElementPassThreads,
                         ::testing::Values(ShellFormulation::belytschko_tsay,
                                           ShellFormulation::assumed_strain));

}  // namespace
}  // namespace sf
