#include "contact/penalty_contact.hpp"

#include <fmt/core.h>
#include <omp.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string_view>

#include "contact/tool_frame.hpp"
#include "core/errors.hpp"
#include "mesh/nodal_area.hpp"

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
  if (state.normal_force.size() != n) {
    state.normal_force.setZero(n);
    state.sliding_distance.setZero(n);
  }
}

// A front bound is taken for a node found apart with a gap of at least front_min_gap cutoffs (a
// node closer would soon be searched again anyway), and for a node bounded beyond the cutoff by
// less than front_beyond cutoffs (a front bound lets it move about cutoff - h); not again within
// front_retry cutoffs of a failed attempt.
constexpr double front_min_gap = 0.05;
constexpr double front_beyond = 0.5;
constexpr double front_retry = 0.25;

// Takes node i's front bound at p, where it is out of contact with half thickness h (mm). Proof
// (docs/contact.md, "Nodes near a tool but out of contact"): at p' with delta = |p' - p|, a gap D -
// h < 0 with D > -h - cutoff needs |D| < h + cutoff, so it would come from a triangle within reach
// = h + 2 cutoff of p when delta + h <= reach - cutoff; on such a triangle D has the sign of p'
// against its plane (the nodal normals agree with the face normal), which stays positive while
// delta < least side; the orthogonal fallback's sign is that of every face normal within reach
// while the cone condition holds; and then D >= distance(p') >= distance(p) - delta >= h. Rounding
// is covered by 10 of the bound's allowances.
void bound_front(const ContactPair& pair, NodeDistanceBounds& bounds, int i, const Vec3& p,
                 double h) {
  if (!bounds.may_bound_front(i, p, front_retry * pair.cutoff)) {
    return;
  }
  const ToolDistanceBound& tool = *pair.distance_bound;
  const double reach = h + 2.0 * pair.cutoff;
  const FrontClearance front = tool.front_clearance(p, reach);
  const double allowance = 10.0 * tool.rounding_allowance(p.cwiseAbs().maxCoeff(), reach);
  const double gap = std::min(front.distance, reach - pair.cutoff) - allowance;
  double side = -1.0;
  if (front.sided) {
    // The fallback's sign: the angle b between p' - (closest point) and its triangle's normal
    // has cos b >= (least side - delta) / (nearest + delta), above the cone's sine.
    side = std::isfinite(front.nearest)
               ? (front.least_side - allowance - front.cone_sine * front.nearest) /
                     (1.0 + front.cone_sine)
               : gap;
  }
  bounds.set_front(i, p, side, gap);
}

// Bounds node i's distance to the tool afresh at p (its half thickness h, mm); whether that
// proves it out of contact. The search finds a triangle only when its computed distance is <=
// cutoff; the rounding allowance (1e-9 of the lengths involved) also covers its tie window (1e-12
// of them). A node left little slack beyond the cutoff gets a front bound too.
bool bound_node(const ContactPair& pair, NodeDistanceBounds& bounds, int i, const Vec3& p,
                double h) {
  const ToolDistanceBound& tool = *pair.distance_bound;
  const double lower = tool.lower_bound(p, distance_bound_reach_factor * pair.cutoff);
  const double allowance = tool.rounding_allowance(p.cwiseAbs().maxCoeff(), lower);
  const double slack = lower - pair.cutoff - allowance;
  bounds.set(i, p, slack);
  if (slack < front_beyond * pair.cutoff) {
    bound_front(pair, bounds, i, p, h);
  }
  return bounds.beyond_cutoff(i, p) || bounds.provably_apart(i, p, h);
}

// Whether node i at p with half thickness h is provably out of contact: no tool triangle within
// the cutoff (then the search would find none), or its front bound holds. A node that had the
// tool within the cutoff at its last query is searched without bounding it first (it most likely
// still has).
bool provably_out_of_contact(const ContactPair& pair, NodeDistanceBounds& bounds, int i,
                             const Vec3& p, double h) {
  if (bounds.beyond_cutoff(i, p) || bounds.provably_apart(i, p, h)) {
    return true;
  }
  return !bounds.was_within_cutoff(i) && bound_node(pair, bounds, i, p, h);
}

