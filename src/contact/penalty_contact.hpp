#pragma once
// Penalty contact of blank nodes (shell mid-surface nodes with a thickness) against a rigid tool
// surface: two-sided, with the half-thickness offset; frictionless in this release.
#include <memory>

#include "contact/contact_search.hpp"
#include "core/types.hpp"
#include "mesh/triangle_surface.hpp"

namespace sf {

/// One tool against all blank nodes.
struct ContactPair {
  const TriangleSurface* surface = nullptr;  ///< the tool, reference configuration
  std::unique_ptr<ContactSearch> search;     ///< a search over *surface
  VectorX stiffness;                         ///< penalty stiffness per blank node, N/mm
  /// Search radius, mm (e.g. max half thickness + a margin). Must exceed every half thickness:
  /// a node on the positive side is in contact when its distance is below its half thickness.
  double cutoff = 0;
};

/// What one call of `compute_penalty_contact` did.
struct ContactResult {
  Vec3 force_on_tool = Vec3::Zero();  ///< sum of the reactions on the tool, N
  int nodes_in_contact = 0;
  double energy = 0;  ///< penalty energy sum 1/2 k g^2, N mm
};

/// For every blank node i: queries the surface at x_i - tool_displacement (reference frame) within
/// pair.cutoff; gap g = signed_distance - half_thickness[i] (mm); if g < 0 and
/// signed_distance > -half_thickness[i] - cutoff (nodes that passed far behind the surface are
/// ignored; with the search radius = cutoff this always holds for a node found), adds
/// k_i (-g) normal to f_contact.col(i) (N; the caller zeroes f_contact) and -k_i (-g) normal to
/// the tool's force. The force is minus the gradient of 1/2 k g^2 (normal = grad signed_distance).
/// Frictionless. Deterministic (nodes in order), no allocation.
/// Throws InputError when pair.cutoff does not exceed a node's half thickness.
ContactResult compute_penalty_contact(ContactPair& pair, const Matrix3X& x,
                                      const VectorX& half_thickness, const Vec3& tool_displacement,
                                      Matrix3X& f_contact);

/// Per-node penalty stiffness of a shell blank (N/mm):
///   k_i = scale * K * A_i / d_i,  K = E / (3 (1 - 2 nu)) (bulk modulus, MPa),
/// A_i the node's tributary area (a quarter of each quad's area, a third of each triangle's; mm^2)
/// and d_i the largest diagonal of the node's elements (mm; a triangle's longest edge) -- the
/// LS-DYNA shell segment stiffness (LS-DYNA Theory Manual, penalty method: k = f_si K A /
/// max shell diagonal; f_si = 0.1 by default), attached to the node.
/// Capped so that the node-on-spring oscillator (mass m_i, stiffness k_i) stays stable at
/// dt_target with the safety factor `dt_safety`: central differences are stable for
/// dt <= 2 / omega, omega = sqrt(k / m), so dt_target <= dt_safety * 2 sqrt(m / k) gives
///   k_i <= m_i (2 dt_safety / dt_target)^2.
/// The cap bounds the contact spring on its own: added to the element stiffness it raises the
/// node's frequency to sqrt(omega_el^2 + k/m), so the time-step control should include k/m (at
/// worst, with both at their limit, the step falls by 1/sqrt(2)). dt_target <= 0: no cap.
/// quads / triangles: blank connectivity (either may be empty); nodal_mass: lumped masses (t, for
/// mm-s-N-t units). Throws InputError for E <= 0, nu outside (-1, 0.5) or scale <= 0.
VectorX compute_penalty_stiffness(const Matrix3X& nodes, const QuadConn& quads,
                                  const TriConn& triangles, const VectorX& nodal_mass,
                                  double youngs_modulus, double poisson_ratio, double scale,
                                  double dt_target, double dt_safety = 0.9);

}  // namespace sf
