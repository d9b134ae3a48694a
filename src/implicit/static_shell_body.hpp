#pragma once
// The blank as an implicit static step sees it: internal forces and moments as a function of the
// displacement increment (du, dtheta) from a committed state (coordinates, stresses, plastic
// strains, thicknesses). The same element code as the explicit loop evaluates them, with the
// increment taken as one step of unit length: strain increments on the mid-increment
// configuration, stresses updated from the committed ones (docs/static-analysis.md).
#include "core/types.hpp"
#include "element/shell_forces.hpp"
#include "element/shell_part.hpp"

namespace sf {

/// Fraction of the plate bending stiffness D = E t^3 / (12 (1 - nu^2)) (N mm per rad) given to
/// the spring on each node's rotation about its averaged normal (the drilling rotation, which the
/// shell elements do not resist).
inline constexpr double kDrillingStiffnessFraction = 1e-4;

class StaticShellBody {
 public:
  /// part: the blank's elements (a viscous hourglass form is replaced by the stiffness form with
  /// the same coefficient: viscous forces have no static stiffness; the assumed strain's
  /// stabilisation unloads as it loads, StabilizationUnloading); x: committed coordinates
  /// (mm); state: committed integration-point state (a viscous run's state gets stiffness-form
  /// hourglass resultants starting at zero).
  StaticShellBody(const ShellPart& part, const Matrix3X& x, const ShellState& state);

  /// Internal forces f (N) and moments m (N mm) of the increment du (mm) and dtheta (rad) from
  /// the committed state, the drilling springs included; `trial` receives the updated state.
  /// small_strain: the strain increments on the committed configuration instead of the
  /// mid-increment one, so the stresses are linear in (du, dtheta) (a linear analysis; the forces
  /// are then those on x + du / 2). Throws InstabilityError naming the element on inversion or a
  /// non-finite value.
  ShellForceResult compute_forces(const Matrix3X& du, const Matrix3X& dtheta, Matrix3X& f,
                                  Matrix3X& m, ShellState& trial, bool small_strain = false) const;
  /// Makes x + du and `trial` the committed state (and re-averages the nodal normals).
  void commit(const Matrix3X& du, const ShellState& trial);

  const ShellPart& part() const { return part_; }
  const Matrix3X& x() const { return x_; }
  const ShellState& state() const { return state_; }
  int node_count() const { return static_cast<int>(x_.cols()); }
  /// mm, the mean element edge length at the start: the length that makes moments comparable
  /// with forces (m / length) and rotations with displacements (dtheta x length) in norms.
  double length_scale() const { return length_scale_; }
  /// N mm per rad, the drilling spring of every node.
  double drilling_stiffness() const { return drilling_stiffness_; }
  /// N/mm, E times the mean thickness at the start: the membrane stiffness scale that the
  /// stabilising springs of a static step are given as a fraction of.
  double membrane_stiffness() const { return membrane_stiffness_; }

 private:
  void update_normals();
  void centre_directors(const Matrix3X& dtheta, ShellState& trial) const;

  ShellPart part_;
  Matrix3X x_;
  ShellState state_;
  Matrix3X normal_;  ///< averaged unit normal per node at the committed coordinates
  double length_scale_ = 1.0;
  double drilling_stiffness_ = 0.0;
  double membrane_stiffness_ = 0.0;
  mutable Matrix3X x_trial_;
  NodeCorners node_corners_;  ///< the part's node-corner lists, built once
  mutable ElementPass pass_;  ///< the element passes' scratch: sized by the first call
};

}  // namespace sf
