#pragma once
// The membrane hourglass rates of a one-point quad (Flanagan & Belytschko 1981) with the warping
// correction, and their transpose, which turns hourglass resultants into nodal forces. Inline:
// they run once per element and cycle. See docs/element-and-material.md.
#include "core/types.hpp"
#include "element/shell_geometry.hpp"

namespace sf {

/// gamma.z (mm) of the coordinates xg (mm) on the geometry g: a warped element's nodes sit at
/// z_I = w h_I off its plane.
inline double compute_warp(const ShellGeometry& g, const Quad3& xg) {
  const Vec3 centre = 0.25 * xg.rowwise().sum();
  return g.gamma.dot(g.frame.col(2).transpose() * (xg.colwise() - centre));
}

/// Warping-corrected membrane hourglass rates (mm/s) of the frame-component velocities vl on the
/// geometry g of warp gz (compute_warp): a rigid rotation about e1, e2 moves the nodes of a
/// warped element in-plane in the hourglass pattern, and that part is removed
/// (Belytschko-Wong-Chiang 1992): q_x = gamma.v_x + gz B_x.v_z, q_y likewise.
inline Vec2 compute_membrane_hourglass_rates(const ShellGeometry& g, double gz, const Quad3& vl) {
  return Vec2(g.gamma.dot(vl.row(0)) + gz * g.b.row(0).dot(vl.row(2)),
              g.gamma.dot(vl.row(1)) + gz * g.b.row(1).dot(vl.row(2)));
}

/// Adds the forces (frame components, N) of membrane hourglass resultants q (N) on the geometry
/// g of warp gz: the transpose of compute_membrane_hourglass_rates there.
inline void add_membrane_hourglass_forces(const ShellGeometry& g, double gz, const Vec2& q,
                                          Quad3& fl) {
  fl.row(0) += q(0) * g.gamma;
  fl.row(1) += q(1) * g.gamma;
  fl.row(2) += (q(0) * gz) * g.b.row(0) + (q(1) * gz) * g.b.row(1);
}

}  // namespace sf
