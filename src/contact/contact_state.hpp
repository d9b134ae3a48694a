#pragma once
// What changes during a run in the penalty contact of one tool (ContactPair holds what is fixed):
// the search's per-node caches, the per-node distance bounds and the friction's stick forces.
#include <memory>

#include "contact/contact_search.hpp"
#include "contact/node_distance_bounds.hpp"
#include "core/types.hpp"

namespace sf {

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
};

}  // namespace sf
