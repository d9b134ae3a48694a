// The cached search: every field of its answer, bit for bit, equals the modified (grid) search's
// along moving trajectories (small steps that stay inside the margin, large ones that force
// rebuilds, finite and infinite cutoffs, a changing cutoff, the trap meshes); overflowing lists
// and oversized tie sets fall back to the grid; queries do not allocate.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <thread>

#include "allocation_counter.hpp"
#include "closest_point_comparison.hpp"
#include "contact/cached_search.hpp"
#include "contact/contact_search.hpp"
#include "contact/modified_search.hpp"
#include "core/errors.hpp"
#include "test_meshes.hpp"

namespace sf {
namespace {

using test::random_points;
using test::warp;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Walk {
  int steps = 100;
  double step = 0.01;  ///< length of each step, mm
  double cutoff = kInf;
  /// fixed: `cutoff` at every step; alternating: cutoff, 2 cutoff, cutoff, ...; growing:
  /// cutoff (1 + 0.01 k) at step k.
  enum class Schedule { fixed, alternating, growing } schedule = Schedule::fixed;
  unsigned seed = 1;
};

/// Random walks of `start.size()` points (one blank node each), a random direction per step;
/// at every step the cached search's node query must equal the modified search's answer in every
/// field. Returns the statistics of the cached search.
CachedSearchStatistics expect_identical_along_walks(const TriangleSurface& s,
                                                    const std::vector<Vec3>& start,
                                                    const Walk& walk, CachedSearch& cached) {
  const ModifiedSearch modified(s);
  const int n = static_cast<int>(start.size());
  const auto cache = cached.make_cache(n);
  std::mt19937 rng(walk.seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Vec3> p = start;
  int mismatches = 0;
  for (int k = 0; k < walk.steps; ++k) {
    double cutoff = walk.cutoff;
    if (walk.schedule == Walk::Schedule::alternating && k % 2 == 1) {
      cutoff = 2 * walk.cutoff;
    } else if (walk.schedule == Walk::Schedule::growing) {
      cutoff = walk.cutoff * (1 + 0.01 * k);
    }
    for (int i = 0; i < n; ++i) {
      ClosestPoint want, got;
      modified.find_closest(p[i], cutoff, want);
      cached.find_closest_for_node(cache.get(), i, p[i], cutoff, got);
      const auto same = test::identical(got, want);
      if (!same && ++mismatches <= 5) {
        ADD_FAILURE() << s.name() << " step " << k << " node " << i << " p " << p[i].transpose()
                      << " cutoff " << cutoff << ": " << same.message();
      }
      p[i] += walk.step * Vec3(g(rng), g(rng), g(rng)).normalized();
    }
  }
  EXPECT_EQ(mismatches, 0) << s.name();
  const CachedSearchStatistics st = cached.statistics(*cache);
  EXPECT_EQ(st.queries, static_cast<long>(n) * walk.steps);
  std::printf(
      "%s: %d nodes x %d steps of %g mm (margin %g mm, capacity %d, cutoff %g%s): rebuilds %ld "
      "(shrunk %ld), overflow fallbacks %ld, tie fallbacks %ld, candidates tested per query "
      "%.2f\n",
      s.name().c_str(), n, walk.steps, walk.step, cached.margin(), cached.capacity(), walk.cutoff,
      walk.schedule == Walk::Schedule::alternating ? " alternating with twice that"
      : walk.schedule == Walk::Schedule::growing   ? " growing by 1% of it per step"
                                                   : "",
      st.rebuilds, st.shrunk_lists, st.overflow_fallbacks, st.tie_fallbacks,
      static_cast<double>(st.candidates_tested) / static_cast<double>(st.queries));
  return st;
}

/// Points near a height field over [-1, 1]^2 (within +-0.3 of z = warp) and some off its edges.
std::vector<Vec3> near_warped_surface(int n, unsigned seed) {
  auto pts = random_points(n, Vec3(-1.2, -1.2, -0.3), Vec3(1.2, 1.2, 0.3), seed);
  for (Vec3& q : pts) {
    q.z() += warp(q.x(), q.y());
  }
  return pts;
}

TEST(CachedSearch, StatelessQueryIsTheModifiedAnswer) {
  const TriangleSurface s = test::make_height_field("refined", 30, 30, -1, 1, -1, 1, warp);
  const CachedSearch cached(s);
  const ModifiedSearch modified(s);
  for (const Vec3& p : random_points(500, Vec3(-1.5, -1.5, -1), Vec3(1.5, 1.5, 1), 2)) {
    for (double cutoff : {kInf, 0.1}) {
      ClosestPoint a, b;
      cached.find_closest(p, cutoff, a);
      modified.find_closest(p, cutoff, b);
      ASSERT_TRUE(test::identical(a, b));
    }
  }
}

TEST(CachedSearch, SmallStepsStayInsideTheMarginAndMatchModified) {
  // Steps of a tenth of the margin: most queries are answered from the list; a walk drifts past
  // the margin now and then (rebuilds, but far fewer than queries).
  const TriangleSurface s = test::make_height_field("warped 30x30", 30, 30, -1, 1, -1, 1, warp);
  const auto start = near_warped_surface(300, 3);
  for (double cutoff : {kInf, 0.1}) {
    CachedSearch cached(s);
    Walk walk;
    walk.steps = 200;
    walk.step = 0.1 * cached.margin();
    walk.cutoff = cutoff;
    const auto st = expect_identical_along_walks(s, start, walk, cached);
    EXPECT_GT(st.rebuilds, 300);       // beyond the first build of each node
    EXPECT_LT(st.rebuilds, 300 * 20);  // a tenth of the queries at most
    EXPECT_GT(st.candidates_tested, 0);
  }
}

TEST(CachedSearch, LargeStepsRebuildEveryTimeAndMatchModified) {
  const TriangleSurface s = test::make_height_field("warped 30x30", 30, 30, -1, 1, -1, 1, warp);
  const auto start = near_warped_surface(200, 4);
  for (double cutoff : {kInf, 0.2}) {
    CachedSearch cached(s);
    Walk walk;
    walk.steps = 60;
    walk.step = 1.5 * cached.margin();
    walk.cutoff = cutoff;
    walk.seed = 5;
    const auto st = expect_identical_along_walks(s, start, walk, cached);
    EXPECT_EQ(st.rebuilds, st.queries);
  }
}

TEST(CachedSearch, LargerCutoffRebuilds) {
  // A list built for a cutoff serves every smaller one: alternating between c and 2c rebuilds
  // once (to 2c) after the first build; a cutoff growing at every step rebuilds at every step.
  const TriangleSurface s = test::make_height_field("warped 30x30", 30, 30, -1, 1, -1, 1, warp);
  const auto start = near_warped_surface(200, 6);
  Walk walk;
  walk.steps = 40;
  walk.step = 1e-4;
  walk.cutoff = 0.05;
  walk.schedule = Walk::Schedule::alternating;
  {
    CachedSearch cached(s);
    EXPECT_EQ(expect_identical_along_walks(s, start, walk, cached).rebuilds, 2 * 200);
  }
  walk.schedule = Walk::Schedule::growing;
  {
    CachedSearch cached(s);
    EXPECT_EQ(expect_identical_along_walks(s, start, walk, cached).rebuilds, 40 * 200);
  }
}

TEST(CachedSearch, TrapMeshesMatchModified) {
  struct Case {
    TriangleSurface surface;
    Vec3 lo, hi;
    double step;
  };
  const Case cases[] = {
      {test::make_trap(), Vec3(-12, -4, -3), Vec3(12, 5, 3), 0.05},
      {test::make_thin_trap(), Vec3(-1.5, -2.5, -1), Vec3(1.5, 2.5, 1), 0.01},
      {test::make_height_field("coarse", 3, 4, -1, 1, -1, 1, warp), Vec3(-1.5, -1.5, -1),
       Vec3(1.5, 1.5, 1), 0.02},
      {test::make_random_soup(300, 5), Vec3::Constant(-0.5), Vec3::Constant(1.5), 0.005},
  };
  for (const Case& c : cases) {
    for (double cutoff : {kInf, 0.1}) {
      CachedSearch cached(c.surface);
      Walk walk;
      walk.steps = 60;
      walk.step = c.step;
      walk.cutoff = cutoff;
      expect_identical_along_walks(c.surface, random_points(200, c.lo, c.hi, 7), walk, cached);
    }
  }
}

TEST(CachedSearch, OverflowShrinksTheReachOrFallsBackToTheGrid) {
  // Capacity 2: most lists cannot even serve a short reach and fall back to the grid. A margin
  // of 0.5 mm on a tool of 0.07 mm edges: lists of hundreds of triangles, cut to the 32 nearest,
  // which serve a shorter reach. Both still give the modified answer.
  const TriangleSurface s = test::make_height_field("warped 30x30", 30, 30, -1, 1, -1, 1, warp);
  const auto start = near_warped_surface(200, 8);
  Walk walk;
  walk.steps = 30;
  walk.step = 0.01;
  walk.cutoff = 0.2;
  {
    CachedSearch tiny_capacity(s, 0, 2);
    const auto st = expect_identical_along_walks(s, start, walk, tiny_capacity);
    EXPECT_GT(st.overflow_fallbacks, st.queries / 2);
  }
  {
    CachedSearch wide_margin(s, 0.5);
    const auto st = expect_identical_along_walks(s, start, walk, wide_margin);
    EXPECT_GT(st.shrunk_lists, 200);
    EXPECT_LT(st.overflow_fallbacks, st.queries / 2);
    EXPECT_GT(st.candidates_tested, 0);
  }
}

TEST(CachedSearch, OversizedTieSetFallsBackToTheGrid) {
  // A fan of 12 triangles around a pole: a point above the pole is at the same distance from all
  // 12, more than ClosestPoint::max_set_size: the set is truncated, and which 8 it keeps depends
  // on the visiting order, so the cached search answers such a query with the grid.
  const int n = 12;
  Matrix3X x(3, n + 1);
  x.col(0) = Vec3(0, 0, 0.2);
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    x.col(k + 1) = Vec3(std::cos(a), std::sin(a), 0);
  }
  TriConn t(3, n);
  for (int k = 0; k < n; ++k) {
    t.col(k) << 0, k + 1, (k + 1) % n + 1;
  }
  const TriangleSurface s("pole", x, t);
  CachedSearch cached(s);
  Walk walk;
  walk.steps = 1;
  walk.cutoff = 2.0;
  const std::vector<Vec3> start = {Vec3(0, 0, 0.9), Vec3(0.3, 0.1, 0.5)};
  const auto st = expect_identical_along_walks(s, start, walk, cached);
  EXPECT_EQ(st.tie_fallbacks, 1);
  ClosestPoint cp;
  const auto cache = cached.make_cache(1);
  cached.find_closest_for_node(cache.get(), 0, start[0], 2.0, cp);
  EXPECT_TRUE(cp.set_truncated);
  EXPECT_EQ(cp.feature, ClosestPoint::Feature::vertex);
}

TEST(CachedSearch, FactoryPassesTheMarginAndCapacity) {
  const TriangleSurface s = test::make_height_field("warped 30x30", 30, 30, -1, 1, -1, 1, warp);
  SearchOptions options;
  options.cached_margin = 0.25;
  options.cached_capacity = 7;
  const auto search = make_contact_search("cached", s, options);
  const auto* cached = dynamic_cast<const CachedSearch*>(search.get());
  ASSERT_NE(cached, nullptr);
  EXPECT_EQ(cached->margin(), 0.25);
  EXPECT_EQ(cached->capacity(), 7);
  // Default: a quarter of the mean edge length (edges 1/15, 1/15 and sqrt(2)/15 before the warp).
  const CachedSearch by_default(s);
  EXPECT_NEAR(by_default.margin(), 0.25 * (2 + std::sqrt(2.0)) / 3 / 15, 0.002);
  EXPECT_THROW(CachedSearch(s, 0.1, 0), InputError);
}

TEST(CachedSearch, QueriesDoNotAllocate) {
  // Rebuilds, list queries and both fallbacks included.
  const TriangleSurface s = test::make_height_field("warped 20x20", 20, 20, -1, 1, -1, 1, warp);
  const auto pts = near_warped_surface(300, 9);
  CachedSearch cached(s, 0, 4);  // small capacity: some lists overflow
  const auto cache = cached.make_cache(static_cast<int>(pts.size()));
  ClosestPoint cp;
  double sum = 0;
  const long before = test::allocation_count();
  for (int k = 0; k < 20; ++k) {
    for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
      const Vec3 p = pts[i] + Vec3(0.01 * k, 0.0, 0.0);
      cached.find_closest_for_node(cache.get(), i, p, k % 3 == 0 ? kInf : 0.2, cp);
      sum += cp.distance;
    }
  }
  EXPECT_EQ(test::allocation_count() - before, 0);
  const auto st = cached.statistics(*cache);
  EXPECT_GT(st.rebuilds, 300);
  EXPECT_GT(st.overflow_fallbacks, 0);
  EXPECT_GT(st.candidates_tested, 0);
  EXPECT_GT(sum, 0);
}

TEST(CachedSearch, NodesMayBeQueriedConcurrently) {
  // Two threads, each with its own half of the nodes (per-node state only), against the
  // modified search run afterwards.
  const TriangleSurface s = test::make_height_field("warped 30x30", 30, 30, -1, 1, -1, 1, warp);
  const auto pts = near_warped_surface(400, 10);
  const int n = static_cast<int>(pts.size());
  CachedSearch cached(s);
  const auto cache = cached.make_cache(n);
  const int steps = 50;
  std::vector<ClosestPoint> got(static_cast<std::size_t>(n) * steps);
  auto run = [&](int first, int last) {
    for (int k = 0; k < steps; ++k) {
      for (int i = first; i < last; ++i) {
        cached.find_closest_for_node(cache.get(), i, pts[i] + Vec3(0, 0.003 * k, 0), 0.2,
                                     got[static_cast<std::size_t>(k) * n + i]);
      }
    }
  };
  std::thread a(run, 0, n / 2), b(run, n / 2, n);
  a.join();
  b.join();
  const ModifiedSearch modified(s);
  for (int k = 0; k < steps; ++k) {
    for (int i = 0; i < n; ++i) {
      ClosestPoint want;
      modified.find_closest(pts[i] + Vec3(0, 0.003 * k, 0), 0.2, want);
      ASSERT_TRUE(test::identical(got[static_cast<std::size_t>(k) * n + i], want));
    }
  }
  EXPECT_EQ(cached.statistics(*cache).queries, static_cast<long>(n) * steps);
}

TEST(CachedSearch, OutOfRangeNodeIsAnsweredByTheGrid) {
  const TriangleSurface s = test::make_height_field("warped 10x10", 10, 10, -1, 1, -1, 1, warp);
  CachedSearch cached(s);
  const auto cache = cached.make_cache(2);
  const ModifiedSearch modified(s);
  ClosestPoint a, b;
  cached.find_closest_for_node(cache.get(), 5, Vec3(0.1, 0.2, 0.3), kInf, a);
  modified.find_closest(Vec3(0.1, 0.2, 0.3), kInf, b);
  EXPECT_TRUE(test::identical(a, b));
  EXPECT_EQ(cached.statistics(*cache).queries, 0);
}

}  // namespace
}  // namespace sf
