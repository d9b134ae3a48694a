#pragma once
// Equation numbers of the blank's six degrees of freedom per node (ux, uy, uz, rx, ry, rz) in an
// implicit static step: held degrees of freedom get none.
#include <string>
#include <vector>

namespace sf {

/// Names of the six nodal degrees of freedom, in order.
inline constexpr const char* kDofNames[6] = {"ux", "uy", "uz", "rx", "ry", "rz"};

/// Equation numbering, node-major: the free degrees of freedom of node 0, then node 1, ...
class DofMap {
 public:
  DofMap() = default;
  /// held: one 6-bit mask per node (bits 0-2 translations, 3-5 rotations), as
  /// NodalConstraints::mask.
  explicit DofMap(const std::vector<unsigned char>& held);

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

 private:
  std::vector<unsigned char> held_;
  std::vector<int> equation_;  ///< 6 per node
  std::vector<int> node_of_;
  std::vector<unsigned char> dof_of_;
  int equation_count_ = 0;
};

}  // namespace sf
