#include "contact/cached_search.hpp"

#include <fmt/core.h>

#include <cmath>
#include <limits>

#include "core/errors.hpp"

namespace sf {

namespace {

double mean_edge_length(const TriangleSurface& surface) {
  const Matrix3X& x = surface.nodes();
  const TriConn& tri = surface.triangles();
  double sum = 0;
  for (int t = 0; t < surface.num_triangles(); ++t) {
    for (int a = 0; a < 3; ++a) {
      sum += (x.col(tri((a + 1) % 3, t)) - x.col(tri(a, t))).norm();
    }
  }
  return surface.num_triangles() > 0 ? sum / (3.0 * surface.num_triangles()) : 1.0;
}

}  // namespace

CachedSearch::CachedSearch(const TriangleSurface& surface, double margin, int capacity)
    : exact_(surface),
      margin_(margin > 0 ? margin : 0.25 * mean_edge_length(surface)),
      capacity_(capacity),
      // The tie tolerance's absolute part is 1e-12 of the tool's size.
      direction_floor_(1e6 * exact_.tolerance().absolute),
      half_space_allowance_(1e4 * exact_.tolerance().absolute) {
  if (capacity < 1 || !std::isfinite(margin_)) {
    throw InputError(
        fmt::format("tool '{}': cached contact search needs a capacity >= 1 and a finite margin "
                    "(got capacity {}, margin {} mm)",
                    surface.name(), capacity, margin));
  }
}

void CachedSearch::find_closest(const Vec3& p, double cutoff, ClosestPoint& out) const {
  exact_.find_closest(p, cutoff, out);
}

std::unique_ptr<SearchCache> CachedSearch::make_cache(int node_count) const {
  return std::make_unique<CandidateCache>(*this, node_count, capacity_);
}

CandidateCache* CachedSearch::candidates(SearchCache* cache) const {
  return const_cast<CandidateCache*>(candidates(static_cast<const SearchCache*>(cache)));
}

const CandidateCache* CachedSearch::candidates(const SearchCache* cache) const {
  // Only this search makes caches owned by it, and they are CandidateCaches (the capacity check
  // guards against a cache outliving its search and meeting another at the same address).
  if (!cache || cache->owner() != this) {
    return nullptr;
  }
  const auto* lists = static_cast<const CandidateCache*>(cache);
  return lists->capacity() == capacity_ ? lists : nullptr;
}

void CachedSearch::set_directions(detail::Candidate* list, int count, const Vec3& p0) const {
  const std::vector<detail::TriangleProjector>& projectors = exact_.projectors();
  for (int k = 0; k < count; ++k) {
    Vec3 point, barycentric;
    detail::project(projectors[static_cast<std::size_t>(list[k].triangle)], p0, point, barycentric);
    // Below a millionth of the tool's size the direction would carry the point's rounding
    // (~1e-16 of the size) magnified; zero keeps the bound d(p0, T) + 0 valid (if useless).
    const Vec3 away = p0 - point;
    const double length = away.norm();
    list[k].away = length > direction_floor_ ? Vec3(away / length) : Vec3::Zero();
  }
}

void CachedSearch::rebuild(detail::NodeCandidates& cache, detail::Candidate* list, const Vec3& p0,
                           double cutoff, double step) const {
  const detail::TieTolerance& tol = exact_.tolerance();
  const std::vector<detail::TriangleProjector>& projectors = exact_.projectors();
  const double m = margin_;
  // R(b, m): the list radius for least distance b and margin m (class comment).
  auto radius_for = [&](double b, double mm) {
    return tol.window(std::min(cutoff, b + mm)) + mm + tol.absolute;
  };
  auto radius = [&](double b) { return radius_for(b, m); };
  double best = std::numeric_limits<double>::infinity();
  double bound = radius(best);
  double lost = std::numeric_limits<double>::infinity();  // least distance dropped for room
  int count = 0;
  long tests = 0;
  exact_.grid().visit(p0, bound, [&](int t) {
    for (int k = 0; k < count; ++k) {
      if (list[k].triangle == t) {
        return bound;  // met again in another cell (cheaper to find than to test again)
      }
    }
    const double d = std::sqrt(detail::squared_distance(projectors[t], p0));
    ++tests;
    if (!(d <= bound)) {
      return bound;
    }
    if (d < best) {
      best = d;
      bound = radius(best);
    }
    if (count < capacity_) {
      list[count++] = detail::Candidate{d, t};
      return bound;
    }
    int worst = 0;
    for (int k = 1; k < count; ++k) {
      if (list[k].distance > list[worst].distance) {
        worst = k;
      }
    }
    if (d < list[worst].distance) {
      lost = std::min(lost, list[worst].distance);
      list[worst] = detail::Candidate{d, t};
    } else {
      lost = std::min(lost, d);
    }
    return bound;
  });
  // Keep those within the final radius, ascending by distance (then by index): insertion sort.
  int kept = 0;
  for (int k = 0; k < count; ++k) {
    if (!(list[k].distance <= bound)) {
      continue;
    }
    const detail::Candidate c = list[k];
    int j = kept++;
    while (j > 0 && (list[j - 1].distance > c.distance ||
                     (list[j - 1].distance == c.distance && list[j - 1].triangle > c.triangle))) {
      list[j] = list[j - 1];
      --j;
    }
    list[j] = c;
  }
  set_directions(list, kept, p0);
  // The list holds every triangle nearer than `lost` (those dropped for room are all at least that
  // far), so it serves the reaches r with R(best, r) < lost. If some were dropped within the
  // radius, shrink the node's reach to the largest such r (R is piecewise linear in r: slope
  // 2 + relative while best + r < cutoff, 1 beyond), less a rounding allowance.
  double reach = m;
  bool overflow = false;
  if (lost <= bound) {
    double r = (lost - 2 * tol.absolute - (1 + tol.relative) * best) / (2 + tol.relative);
    if (!(best + r <= cutoff)) {
      r = lost - tol.window(cutoff) - tol.absolute;
    }
    r -= tol.absolute;
    if (r > 0 && r >= min_cycles_of_reach * step && radius_for(best, r) < lost) {
      reach = r;
      ++cache.stats.shrunk_lists;
    } else {
      overflow = true;  // too short to be worth rebuilding for: the grid until the node moves m
    }
  }
  cache.anchor = p0;
  cache.cutoff = cutoff;
  cache.reach = reach;
  cache.count = kept;
  cache.overflow = overflow;
  cache.valid = true;
  cache.built_at = cache.stats.queries;
  ++cache.stats.rebuilds;
  cache.stats.rebuild_tests += tests;
}

void CachedSearch::find_closest_for_node(SearchCache* cache, int node, const Vec3& p, double cutoff,
                                         ClosestPoint& out) const {
  CandidateCache* lists = candidates(cache);
  if (!lists || node < 0 || node >= lists->node_count() || !p.allFinite()) {
    exact_.find_closest(p, cutoff, out);
    return;
  }
  detail::NodeCandidates& entry = lists->node(node);
  detail::Candidate* list = lists->list(node);
  ++entry.stats.queries;
  double delta = (p - entry.anchor).norm();
  if (!entry.valid || !(delta <= entry.reach) || !(cutoff <= entry.cutoff)) {
    // The node's recent motion per query, from how far it went since the last build.
    const long since = entry.stats.queries - entry.built_at;
    const double step = entry.valid && since > 0 ? delta / static_cast<double>(since) : 0.0;
    rebuild(entry, list, p, cutoff, step);
    delta = 0;
  }
  if (entry.overflow) {
    ++entry.stats.overflow_fallbacks;
    exact_.find_closest(p, cutoff, out);
    return;
  }
  query_list(entry, list, p, delta, cutoff, out);
}

void CachedSearch::query_list(detail::NodeCandidates& cache, const detail::Candidate* list,
                              const Vec3& p, double delta, double cutoff, ClosestPoint& out) const {
  const detail::TieTolerance& tol = exact_.tolerance();
  const std::vector<detail::TriangleProjector>& projectors = exact_.projectors();
  detail::TieSet ties(tol);
  // The same bound as the modified search; a candidate whose lower bound d(p0, T) - delta
  // exceeds it (beyond the rounding allowance) ends the scan.
  double bound = tol.window(cutoff);
  const double slack = delta + tol.absolute;
  const Vec3 moved = p - cache.anchor;
  long tests = 0;
  for (int k = 0; k < cache.count; ++k) {
    if (list[k].distance - slack > bound) {
      break;
    }
    // The half-space bound (Candidate::away): a triangle provably beyond the bound is not
    // tested; the modified search would not take it either (its computed distance exceeds the
    // bound too). The allowance, 1e-8 of the tool's size, covers the rounding of `away` (at most
    // ~1e-10 of it with the direction floor) times the lengths involved, and of the dot product.
    if (list[k].distance + moved.dot(list[k].away) - half_space_allowance_ > bound) {
      continue;
    }
    const int t = list[k].triangle;
    const double d2 = detail::squared_distance(projectors[t], p);
    ++tests;
    if (d2 <= bound * bound) {
      ties.offer(t, std::sqrt(d2));
      bound = tol.window(std::min(cutoff, ties.best()));
    }
  }
  cache.stats.candidates_tested += tests;
  ties.fill(projectors, exact_.surface(), p, cutoff, out);
  if (out.set_truncated) {
    ++cache.stats.tie_fallbacks;
    exact_.find_closest(p, cutoff, out);
  }
}

CachedSearchStatistics CachedSearch::statistics(const SearchCache& cache) const {
  const CandidateCache* lists = candidates(&cache);
  return lists ? lists->statistics() : CachedSearchStatistics{};
}

void CachedSearch::reset_statistics(SearchCache& cache) const {
  if (CandidateCache* lists = candidates(&cache)) {
    lists->reset_statistics();
  }
}

}  // namespace sf
