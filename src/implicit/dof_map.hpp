#pragma once
// Equation numbers of the blank's six degrees of freedom per node (ux, uy, uz, rx, ry, rz) in an
// implicit static step: held degrees of freedom get none. A node with a frame of its own
// (NodeFrames) has the components of its translation and rotation along its own axes as degrees
// of freedom; the others have the global components.
#include <string>
#include <vector>

#include "core/dof_names.hpp"
#include "core/types.hpp"
#include "model/node_frames.hpp"

namespace sf {

/// Equation numbering, node-major: the free degrees of freedom of node 0, then node 1, ...
class DofMap {
 public:
  DofMap() = default;
  /// held: one 6-bit mask per node (bits 0-2 translations, 3-5 rotations), as
  /// NodalConstraints::mask, in each node's axes: the frames' where given, else the global ones.
  explicit DofMap(const std::vector<unsigned char>& held, NodeFrames frames = {});

  int node_count() const { return static_cast<int>(held_.size()); }
  int equation_count() const { return equation_count_; }
  /// The equation of node `node`'s degree of freedom `dof` (0..5), or -1 when it is held.
  int equation(int node, int dof) const {
    return equation_[6 * static_cast<std::size_t>(node) + dof];
  }
  /// The node and degree of freedom of an equation.
  int node_of(int equation) const { return node_of_[static_cast<std::size_t>(equation)]; }
  int dof_of(int equation) const { return dof_of_[static_cast<std::size_t>(equation)]; }
  const std::vector<unsigned char>& held() const { return held_; }
  const NodeFrames& frames() const { return frames_; }

  /// The component of node `node`'s degree of freedom `dof` in a nodal field pair (f, m): of f
  /// for a translation, of m for a rotation, along the node's axis.
  double component(int node, int dof, const Matrix3X& f, const Matrix3X& m) const {
    const Matrix3X& field = dof < 3 ? f : m;
    if (!frames_.has(node)) {
      return field(dof % 3, node);
    }
    return frames_.axis(node, dof).dot(field.col(node));
  }
  /// Adds `value` along node `node`'s degree of freedom `dof` to the field pair (du, dtheta).
  void add(int node, int dof, double value, Matrix3X& du, Matrix3X& dtheta) const {
    Matrix3X& field = dof < 3 ? du : dtheta;
    if (!frames_.has(node)) {
      field(dof % 3, node) += value;
      return;
    }
    field.col(node) += value * frames_.axis(node, dof);
  }
  /// "uz", or "uz (node axes)" for a node with a frame of its own.
  std::string dof_name(int node, int dof) const;

 private:
  std::vector<unsigned char> held_;
  NodeFrames frames_;
  std::vector<int> equation_;  ///< 6 per node
  std::vector<int> node_of_;
  std::vector<unsigned char> dof_of_;
  int equation_count_ = 0;
};

}  // namespace sf
