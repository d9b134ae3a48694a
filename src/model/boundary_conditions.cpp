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
    if (frames.has(static_cast<int>(i))) {
      Vec3 vi = v.col(i);
      Vec3 wi = omega.col(i);
      zero_framed_components(static_cast<int>(i), m, vi, wi);
      v.col(i) = vi;
      omega.col(i) = wi;
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

void NodalConstraints::zero_framed_components(int node, unsigned bits, Vec3& v, Vec3& omega) const {
  // Remove the component along each held local axis: v - (a . v) a (the axes are orthonormal, so
  // the components left keep their values exactly as far as rounding allows).
  const NodeFrame& f = frames.of(node);
  for (int c = 0; c < 3; ++c) {
    if (bits & (1u << c)) {
      const auto a = f.translation.col(c);
      v -= a.dot(v) * a;
    }
    if (bits & (1u << (3 + c))) {
      const auto a = f.rotation.col(c);
      omega -= a.dot(omega) * a;
    }
  }
}

std::vector<unsigned char> NodalConstraints::held_or_prescribed() const {
  std::vector<unsigned char> both = mask;
  for (std::size_t i = 0; i < prescribed.size() && i < both.size(); ++i) {
    both[i] |= prescribed[i];
  }
  return both;
}

int NodalConstraints::constrained_node_count() const {
  return static_cast<int>(
      std::count_if(mask.begin(), mask.end(), [](unsigned char m) { return m != 0; }));
}

}  // namespace sf
