#pragma once
// Gathers an element's nodal columns from, and adds its nodal forces and moments into, the
// column-major 3 x n_nodes arrays of the time loop (raw pointers, no bounds checks: the element
// loops check the array sizes once). Shared by the quad and the triangle loops.
#include <cstddef>

#include <Eigen/Core>

namespace sf {

/// q.col(i) = column nodes[i] of the 3 x n array a, for the N nodes of one element.
template <int N>
inline void gather_nodes(const double* a, const int* nodes, Eigen::Matrix<double, 3, N>& q) {
  for (int i = 0; i < N; ++i) {
    const double* c = a + 3 * static_cast<std::ptrdiff_t>(nodes[i]);
    q(0, i) = c[0];
    q(1, i) = c[1];
    q(2, i) = c[2];
  }
}

/// Adds the element's nodal forces f (N) and moments m (N mm), global components, into the
/// 3 x n arrays fd and md at the columns nodes[i].
template <int N>
inline void scatter_add_nodes(const Eigen::Matrix<double, 3, N>& f,
                              const Eigen::Matrix<double, 3, N>& m, const int* nodes, double* fd,
                              double* md) {
  for (int i = 0; i < N; ++i) {
    double* fc = fd + 3 * static_cast<std::ptrdiff_t>(nodes[i]);
    double* mc = md + 3 * static_cast<std::ptrdiff_t>(nodes[i]);
    fc[0] += f(0, i);
    fc[1] += f(1, i);
    fc[2] += f(2, i);
    mc[0] += m(0, i);
    mc[1] += m(1, i);
    mc[2] += m(2, i);
  }
}

}  // namespace sf
