#include "element/node_turns.hpp"

#include <cstddef>

namespace sf {

namespace {
// Below this many nodes one thread does it (a parallel region costs microseconds).
constexpr Eigen::Index kMinParallelNodes = 2048;
}  // namespace

void compute_node_turns(const Matrix3X& omega, double dt, NodeTurns& turns) {
  const Eigen::Index n = omega.cols();
  const auto size = static_cast<std::size_t>(n);
  for (std::vector<double>* v : {&turns.axis_x, &turns.axis_y, &turns.axis_z, &turns.c, &turns.s}) {
    v->resize(size);
  }
#pragma omp parallel for schedule(static) if (n >= kMinParallelNodes)
  for (Eigen::Index i = 0; i < n; ++i) {
    // dt * omega.col(i) as the element forms it from its gathered velocities (the same bits).
    const DirectorTurn t = director_turn(dt * Vec3(omega.col(i)));
    const auto k = static_cast<std::size_t>(i);
    turns.axis_x[k] = t.axis(0);
    turns.axis_y[k] = t.axis(1);
    turns.axis_z[k] = t.axis(2);
    turns.c[k] = t.c;
    turns.s[k] = t.s;
  }
}

}  // namespace sf
