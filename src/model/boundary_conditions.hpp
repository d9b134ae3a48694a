#pragma once
// Kinematic constraints on blank nodes: which translational and rotational velocity components are
// held at zero.
#include <vector>

#include "core/types.hpp"

namespace sf {

/// Per node, a 6-bit mask: bits 0-2 hold translations x, y, z; bits 3-5 hold rotations x, y, z.
struct NodalConstraints {
  std::vector<unsigned char> mask;  ///< one per node

  /// Hold the node's translation along `axis` and its rotations about the two other axes (a
  /// symmetry plane whose normal is `axis`).
  void add_symmetry(int node, int axis);
  /// Hold all six components.
  void add_fixed(int node);
  /// Zero the held components of translational (v) and angular (omega) velocities.
  void apply(Matrix3X& v, Matrix3X& omega) const;
  /// The number of nodes with at least one held component.
  int constrained_node_count() const;
};

}  // namespace sf
