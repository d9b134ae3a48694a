#pragma once
// The tangent stiffness of a StaticShellBody by central finite differences of its internal
// forces, assembled straight into compressed columns. All nodes of one colour of a distance-2
// colouring are perturbed in one degree of freedom at once: no node's force then depends on two
// perturbed nodes, so each evaluation pair gives whole columns, and the result equals the
// assembled element-level difference matrices (docs/static-analysis.md: why differences and not
// the consistent tangent). A node with a frame of its own is perturbed along its axes and its
// forces are read as components along them (DofMap), so K = T^T K_global T.
#include "implicit/csc_matrix.hpp"
#include "implicit/dof_map.hpp"
#include "implicit/node_graph.hpp"
#include "implicit/static_shell_body.hpp"

namespace sf {

class TangentStiffness {
 public:
  /// graph: the body's node graph; dofs: its equations. Perturbations: relative_step x the
  /// body's length scale for translations (mm), relative_step for rotations (rad).
  TangentStiffness(const NodeGraph& graph, const DofMap& dofs, double length_scale,
                   double relative_step = 1e-6);

  /// K = d(f, m) / d(du, dtheta) at the increment (du, dtheta), over the free equations, into
  /// `k` (its pattern is set on the first call and kept). Throws InstabilityError when a
  /// perturbed evaluation does (an element on the verge of inversion).
  void compute(const StaticShellBody& body, const Matrix3X& du, const Matrix3X& dtheta,
               CscMatrix& k);

  int colour_count() const { return colouring_.colour_count; }
  /// Internal-force evaluations per tangent: 2 x 6 x colours.
  int evaluations_per_tangent() const { return 12 * colouring_.colour_count; }

 private:
  void make_pattern(CscMatrix& k) const;
  void perturb(int colour, int dof, double step, Matrix3X& du, Matrix3X& dtheta) const;

  const NodeGraph& graph_;
  const DofMap& dofs_;
  NodeColouring colouring_;
  double step_translation_;  ///< mm
  double step_rotation_;     ///< rad
  Matrix3X du_, dtheta_, f_plus_, m_plus_, f_minus_, m_minus_;
  ShellState trial_;
};

}  // namespace sf
