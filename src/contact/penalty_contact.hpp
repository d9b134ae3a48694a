#pragma once
// Penalty contact of blank nodes (shell mid-surface nodes with a thickness) against a rigid tool
// surface: two-sided, with the half-thickness offset, the normal along the orthogonal or the
// interpolated projection, and regularised Coulomb friction.
#include <memory>
#include <span>

#include "contact/contact_choices.hpp"
#include "contact/contact_search.hpp"
#include "contact/contact_state.hpp"
#include "contact/coulomb_friction.hpp"
#include "contact/interpolated_projection.hpp"
#include "contact/tool_distance_bound.hpp"
#include "core/types.hpp"
#include "mesh/triangle_surface.hpp"

namespace sf {

/// One tool against all blank nodes: what is fixed for the run (ContactState holds what changes).
struct ContactPair {
  const TriangleSurface* surface = nullptr;     ///< the tool, reference configuration
  std::unique_ptr<const ContactSearch> search;  ///< a search over *surface (immutable)
  VectorX stiffness;                            ///< penalty stiffness per blank node, N/mm
  /// Search radius, mm (e.g. max half thickness + a margin). Must exceed every half thickness:
  /// a node on the positive side is in contact when its distance is below its half thickness.
  double cutoff = 0;
  /// Orthogonal by default here, for library users who want a gradient field; the case file's
  /// default is the paper's interpolated projection (build_model sets it; the driver counts the
  /// contact energy as the work of the contact forces, which holds for either: docs/contact.md).
  ContactProjection projection = ContactProjection::orthogonal;
  /// The interpolated projection over *surface: required with ContactProjection::interpolated.
  std::unique_ptr<const InterpolatedProjector> projector;
  FrictionParameters friction;  ///< frictionless unless friction.active()
  /// Per blank node: its tributary area at the start (mm^2) and its half thickness then (mm), for
  /// the contact pressure k_i (-g) / area_now (mesh/nodal_area.hpp: the area grows as the sheet
  /// thins). Needed, one per node, when friction.needs_pressure(); else may be empty.
  VectorX start_area;
  VectorX start_half_thickness;
  /// Distance bounds over *surface: when set, a node that provably cannot be within the cutoff
  /// is not searched (the same forces, bit for bit); nullptr: every node is searched every call.
  std::unique_ptr<const ToolDistanceBound> distance_bound;
};

/// How far ahead (in cutoffs) a node's distance to the tool is measured when it is bounded: a
/// node at least this far away may then move (factor - 1) cutoffs before it is looked at again.
inline constexpr double distance_bound_reach_factor = 4.0;

/// Sizes a pair's state for n blank nodes as its first call does (its search cache, distance
/// bounds and stick forces), for a pair out of play whose state must still be whole (a
/// checkpoint keeps it).
void size_contact_state(const ContactPair& pair, ContactState& state, int n);

/// What compute_penalty_contact needs of the blank and the tool for one call.
struct ContactKinematics {
  const Matrix3X& x;                 ///< blank node positions, mm
  const Matrix3X& v;                 ///< blank node velocities over the step (mid-step), mm/s
  const VectorX& half_thickness;     ///< per blank node, mm
  Vec3 tool_displacement;            ///< the tool's translation now, mm
  Vec3 tool_displacement_increment;  ///< the tool's translation over the step, mm
  double dt = 0;                     ///< the step, s (0: no relative motion, e.g. the first call)
  /// The nodes to compute and count, ascending (an MPI rank's owned nodes); empty: every node.
  std::span<const int> owned_nodes = {};
  /// Nodes whose forces are computed but whose sums and failures are left to their owner
  /// (an MPI rank's ghost nodes), ascending; used only with owned_nodes.
  std::span<const int> ghost_nodes = {};
  /// The tool's rotation now and a step ago: its mesh's point X stands at R X +
  /// tool_displacement. Identity (the default) for a tool that only translates.
  Mat3 tool_rotation = Mat3::Identity();
  Mat3 tool_rotation_previous = Mat3::Identity();
};

/// What one call of `compute_penalty_contact` did.
struct ContactResult {
  Vec3 force_on_tool = Vec3::Zero();  ///< sum of the reactions on the tool (normal + friction), N
  /// N mm, a rotating tool's (zero for a translating one): the reactions' moment about the
  /// origin, each acting at its blank node (its torque about an axis through c:
  /// (moment_on_tool - c x force_on_tool) . axis)
  Vec3 moment_on_tool = Vec3::Zero();
  int nodes_in_contact = 0;
  double energy = 0;         ///< penalty energy sum 1/2 k g^2, N mm
  double friction_work = 0;  ///< friction work dissipated in this call, N mm (>= 0)
  int sliding_nodes = 0;     ///< nodes in contact whose friction force is at the Coulomb limit
  int sticking_nodes = 0;    ///< nodes in contact below the limit (friction active)
  /// Nodes in contact whose interpolated projection fell back to the orthogonal one (nodes out of
  /// contact are not counted: the bounds may skip them).
  int projection_fallbacks = 0;
  /// Per TableEnd: the nodes whose contact pressure or slip speed lay beyond that end of the
  /// friction tables (their end value held).
  int beyond_table[kTableEnds] = {};
};

/// For every blank node i (or, with kinematics.owned_nodes / ghost_nodes, those nodes, the sums
/// over the owned ones only): queries the surface at p = R^T (x_i - tool_displacement) (the tool's
/// mesh frame; R = kinematics.tool_rotation, identity for a translating tool; normals found there
/// are turned by R)
/// within pair.cutoff (search->find_closest_for_node with the state's search cache); D = the signed
/// distance (orthogonal) or the interpolated projection's D, n the matching normal; gap g = D -
/// half_thickness[i] (mm); if g < 0 and D > -half_thickness[i] - cutoff (nodes that passed far
/// behind the surface are ignored), adds the normal force k_i (-g) n to f_contact.col(i) (N; the
/// caller zeroes f_contact) and its reaction to the tool's force. With friction active, the node's
/// relative tangential displacement over the step, dt v_i less the step of the tool's point at the
/// node ((R - R_previous) p + tool_displacement_increment; for a translating tool the increment)
/// projected
/// on the tangent plane of n, drives coulomb_friction_update with the normal force k_i (-g), k_t
/// = ratio * k_i and (for a pressure-dependent law) the pressure k_i (-g) / A_i, A_i =
/// area_now(start_area[i], start_half_thickness[i], half_thickness[i]) (mm^2; pressure 0 where
/// A_i is 0); its force is added likewise and its dissipation summed. A node out of contact has
/// its stick force reset to zero. Orthogonal: the normal force is minus the gradient of 1/2 k g^2.
/// For the results, state.normal_force[i] is set to the normal force k_i (-g) (0 out of contact)
/// and the node's relative step in the tangent plane of n is added to state.sliding_distance[i].
/// Interpolated: it is not a gradient in general (`energy` is then only the penalty spring's stored
/// energy). With pair.distance_bound, a node whose distance bound (state.distance_bounds) proves it
/// beyond the cutoff is not searched: the search would have found nothing, so the result is the
/// same. Deterministic (nodes in order); allocates only on the first call (sizing `state`). Throws
/// InputError when pair.cutoff does not exceed a node's half thickness or the friction parameters
/// are invalid, std::invalid_argument when the interpolated projection has no pair.projector or a
/// pressure-dependent friction law has no start_area / start_half_thickness per node.
ContactResult compute_penalty_contact(const ContactPair& pair, ContactState& state,
                                      const ContactKinematics& kinematics, Matrix3X& f_contact);

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

/// The cap of compute_penalty_stiffness applied to given stiffnesses (N/mm, per node, changed in
/// place): k_i <= m_i (2 dt_safety / dt_target)^2. Returns the number of nodes capped; dt_target
/// <= 0: no cap.
int cap_penalty_stiffness(VectorX& stiffness, const VectorX& nodal_mass, double dt_target,
                          double dt_safety);

}  // namespace sf
