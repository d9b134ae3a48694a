#pragma once
// For the fuzz targets that make a SolutionState without the element library (the checkpoint
// and formed-part readers). Include it in one file of a target.
#include <cstdlib>
#include <span>

#include "solver/solution_state.hpp"

// A SolutionState holds a serial domain, whose (inline) methods name these element functions. These
// targets never run a step, so it does not link the element library (the fuzz build would compile
// it, with the sanitizers, for nothing): these stand-ins, weak (the real ones win where linked),
// satisfy the linker and stop the process if ever called.
namespace sf {
[[gnu::weak]] StableStep smallest_time_step(std::span<const double> /*element_dt*/) {
  std::abort();
}
[[gnu::weak]] void gather_corner_forces(const NodeCorners& /*nodes*/,
                                        std::span<const double> /*corners*/, Matrix3X& /*f*/,
                                        Matrix3X& /*m*/) {
  std::abort();
}
[[gnu::weak]] void gather_half_thickness(const NodeCorners& /*nodes*/,
                                         std::span<const double> /*thickness*/,
                                         const VectorX& /*weight*/, VectorX& /*half_thickness*/) {
  std::abort();
}
[[gnu::weak]] void add_corner_masses(const NodeCorners& /*nodes*/,
                                     std::span<const double> /*corner_mass*/, VectorX& /*mass*/,
                                     VectorX& /*inertia*/) {
  std::abort();
}
[[gnu::weak]] void add_flagged_corner_forces(const NodeCorners& /*nodes*/,
                                             std::span<const double> /*corners*/, Matrix3X& /*f*/) {
  std::abort();
}
}  // namespace sf