// The distance D along the normal and the unit normal of the gap of a node at p whose search
// answer is cp (a triangle within the cutoff), per pair.projection; whether an interpolated
// projection fell back to the orthogonal one.
bool gap_geometry(const ContactPair& pair, const Vec3& p, const ClosestPoint& cp, double& distance,
                  Vec3& normal) {
  distance = cp.signed_distance;
  normal = cp.normal;
  if (pair.projection == ContactProjection::interpolated) {
    InterpolatedProjection ip;
    pair.projector->project(p, cp, ip);
    distance = ip.distance;
    normal = ip.normal;
    return ip.fallback;
  }
  return false;
}

// The penalty and friction force on node i with gap g = distance - h < 0 along `normal`, into
// f_contact and result; updates the node's stick force. p: the node in the tool's mesh frame.
void add_node_force(const ContactPair& pair, ContactState& state,
                    const ContactKinematics& kinematics, bool rotating, int i, const Vec3& p,
                    double g, const Vec3& normal, ContactShare& result, Matrix3X& f_contact) {
  const double k = pair.stiffness[i];
  const double normal_force = k * (-g);
  Vec3 f = normal_force * normal;
  result.energy.add(0.5 * k * g * g);
  ++result.nodes_in_contact;
  // The node's step relative to the tool's point where it is (a translating tool's: its own).
  const Vec3 increment =
      kinematics.dt * kinematics.v.col(i) - tool_step_at(kinematics, rotating, p);
  state.normal_force[i] = normal_force;
  state.sliding_distance[i] += (increment - increment.dot(normal) * normal).norm();
  if (pair.friction.active()) {
    double pressure = 0.0;  // MPa
    if (pair.friction.needs_pressure()) {
      const double area =
          area_now(pair.start_area[i], pair.start_half_thickness[i], kinematics.half_thickness[i]);
      pressure = area > 0.0 ? normal_force / area : 0.0;
    }
    Vec3 stored = state.stick_force.col(i);
    const FrictionStep step = coulomb_friction_update(
        pair.friction, stored, normal, increment, kinematics.dt, normal_force,
        pair.friction.tangential_stiffness_ratio * k, pressure);
    state.stick_force.col(i) = stored;
    f += step.force;
    result.friction_work.add(step.work);
    ++(step.sliding ? result.sliding_nodes : result.sticking_nodes);
    if (step.beyond != 0) {
      for (int e = 0; e < kTableEnds; ++e) {
        result.beyond_table[e] += (step.beyond >> e) & 1u;
      }
    }
  }
  f_contact.col(i) += f;
  for (int c = 0; c < 3; ++c) {
    result.force_on_tool[c].add(-f[c]);
  }
  if (rotating) {
    const Vec3 moment = kinematics.x.col(i).cross(-f);
    for (int c = 0; c < 3; ++c) {
      result.moment_on_tool[c].add(moment[c]);
    }
  }
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
                         const ContactKinematics& kinematics, bool rotating, int i, const Vec3& p,
                         ContactShare& result, Matrix3X& f_contact) {
  const bool bounded = pair.distance_bound != nullptr;
  const double h = kinematics.half_thickness[i];
  if (bounded && provably_out_of_contact(pair, state.distance_bounds, i, p, h)) {
    return NodeOutcome::skipped;
  }
  ClosestPoint cp;
  pair.search->find_closest_for_node(state.search_cache.get(), i, p, pair.cutoff, cp);
  if (bounded) {
    if (cp.triangle >= 0) {
      state.distance_bounds.set_within_cutoff(i);
    } else {
      bound_node(pair, state.distance_bounds, i, p, h);  // for the next calls
    }
  }
  if (cp.triangle < 0) {
    return NodeOutcome::apart;
  }
  double distance = 0;
  Vec3 normal;
  const bool fallback = gap_geometry(pair, p, cp, distance, normal);
  const double g = distance - h;
  if (!(g < 0 && distance > -h - pair.cutoff)) {
    if (bounded && g >= front_min_gap * pair.cutoff) {
      bound_front(pair, state.distance_bounds, i, p, h);
    }
    return NodeOutcome::apart;
  }
  result.projection_fallbacks += fallback ? 1 : 0;
  if (bounded) {
    state.distance_bounds.clear_front(i);
  }
  if (rotating) {
    normal = kinematics.tool_rotation * normal;  // found in the tool's mesh frame
  }
  add_node_force(pair, state, kinematics, rotating, i, p, g, normal, result, f_contact);
  return NodeOutcome::pressed;
}

}  // namespace

void size_contact_state(const ContactPair& pair, ContactState& state, int n) {
  size_state(pair, state, n, pair.friction.active());
}

