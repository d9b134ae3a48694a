#pragma once
// What changes during a run in the penalty contact of one tool (ContactPair holds what is fixed):
// the search's per-node caches, the per-node distance bounds and the friction's stick forces.
#include <climits>
#include <memory>
#include <string>
#include <vector>

#include "contact/contact_search.hpp"
#include "contact/coulomb_friction.hpp"
#include "contact/node_distance_bounds.hpp"
#include "core/exact_sum.hpp"
#include "core/types.hpp"

namespace sf {

/// What one thread's share of the blank nodes sums in a contact call: exactly (the tool's reaction
/// and the energies), so that the totals do not depend on how the nodes were shared out.
struct alignas(64) ContactShare {
  ExactSum force_on_tool[3];   ///< N, components of the reaction on the tool
  ExactSum moment_on_tool[3];  ///< N mm, its moment about the origin
  ExactSum energy;             ///< N mm, penalty spring energy
  ExactSum friction_work;      ///< N mm
  int nodes_in_contact = 0;
  int sliding_nodes = 0;
  int sticking_nodes = 0;
  int projection_fallbacks = 0;
  int beyond_table[kTableEnds] = {};  ///< nodes beyond each end of the friction tables
  int thin_node = INT_MAX;            ///< the lowest node whose half thickness reaches the cutoff
  double thin_half_thickness = 0.0;
  int failed_node = INT_MAX;  ///< the lowest node of a block whose computation threw
  std::string failure;        ///< what it threw

  void reset() { *this = ContactShare(); }
  int first_failing_node() const { return thin_node < failed_node ? thin_node : failed_node; }
};

/// The state of one ContactPair over a run. Sized by compute_penalty_contact on its first call
/// (or when the node count changes), never reallocated afterwards.
struct ContactState {
  int node_count = -1;                        ///< the blank nodes it is sized for (-1: not yet)
  std::unique_ptr<SearchCache> search_cache;  ///< the search's (nullptr: it keeps none)
  const ContactSearch* search = nullptr;      ///< the search that made search_cache
  NodeDistanceBounds distance_bounds;         ///< used when the pair has a distance bound
  /// Per blank node: the stored elastic stick force on the node, N (zero out of contact; sized
  /// only with friction).
  Matrix3X stick_force;
  /// Per blank node: the normal contact force of the last call, N (zero out of contact), and
  /// the path it has slid over the tool while in contact, mm (its steps relative to the tool's
  /// point at it, in the tangent plane, summed since time 0): results, not forces.
  VectorX normal_force;
  VectorX sliding_distance;
  /// Per TableEnd: whether the run has warned of a node beyond that end of the friction tables
  /// (once a run; not checkpointed: a restarted run may say it again).
  bool warned_beyond_table[kTableEnds] = {};
  std::vector<ContactShare> shares;  ///< one per thread (scratch)
  /// One per thread: the sums of the ghost nodes (ContactKinematics::ghost_nodes), computed for
  /// their forces and then dropped, their owner counting them (scratch).
  std::vector<ContactShare> ghost_shares;
};

}  // namespace sf
