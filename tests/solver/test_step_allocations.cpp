// A step of the explicit engine allocates nothing (issue 16): counted by interposing malloc,
// calloc and realloc in this test binary (below), over steps of the bundled square cup (three
// tools, contact with friction, Hill48, a force-controlled holder), after a few warm-up steps in
// which the contact caches and the output-free state settle.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "casefile/case_config.hpp"
#include "model/build_model.hpp"
#include "solver/explicit_driver.hpp"

namespace {
long g_allocations = 0;
bool g_counting = false;
}  // namespace

// Every heap allocation goes through malloc, calloc or realloc: operator new (libstdc++) and
// Eigen's dynamic matrices (its aligned malloc is plain malloc on x86-64, where malloc is
// already 16-byte aligned) alike. This binary interposes the three and counts them, passing the
// work to glibc's own entry points.
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);

void* malloc(std::size_t size) {
  g_allocations += g_counting ? 1 : 0;
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  g_allocations += g_counting ? 1 : 0;
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) {
  g_allocations += g_counting ? 1 : 0;
  return __libc_realloc(p, size);
}
}

namespace {

TEST(StepAllocations, AStepOfTheSquareCupAllocatesNothing) {
  sf::CaseConfig config =
      sf::read_case(std::filesystem::path(SF_SOURCE_DIR) / "cases/square_cup_aluminium/case.toml");
  sf::Model model = sf::build_model(config);
  sf::SolutionState s = sf::make_initial_state(model);
  sf::compute_forces(model, s, 0.0);
  double dt_previous = 0.0;
  const auto step = [&] {
    const double dt = sf::compute_time_step(model, s);
    sf::advance_one_step(model, s, dt, dt_previous);
    dt_previous = dt;
  };
  for (int i = 0; i < 200; ++i) {
    step();  // warm-up
  }
  // The counter counts (a check that it can fail): a std::vector and an Eigen matrix.
  g_allocations = 0;
  g_counting = true;
  {
    const std::vector<double> probe(16, 1.0);
    const Eigen::MatrixXd matrix = Eigen::MatrixXd::Constant(8, 8, 1.0);
    ASSERT_EQ(probe.size() + static_cast<std::size_t>(matrix.size()), 80u);
  }
  g_counting = false;
  ASSERT_EQ(g_allocations, 2);

  g_allocations = 0;
  g_counting = true;
  constexpr int steps = 200;
  for (int i = 0; i < steps; ++i) {
    step();
  }
  g_counting = false;
  std::printf("%ld allocations in %d steps (%.2f per step)\n", g_allocations, steps,
              static_cast<double>(g_allocations) / steps);
  EXPECT_EQ(g_allocations, 0);
}

}  // namespace