namespace {

// Blank nodes per unit of work the threads take (dynamically: contact nodes cluster).
constexpr int kContactBlock = 256;

// The nodes at list positions [begin, end) into `share` (list empty: nodes begin..end-1). The
// half thickness is checked here, where the node is read, and a failure recorded, not thrown
// (threads must not throw out of a parallel region).
void contact_block(const ContactPair& pair, ContactState& state,
                   const ContactKinematics& kinematics, std::span<const int> list, int begin,
                   int end, ContactShare& share, Matrix3X& f_contact) {
  const bool friction = pair.friction.active();
  const bool rotating = tool_turns(kinematics);
  for (int k = begin; k < end; ++k) {
    const int i = list.empty() ? k : list[static_cast<std::size_t>(k)];
    const double h = kinematics.half_thickness[i];
    if (!(pair.cutoff > h)) {
      if (i < share.thin_node) {
        share.thin_node = i;
        share.thin_half_thickness = h;
      }
      continue;
    }
    // In the tool's mesh frame, where its search, projection and distance bounds live.
    const Vec3 p = node_in_tool_frame(kinematics, rotating, i);
    // A skipped node's stick and normal forces are zero already, so they are not written (memory
    // traffic is most of a skipped node's cost): a node is skipped only while its bound is
    // positive, and a bound is set in a call where the node is out of contact -- skipped, or
    // searched and apart (its stick force reset then) -- and lost (slack -1) when a search finds
    // the tool.
    const NodeOutcome outcome =
        node_contact(pair, state, kinematics, rotating, i, p, share, f_contact);
    if (outcome == NodeOutcome::apart) {
      state.normal_force[i] = 0.0;
      if (friction) {
        state.stick_force.col(i).setZero();
      }
    }
  }
}

// The shares' sums, exactly, and their first failures.
ContactResult merge_shares(std::vector<ContactShare>& shares, int used, std::string_view tool,
                           double cutoff) {
  ContactShare& total = shares[0];
  for (int t = 1; t < used; ++t) {
    const ContactShare& share = shares[static_cast<std::size_t>(t)];
    for (int c = 0; c < 3; ++c) {
      total.force_on_tool[c].merge(share.force_on_tool[c]);
      total.moment_on_tool[c].merge(share.moment_on_tool[c]);
    }
    total.energy.merge(share.energy);
    total.friction_work.merge(share.friction_work);
    total.nodes_in_contact += share.nodes_in_contact;
    total.sliding_nodes += share.sliding_nodes;
    total.sticking_nodes += share.sticking_nodes;
    total.projection_fallbacks += share.projection_fallbacks;
    for (int e = 0; e < kTableEnds; ++e) {
      total.beyond_table[e] += share.beyond_table[e];
    }
    if (share.thin_node < total.thin_node) {
      total.thin_node = share.thin_node;
      total.thin_half_thickness = share.thin_half_thickness;
    }
    if (share.failed_node < total.failed_node) {
      total.failed_node = share.failed_node;
      total.failure = share.failure;
    }
  }
  if (total.thin_node != INT_MAX) {
    throw InputError(fmt::format(
        "contact with tool '{}': search radius {} mm does not exceed the half thickness {} mm "
        "of blank node {}",
        tool, cutoff, total.thin_half_thickness, total.thin_node));
  }
  if (total.failed_node != INT_MAX) {
    throw std::runtime_error(fmt::format("contact with tool '{}', blank nodes from {}: {}", tool,
                                         total.failed_node, total.failure));
  }
  ContactResult result;
  for (int c = 0; c < 3; ++c) {
    result.force_on_tool[c] = total.force_on_tool[c].round();
    result.moment_on_tool[c] = total.moment_on_tool[c].round();
  }
  result.energy = total.energy.round();
  result.friction_work = total.friction_work.round();
  result.nodes_in_contact = total.nodes_in_contact;
  result.sliding_nodes = total.sliding_nodes;
  result.sticking_nodes = total.sticking_nodes;
  result.projection_fallbacks = total.projection_fallbacks;
  std::copy(std::begin(total.beyond_table), std::end(total.beyond_table), result.beyond_table);
  return result;
}

}  // namespace

