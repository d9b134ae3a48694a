#pragma once
// "cached": exactly the modified search's answer (Wawrzyk & Kowalczyk; the same ClosestPoint, bit
// for bit, as "modified"), at a lower cost per node and cycle, by keeping for every blank node a
// short list of candidate triangles that is valid while the node stays near where it was built.
#include <memory>
#include <string_view>
#include <vector>

#include "contact/candidate_cache.hpp"
#include "contact/modified_search.hpp"

namespace sf {

/// "cached": the modified search with a per-node candidate list.
///
/// For blank node i the list is built at an anchor p0 (the node's position at the build) and a
/// cutoff c: every triangle T with
///     d(p0, T) <= R(m) = w(min(c, b0 + m)) + m + a,
/// where b0 is the least distance from p0 to the surface, m the margin, w the tie window
/// (detail::TieTolerance) and a its absolute part (a rounding allowance); found with the grid of
/// the modified search, stored ascending by d(p0, T) with that distance.
///
/// Why a query at p with |p - p0| = delta <= m needs nothing else: the modified search's answer
/// depends only on the triangles with d(p, T) <= w(min(c, b(p))) (the closest within the
/// cutoff and its ties), b(p) the least distance at p. By the triangle inequality
/// d(p0, T) <= d(p, T) + delta and b(p) <= b0 + delta, so each such triangle has
/// d(p0, T) <= w(min(c, b0 + m)) + m: it is in the list. The query tests the list in ascending
/// order with the modified search's kernel and bound, and stops at the first T with
/// d(p0, T) - delta > bound (+ a): since d(p, T) >= d(p0, T) - delta, that triangle and all the
/// later ones are beyond the bound, where the modified search does not take them either. The
/// distance, the tie set and therefore every field of the answer (detail::TieSet::fill) are those
/// of "modified". Within the scan, a candidate whose half-space bound
/// d(p0, T) + (p - p0) . u_T (detail::Candidate::away) exceeds the bound is not tested either:
/// it too lies beyond the bound, and the bound stays tight when the node slides sideways.
///
/// The list is rebuilt when delta exceeds the node's reach (the margin, or less, below), when the
/// cutoff grows beyond the one it was built for, or on the first query of the node.
///
/// Capacity: a list holds at most `capacity` triangles (allocated by `prepare`; queries never
/// allocate). When more lie within R(m), the nearest `capacity` are kept: every triangle nearer
/// than the nearest dropped one (distance L) is in the list, so the list is exact for the reaches
/// m' with R(m') < L; the node keeps the largest such m' as its reach (counted as a shrunk list).
/// If that reach would last fewer than min_cycles_of_reach queries at the node's recent pace
/// (its distance from the previous anchor over the queries since that build), or is not
/// positive, the list is marked overflowed instead and the node's queries use the full grid
/// search until it has moved m (a build costs a few grid searches: rebuilding at nearly every
/// query would cost more than the grid). A query whose tie set
/// exceeds ClosestPoint::max_set_size also uses the full grid (a truncated set depends on the
/// visiting order). Fallbacks are counted; every path gives the modified answer.
///
/// Margin: the default is a quarter of the mean tool edge length. A query tests the candidates
/// within about 2 delta of the closest one, and a list holds the triangles within about b0 + 2m of
/// the anchor (a disk of radius 2 sqrt(m (b0 + m)) on a flat tool), so a small margin keeps both
/// short, while a node moving s per cycle rebuilds only every m / s cycles (a build costs a few
/// grid searches). Measured on a 16k-triangle punch (bench_contact_search, docs/contact-cost.md):
/// from 0.05 to 0.5 edge the cost per node-cycle varies little at 1e-3 mm per cycle; at 2e-2 mm
/// per cycle 0.1-0.25 edge is cheapest.
///
/// The lists live in a CandidateCache (make_cache) that the caller owns; the search itself is
/// immutable. Thread safety: find_closest is thread-safe; find_closest_for_node touches only the
/// cache entry of its node (statistics included), so different nodes may be queried concurrently.
class CachedSearch final : public ContactSearch {
 public:
  static constexpr int default_capacity = 32;
  /// An overflowing list keeps a shorter reach only if it lasts at least this many queries at the
  /// node's recent pace; otherwise the node falls back to the grid.
  static constexpr double min_cycles_of_reach = 8;

  /// `surface` must outlive the search. margin (mm) <= 0 chooses the default (a quarter of the
  /// mean tool edge length); capacity >= 1 candidates per node.
  explicit CachedSearch(const TriangleSurface& surface, double margin = 0,
                        int capacity = default_capacity);

  /// The modified (grid) search's answer, without any cache.
  void find_closest(const Vec3& p, double cutoff, ClosestPoint& out) const override;
  /// The lists of `node_count` nodes (all invalid: each is built at its first query), with
  /// cleared statistics.
  std::unique_ptr<SearchCache> make_cache(int node_count) const override;
  /// The modified search's answer for node `node` at p, from its list in `cache` (made by this
  /// search). No cache (nullptr or another search's), a node outside [0, node count) or a
  /// non-finite p: answered by the full grid search.
  void find_closest_for_node(SearchCache* cache, int node, const Vec3& p, double cutoff,
                             ClosestPoint& out) const override;
  std::string_view name() const override { return "cached"; }

  double margin() const { return margin_; }
  int capacity() const { return capacity_; }
  /// The counters summed over the nodes of `cache` (made by this search; zero otherwise).
  CachedSearchStatistics statistics(const SearchCache& cache) const;
  /// Clears the counters of `cache` (made by this search).
  void reset_statistics(SearchCache& cache) const;

 private:
  /// `cache` as this search's CandidateCache, or nullptr when another search made it.
  CandidateCache* candidates(SearchCache* cache) const;
  const CandidateCache* candidates(const SearchCache* cache) const;
  /// Builds node's list at p0; `step` is the node's recent motion per query (mm, 0 if unknown).
  void rebuild(detail::NodeCandidates& cache, detail::Candidate* list, const Vec3& p0,
               double cutoff, double step) const;
  /// Sets Candidate::away of the first `count` candidates of a list built at p0.
  void set_directions(detail::Candidate* list, int count, const Vec3& p0) const;
  /// Answers a query at p from a valid list, |p - anchor| = delta <= its reach.
  void query_list(detail::NodeCandidates& cache, const detail::Candidate* list, const Vec3& p,
                  double delta, double cutoff, ClosestPoint& out) const;

  ModifiedSearch exact_;
  double margin_;
  int capacity_;
  double direction_floor_;       ///< mm: Candidate::away only beyond 1e-6 of the tool's size
  double half_space_allowance_;  ///< mm: rounding allowance of the half-space bound (1e-8 size)
};

}  // namespace sf
