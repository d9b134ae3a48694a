#pragma once
// Local axes of the blank nodes whose constraints are not along the global axes (a symmetry plane
// on a diagonal, a diaphragm on a skew end, a hold in a rotated frame). A node's six degrees of
// freedom are then the components of its translation and rotation along its own axes; nodes
// without a frame (the common case) keep the global axes and cost nothing extra.
#include <vector>

#include "core/types.hpp"

namespace sf {

/// The axes of one node: columns are the local x, y, z axes in global components (orthonormal,
/// right-handed), one set for the translations and one for the rotations (they differ only where
/// two constraints meet at a node, e.g. two symmetry planes).
struct NodeFrame {
  Mat3 translation = Mat3::Identity();
  Mat3 rotation = Mat3::Identity();
};

/// The frames of the nodes that have one.
class NodeFrames {
 public:
  NodeFrames() = default;
  /// No frames yet, for `node_count` nodes.
  explicit NodeFrames(int node_count) : index_(static_cast<std::size_t>(node_count), -1) {}

  /// Gives `node` the frame (replacing any it had).
  void set(int node, const NodeFrame& frame);
  /// Whether `node` has a frame of its own (else its axes are the global ones).
  bool has(int node) const {
    return !index_.empty() && index_[static_cast<std::size_t>(node)] >= 0;
  }
  /// The frame of a node that has one.
  const NodeFrame& of(int node) const {
    return frames_[static_cast<std::size_t>(index_[static_cast<std::size_t>(node)])];
  }
  /// The global direction (unit) of the node's degree of freedom `dof` (0..5: ux .. rz).
  Vec3 axis(int node, int dof) const;
  /// Nodes with a frame.
  int count() const { return static_cast<int>(frames_.size()); }
  /// The number of nodes this covers (0 when default-constructed: no node has a frame).
  int node_count() const { return static_cast<int>(index_.size()); }

 private:
  std::vector<int> index_;  ///< per node: into frames_, or -1
  std::vector<NodeFrame> frames_;
};

}  // namespace sf