ContactResult compute_penalty_contact(const ContactPair& pair, ContactState& state,
                                      const ContactKinematics& kinematics, Matrix3X& f_contact) {
  const int n = static_cast<int>(kinematics.x.cols());
  const std::string_view tool_name = pair.surface ? std::string_view(pair.surface->name()) : "?";
  const bool friction = pair.friction.active();
  if (friction) {
    pair.friction.validate(tool_name);
    if (pair.friction.needs_pressure() &&
        (pair.start_area.size() != n || pair.start_half_thickness.size() != n)) {
      throw std::invalid_argument(fmt::format(
          "contact with tool '{}': a pressure-dependent friction law needs ContactPair::"
          "start_area and start_half_thickness for each of the {} blank nodes",
          tool_name, n));
    }
  }
  if (pair.projection == ContactProjection::interpolated && !pair.projector) {
    throw std::invalid_argument(fmt::format(
        "contact with tool '{}': the interpolated projection needs ContactPair::projector",
        tool_name));
  }
  size_state(pair, state, n, friction);
  // Counted nodes first (all, or the owned ones), then the ghost nodes into shares dropped after.
  const bool subset = !kinematics.owned_nodes.empty() || !kinematics.ghost_nodes.empty();
  const std::span<const int> counted = subset ? kinematics.owned_nodes : std::span<const int>();
  const std::span<const int> ghosts = subset ? kinematics.ghost_nodes : std::span<const int>();
  const int n_counted = subset ? static_cast<int>(counted.size()) : n;
  const int n_ghosts = static_cast<int>(ghosts.size());
  const int counted_blocks = (n_counted + kContactBlock - 1) / kContactBlock;
  const int blocks = counted_blocks + (n_ghosts + kContactBlock - 1) / kContactBlock;
  // A few blocks on one thread: a parallel region costs microseconds.
  const int threads = n_counted + n_ghosts >= 2 * kContactBlock ? omp_get_max_threads() : 1;
  for (std::vector<ContactShare>* shares : {&state.shares, &state.ghost_shares}) {
    if (shares->size() < static_cast<std::size_t>(threads)) {
      shares->resize(static_cast<std::size_t>(threads));
    }
  }
  int used = 1;
  // Each node writes only its own columns and cache entries; the sums are exact, so the dynamic
  // share-out of the blocks cannot change a bit of the result.
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    if (t == 0) {
      used = omp_get_num_threads();
    }
    ContactShare& share = state.shares[static_cast<std::size_t>(t)];
    ContactShare& ghost_share = state.ghost_shares[static_cast<std::size_t>(t)];
    share.reset();
    ghost_share.reset();
#pragma omp for schedule(dynamic, 1)
    for (int b = 0; b < blocks; ++b) {
      const bool is_ghost = b >= counted_blocks;
      const std::span<const int> list = is_ghost ? ghosts : counted;
      const int size = is_ghost ? n_ghosts : n_counted;
      const int begin = (is_ghost ? b - counted_blocks : b) * kContactBlock;
      ContactShare& into = is_ghost ? ghost_share : share;
      try {
        contact_block(pair, state, kinematics, list, begin, std::min(size, begin + kContactBlock),
                      into, f_contact);
      } catch (const std::exception& error) {
        const int node = list.empty() ? begin : list[static_cast<std::size_t>(begin)];
        if (node < into.failed_node) {
          into.failed_node = node;
          into.failure = error.what();
        }
      }
    }
  }
  return merge_shares(state.shares, used, tool_name, pair.cutoff);
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
  const VectorX area = nodal_tributary_area(nodes, quads, triangles);
  VectorX diagonal = VectorX::Zero(n);
  for (int e = 0; e < quads.cols(); ++e) {
    const Vec3 d1 = nodes.col(quads(2, e)) - nodes.col(quads(0, e));
    const Vec3 d2 = nodes.col(quads(3, e)) - nodes.col(quads(1, e));
    const double d = std::max(d1.norm(), d2.norm());
    for (int k = 0; k < 4; ++k) {
      diagonal[quads(k, e)] = std::max(diagonal[quads(k, e)], d);
    }
  }
  for (int e = 0; e < triangles.cols(); ++e) {
    const Vec3 x1 = nodes.col(triangles(0, e));
    const Vec3 e1 = nodes.col(triangles(1, e)) - x1;
    const Vec3 e2 = nodes.col(triangles(2, e)) - x1;
    const double d =
        std::sqrt(std::max({e1.squaredNorm(), e2.squaredNorm(), (e2 - e1).squaredNorm()}));
    for (int k = 0; k < 3; ++k) {
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
