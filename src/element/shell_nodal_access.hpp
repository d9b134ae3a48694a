#pragma once
// Gathers an element's nodal columns from the column-major 3 x n_nodes arrays of the time loop
// (raw pointers, no bounds checks: the element pass checks the array sizes once). Shared by the
// quad and the triangle loops; their forces go to corner slots (corner_forces.hpp).
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

}  // namespace sf
