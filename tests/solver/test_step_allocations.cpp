// A step of the explicit engine allocates nothing (issue 16): counted by replacing the global
// operator new in this test binary, over steps of the bundled square cup (three tools, contact
// with friction, Hill48, a force-controlled holder), after a few warm-up steps in which the
// contact caches and the output-free state settle.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <new>
#include <vector>

#include "io/case_config.hpp"
#include "model/build_model.hpp"
#include "solver/explicit_driver.hpp"

namespace {
long g_allocations = 0;
bool g_counting = false;
}  // namespace

void* operator new(std::size_t size) {
  if (g_counting) {
    ++g_allocations;
  }
  if (void* p = std::malloc(size == 0 ? 1 : size)) {
    return p;
  }
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  return operator new(size);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
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
  // The counter counts (a check that it can fail): one vector, one allocation.
  g_allocations = 0;
  g_counting = true;
  {
    const std::vector<double> probe(16, 1.0);
    ASSERT_EQ(probe.size(), 16u);
  }
  g_counting = false;
  ASSERT_EQ(g_allocations, 1);

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
