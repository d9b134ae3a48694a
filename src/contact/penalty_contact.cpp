#include "contact/penalty_contact.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include "core/errors.hpp"

namespace sf {

namespace {

// Sizes the state for n nodes and the pair's search (the only allocations: on the first call).
void size_state(const ContactPair& pair, ContactState& state, int n, bool friction) {
  if (state.node_count != n || state.search != pair.search.get()) {
    state.search_cache = pair.search->make_cache(n);
    state.search = pair.search.get();
    state.node_count = n;
  }
  if (pair.distance_bound && state.distance_bounds.node_count() != n) {
    state.distance_bounds.resize(n);
  }
  if (friction && state.stick_force.cols() != n) {
    state.stick_force.setZero(3, n);
  }
}

// Bounds node i's distance to the tool afresh at p; whether that proves it beyond the cutoff.
// The search finds a triangle only when its computed distance is <= cutoff; the rounding
// allowance (1e-9 of the lengths involved) also covers its tie window (1e-12 of them).
bool bound_node(const ContactPair& pair, NodeDistanceBounds& bounds, int i, const Vec3& p) {
  const ToolDistanceBound& tool = *pair.distance_bound;
  const double lower = tool.lower_bound(p, distance_bound_reach_factor * pair.cutoff);
  const double allowance = tool.rounding_allowance(p.cwiseAbs().maxCoeff(), lower);
  bounds.set(i, p, lower - pair.cutoff - allowance);
  return bounds.beyond_cutoff(i, p);
}

// Whether node i at p provably has no tool triangle within the cutoff (then the search would
// find none and the node exerts no force). A node that had the tool within the cutoff at its
// last query is searched without bounding it first (it most likely still has).
bool provably_beyond_cutoff(const ContactPair& pair, NodeDistanceBounds& bounds, int i,
                            const Vec3& p) {
  if (bounds.beyond_cutoff(i, p)) {
    return true;
  }
  return !bounds.was_within_cutoff(i) && bound_node(pair, bounds, i, p);
}

// The distance D along the normal and the unit normal of the gap of a node at p whose search
// answer is cp (a triangle within the cutoff), per pair.projection.
void gap_geometry(const ContactPair& pair, const Vec3& p, const ClosestPoint& cp,
                  ContactResult& result, double& distance, Vec3& normal) {
  distance = cp.signed_distance;
  normal = cp.normal;
  if (pair.projection == ContactProjection::interpolated) {
    InterpolatedProjection ip;
    pair.projector->project(p, cp, ip);
    result.projection_fallbacks += ip.fallback ? 1 : 0;
    distance = ip.distance;
    normal = ip.normal;
  }
}

// The penalty and friction force on node i with gap g = distance - h < 0 along `normal`, into
// f_contact and result; updates the node's stick force.
void add_node_force(const ContactPair& pair, ContactState& state,
                    const ContactKinematics& kinematics, int i, double g, const Vec3& normal,
                    ContactResult& result, Matrix3X& f_contact) {
  const double k = pair.stiffness[i];
  const double normal_force = k * (-g);
  Vec3 f = normal_force * normal;
  result.energy += 0.5 * k * g * g;
  ++result.nodes_in_contact;
  if (pair.friction.active()) {
    const Vec3 increment =
        kinematics.dt * kinematics.v.col(i) - kinematics.tool_displacement_increment;
    Vec3 stored = state.stick_force.col(i);
    const FrictionStep step =
        coulomb_friction_update(pair.friction, stored, normal, increment, kinematics.dt,
                                normal_force, pair.friction.tangential_stiffness_ratio * k);
    state.stick_force.col(i) = stored;
    f += step.force;
    result.friction_work += step.work;
    ++(step.sliding ? result.sliding_nodes : result.sticking_nodes);
  }
  f_contact.col(i) += f;
  result.force_on_tool -= f;
}

// What happened to a node in one call.
enum class NodeOutcome {
  skipped,  ///< its distance bound proved it beyond the cutoff: not searched
  apart,    ///< searched, not in contact
  pressed,  ///< in contact: a force was added
};

// The contact of node i at p: searched (or skipped when its distance bound allows), then the
// force if it penetrates.
NodeOutcome node_contact(const ContactPair& pair, ContactState& state,
                         const ContactKinematics& kinematics, int i, const Vec3& p,
                         ContactResult& result, Matrix3X& f_contact) {
  const bool bounded = pair.distance_bound != nullptr;
  if (bounded && provably_beyond_cutoff(pair, state.distance_bounds, i, p)) {
    return NodeOutcome::skipped;
  }
  ClosestPoint cp;
  pair.search->find_closest_for_node(state.search_cache.get(), i, p, pair.cutoff, cp);
  if (bounded) {
    if (cp.triangle >= 0) {
      state.distance_bounds.set_within_cutoff(i);
    } else {
      bound_node(pair, state.distance_bounds, i, p);  // for the next calls
    }
  }
  if (cp.triangle < 0) {
    return NodeOutcome::apart;
  }
  double distance = 0;
  Vec3 normal;
  gap_geometry(pair, p, cp, result, distance, normal);
  const double h = kinematics.half_thickness[i];
  const double g = distance - h;
  if (!(g < 0 && distance > -h - pair.cutoff)) {
    return NodeOutcome::apart;
  }
  add_node_force(pair, state, kinematics, i, g, normal, result, f_contact);
  return NodeOutcome::pressed;
}

}  // namespace

ContactResult compute_penalty_contact(const ContactPair& pair, ContactState& state,
                                      const ContactKinematics& kinematics, Matrix3X& f_contact) {
  ContactResult result;
  const Matrix3X& x = kinematics.x;
  const int n = static_cast<int>(x.cols());
  const std::string_view tool_name = pair.surface ? std::string_view(pair.surface->name()) : "?";
  const bool friction = pair.friction.active();
  if (friction) {
    pair.friction.validate(tool_name);
  }
  if (pair.projection == ContactProjection::interpolated && !pair.projector) {
    throw std::invalid_argument(fmt::format(
        "contact with tool '{}': the interpolated projection needs ContactPair::projector",
        tool_name));
  }
  size_state(pair, state, n, friction);
  for (int i = 0; i < n; ++i) {
    const double h = kinematics.half_thickness[i];
    if (!(pair.cutoff > h)) {
      throw InputError(fmt::format(
          "contact with tool '{}': search radius {} mm does not exceed the half thickness {} mm "
          "of blank node {}",
          tool_name, pair.cutoff, h, i));
    }
    const Vec3 p = x.col(i) - kinematics.tool_displacement;
    // A skipped node's stick force is zero already, so it is not written (memory traffic is
    // most of a skipped node's cost): a node is skipped only while its bound is positive, and a
    // bound is set in a call where the node is out of contact -- skipped, or searched and apart
    // (its stick force reset then) -- and lost (slack -1) when a search finds the tool.
    const NodeOutcome outcome = node_contact(pair, state, kinematics, i, p, result, f_contact);
    if (friction && outcome == NodeOutcome::apart) {
      state.stick_force.col(i).setZero();
    }
  }
  return result;
}

VectorX compute_penalty_stiffness(const Matrix3X& nodes, const QuadConn& quads,
                                  const TriConn& triangles, const VectorX& nodal_mass,
                                  double youngs_modulus, double poisson_ratio, double scale,
                                  double dt_target, double dt_safety) {
  if (!(youngs_modulus > 0) || !(poisson_ratio > -1 && poisson_ratio < 0.5)) {
    throw InputError(
        fmt::format("contact penalty: need E > 0 and -1 < nu < 0.5 (got E = {} MPa, nu = {})",
                    youngs_modulus, poisson_ratio));
  }
  if (!(scale > 0)) {
    throw InputError(fmt::format("contact penalty: scale must be > 0 (got {})", scale));
  }
  const int n = static_cast<int>(nodes.cols());
  const double bulk = youngs_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio));
  VectorX area = VectorX::Zero(n);
  VectorX diagonal = VectorX::Zero(n);
  for (int e = 0; e < quads.cols(); ++e) {
    const Vec3 d1 = nodes.col(quads(2, e)) - nodes.col(quads(0, e));
    const Vec3 d2 = nodes.col(quads(3, e)) - nodes.col(quads(1, e));
    const double a = 0.5 * d1.cross(d2).norm();  // exact for a flat quad
    const double d = std::max(d1.norm(), d2.norm());
    for (int k = 0; k < 4; ++k) {
      area[quads(k, e)] += 0.25 * a;
      diagonal[quads(k, e)] = std::max(diagonal[quads(k, e)], d);
    }
  }
  for (int e = 0; e < triangles.cols(); ++e) {
    const Vec3 x1 = nodes.col(triangles(0, e));
    const Vec3 e1 = nodes.col(triangles(1, e)) - x1;
    const Vec3 e2 = nodes.col(triangles(2, e)) - x1;
    const double a = 0.5 * e1.cross(e2).norm();
    const double d =
        std::sqrt(std::max({e1.squaredNorm(), e2.squaredNorm(), (e2 - e1).squaredNorm()}));
    for (int k = 0; k < 3; ++k) {
      area[triangles(k, e)] += a / 3.0;
      diagonal[triangles(k, e)] = std::max(diagonal[triangles(k, e)], d);
    }
  }
  VectorX k = VectorX::Zero(n);
  for (int i = 0; i < n; ++i) {
    if (diagonal[i] > 0) {
      k[i] = scale * bulk * area[i] / diagonal[i];
    }
  }
  cap_penalty_stiffness(k, nodal_mass, dt_target, dt_safety);
  return k;
}

int cap_penalty_stiffness(VectorX& stiffness, const VectorX& nodal_mass, double dt_target,
                          double dt_safety) {
  if (!(dt_target > 0)) {
    return 0;
  }
  const double omega_max = 2.0 * dt_safety / dt_target;
  int capped = 0;
  for (Eigen::Index i = 0; i < stiffness.size(); ++i) {
    const double limit = nodal_mass[i] * omega_max * omega_max;
    if (stiffness[i] > limit) {
      stiffness[i] = limit;
      ++capped;
    }
  }
  return capped;
}

}  // namespace sf
