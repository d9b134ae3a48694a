#pragma once
// Kinematic constraints on blank nodes: which of a node's six degrees of freedom (translations
// ux, uy, uz and rotations rx, ry, rz) are held at zero and which a prescribed motion drives, in
// the global axes or, for the nodes that have one, in the node's own frame (NodeFrames).
#include <vector>

#include "core/types.hpp"
#include "model/node_frames.hpp"

namespace sf {

/// Per node, 6-bit masks: bits 0-2 the translations along the node's x, y, z axes, bits 3-5 the
/// rotations about them. The axes are the global ones, or the node's frame where it has one.
struct NodalConstraints {
  std::vector<unsigned char> mask;        ///< held at zero; one per node
  std::vector<unsigned char> prescribed;  ///< driven by a prescribed motion; one per node
  NodeFrames frames;                      ///< the nodes whose masks refer to their own axes

  /// Hold the node's translation along the global `axis` and its rotations about the two other
  /// axes (a symmetry plane whose normal is `axis`). For nodes without a frame.
  void add_symmetry(int node, int axis);
  /// Hold all six components.
  void add_fixed(int node);
  /// Zero the held components of translational (v) and angular (omega) velocities. Nodes without
  /// a frame take the global path (no rotation).
  void apply(Matrix3X& v, Matrix3X& omega) const;
  /// Zero the components `bits` (in the node's axes) of one node's v and omega.
  void zero_components(int node, unsigned bits, Vec3& v, Vec3& omega) const {
    if (!frames.has(node)) {
      for (int c = 0; c < 3; ++c) {
        if (bits & (1u << c)) {
          v[c] = 0.0;
        }
        if (bits & (1u << (3 + c))) {
          omega[c] = 0.0;
        }
      }
      return;
    }
    zero_framed_components(node, bits, v, omega);
  }
  /// One node's held and prescribed bits together (prescribed may be empty: none).
  unsigned constrained_bits(std::size_t node) const {
    return static_cast<unsigned>(mask[node]) | (prescribed.empty() ? 0u : prescribed[node]);
  }
  /// Per node, the held and the prescribed bits together: the degrees of freedom an implicit
  /// step does not solve for.
  std::vector<unsigned char> held_or_prescribed() const;
  /// The number of nodes with at least one held component.
  int constrained_node_count() const;

 private:
  void zero_framed_components(int node, unsigned bits, Vec3& v, Vec3& omega) const;
};

}  // namespace sf
