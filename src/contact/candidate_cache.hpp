#pragma once
// The per-node state of the cached search ("cached"): each blank node's list of candidate
// triangles, where and for which cutoff it was built, and the node's counters. Kept by the caller
// (ContactState) so that the search itself stays immutable; made by CachedSearch::make_cache.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "contact/contact_search.hpp"
#include "core/types.hpp"

namespace sf {

/// Counts of what the cached search did (summed over the nodes).
struct CachedSearchStatistics {
  long queries = 0;             ///< find_closest_for_node calls
  long rebuilds = 0;            ///< candidate lists built (the first one of each node included)
  long shrunk_lists = 0;        ///< builds that overflowed the capacity and kept a shorter reach
  long overflow_fallbacks = 0;  ///< queries answered by the full grid: the list had overflowed
  long tie_fallbacks = 0;       ///< queries answered by the full grid: more ties than max_set_size
  long candidates_tested = 0;   ///< point-triangle tests in queries answered from the lists
  long rebuild_tests = 0;       ///< point-triangle tests while building the lists
  long fallbacks() const { return overflow_fallbacks + tie_fallbacks; }
};

namespace detail {

/// A candidate triangle of a node's list.
struct Candidate {
  double distance;  ///< d(anchor, triangle), mm
  int triangle;
  /// The unit vector from the triangle's point closest to the anchor to the anchor (zero when the
  /// anchor lies on the triangle). The triangle lies in the half-space behind that point, so
  /// d(p, triangle) >= distance + (p - anchor) . away for every p: a bound that a sideways or
  /// receding motion does not loosen, unlike distance - |p - anchor|.
  Vec3 away = Vec3::Zero();
};

/// One node's list header (its triangles are in CandidateCache::list).
struct NodeCandidates {
  Vec3 anchor = Vec3::Zero();  ///< where the list was built, mm
  double cutoff = 0;           ///< the cutoff it was built for, mm
  double reach = 0;            ///< the list serves |p - anchor| <= reach (<= margin), mm
  long built_at = 0;           ///< stats.queries at the last build
  int count = 0;               ///< candidates in the list
  bool valid = false;
  bool overflow = false;
  CachedSearchStatistics stats;
};

}  // namespace detail

/// The candidate lists of every blank node: fixed capacity, allocated once.
class CandidateCache final : public SearchCache {
 public:
  /// `node_count` nodes, every list empty and invalid (built at the node's first query).
  CandidateCache(const ContactSearch& owner, int node_count, int capacity)
      : SearchCache(owner),
        nodes_(static_cast<std::size_t>(std::max(node_count, 0))),
        candidates_(nodes_.size() * static_cast<std::size_t>(capacity), detail::Candidate{0.0, -1}),
        capacity_(capacity) {}

  int node_count() const { return static_cast<int>(nodes_.size()); }
  int capacity() const { return capacity_; }
  detail::NodeCandidates& node(int i) { return nodes_[static_cast<std::size_t>(i)]; }
  /// Node i's list: `capacity` slots.
  detail::Candidate* list(int i) {
    return candidates_.data() + static_cast<std::size_t>(i) * capacity_;
  }

  /// Sums the per-node counters.
  CachedSearchStatistics statistics() const {
    CachedSearchStatistics sum;
    for (const detail::NodeCandidates& c : nodes_) {
      sum.queries += c.stats.queries;
      sum.rebuilds += c.stats.rebuilds;
      sum.overflow_fallbacks += c.stats.overflow_fallbacks;
      sum.tie_fallbacks += c.stats.tie_fallbacks;
      sum.shrunk_lists += c.stats.shrunk_lists;
      sum.candidates_tested += c.stats.candidates_tested;
      sum.rebuild_tests += c.stats.rebuild_tests;
    }
    return sum;
  }
  void reset_statistics() {
    for (detail::NodeCandidates& c : nodes_) {
      c.stats = CachedSearchStatistics{};
    }
  }

 private:
  std::vector<detail::NodeCandidates> nodes_;
  std::vector<detail::Candidate> candidates_;  ///< node i's list: [i capacity, (i + 1) capacity)
  int capacity_;
};

}  // namespace sf
