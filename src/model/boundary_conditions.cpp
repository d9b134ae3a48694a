#include "model/boundary_conditions.hpp"

#include <algorithm>

namespace sf {

void NodalConstraints::add_symmetry(int node, int axis) {
  // Mirror symmetry about the plane normal to `axis`: no normal translation and no rotation about
  // the two in-plane axes (those would tilt the mid-surface out of the mirror).
  mask[static_cast<std::size_t>(node)] |= static_cast<unsigned char>(1u << axis);
  for (int r = 0; r < 3; ++r) {
    if (r != axis) {
      mask[static_cast<std::size_t>(node)] |= static_cast<unsigned char>(1u << (3 + r));
    }
  }
}

void NodalConstraints::add_fixed(int node) {
  mask[static_cast<std::size_t>(node)] = 0x3f;
}

void NodalConstraints::apply(Matrix3X& v, Matrix3X& omega) const {
  const Eigen::Index n = v.cols();
  for (Eigen::Index i = 0; i < n; ++i) {
    const unsigned m = mask[static_cast<std::size_t>(i)];
    if (m == 0) {
      continue;
    }
    for (int c = 0; c < 3; ++c) {
      if (m & (1u << c)) {
        v(c, i) = 0.0;
      }
      if (m & (1u << (3 + c))) {
        omega(c, i) = 0.0;
      }
    }
  }
}

int NodalConstraints::constrained_node_count() const {
  return static_cast<int>(
      std::count_if(mask.begin(), mask.end(), [](unsigned char m) { return m != 0; }));
}

}  // namespace sf
