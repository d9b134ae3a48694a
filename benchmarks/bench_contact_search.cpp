// Benchmark of the contact searches (not a test): the cost study of Wawrzyk & Kowalczyk's section
// 3 (/work/shared/seed/modified-contact-search.txt), measured. Tool: a punch-like height field
// z = 20 exp(-(x^2 + y^2) / 5000) mm over [-100, 100]^2 mm, n x n cells of two triangles, the
// interior nodes jittered in the plane by up to 0.2 of a cell (an irregular mesh, as a mesher
// makes it), at about 1k, 4k, 16k, 65k and 130k triangles. Cutoff 1.6 mm (twice a 0.8 mm blank,
// the case-file rule).
//
// Per mesh:
//  - static queries: 20000 points within +-1 mm (vertically) of the surface; ns per query of
//    standard_brute_force, modified_brute_force (fewer points on the large meshes), standard,
//    modified, and cached with one node per point, so that every query builds its list (the
//    cost of a list build);
//  - motion: a 45 x 45 grid of blank nodes (2025), each sliding along the surface at a fixed
//    offset in [-1, 1] mm in its own direction, 1e-3 mm per cycle for 500 cycles, and for cached
//    also 2e-2 mm per cycle; ns per node-cycle of standard, modified and cached, the cached figure
//    including all its list builds (from empty lists);
//  - the multiplications, divisions and square roots per query of the two brute-force searches
//    (the paper's measure) and of the grid searches, and per node-cycle of cached (list builds
//    included): an analytic count per primitive (below) times the primitives actually executed,
//    counted by a replica of each search that is checked to return the production answer (every
//    field) at every counted query;
//  - checks: cached equals modified in every field at every static point; the fraction of
//    static points where standard's triangle is not in modified's tie set (its misses).
// Then a margin study of cached on the 16k mesh. Each time is the fastest of 3 passes (2 for the
// trajectories): the machine is shared, other jobs only slow a pass down.
//
// Operation counts per primitive (doubles; additions, subtractions, comparisons not counted):
//  - point-triangle kernel (detail::squared_distance): r = p - x1, then (T1, T2, D) = A^-1 r with
//    A^-1 precomputed for the rigid tool: 9 mult; inside (all T >= 0) D^2: 1 mult -> 10; outside,
//    per edge projected (one per negative coordinate, 1 or 2): (p - a).e 3, times 1/|e|^2 1,
//    t e 3, |p - a - t e|^2 3 -> 10 mult each. No division (1/|e|^2 and A^-1 are precomputed).
//  - offer to the tie set (a triangle within the bound): 1 sqrt; window check 1 mult; a new least
//    distance: its window 1 mult; the new bound and its square 2 mult.
//  - node distance (standard): |x - p|^2, 3 mult.
//  - grid traversal (detail::BoxGrid::visit, see GridCounter): 3 div for p's cell, 6 mult per
//    shell bound, 6 mult per cell box, 3 mult per item box, 1 mult per item tested.
//  - cached: |p - anchor| 3 mult + 1 sqrt per query; then its candidates as kernels and offers.
//  - final answer (detail::TieSet::fill, once per query): the kernel with the point: 9 + (inside:
//    1 + 6; outside: 10 per edge + 9) mult, 1 sqrt; mean normal of the set: 3 mult, 1 sqrt, 3 div;
//    normal and sign: 3 mult (face or on the surface), or 6 mult and 1 div (edge or vertex).
//
// Usage: bench_contact_search <out.csv> [quick]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "bench_host.hpp"
#include "contact/cached_search.hpp"
#include "contact/contact_search.hpp"
#include "contact/modified_search.hpp"
#include "contact/standard_search.hpp"
#include "contact/triangle_projection.hpp"

namespace {

using namespace sf;

constexpr double kHalf = 100.0;      // mm, half-width of the tool
constexpr double kCutoff = 1.6;      // mm
constexpr double kOffset = 1.0;      // mm, query points within +-kOffset of the surface
constexpr double kSmallStep = 1e-3;  // mm per cycle
constexpr double kLargeStep = 2e-2;  // mm per cycle

double punch(double x, double y) {
  return 20.0 * std::exp(-(x * x + y * y) / 5000.0);
}

using bench::machine_name;

/// n x n cells, 2 n^2 triangles, alternating diagonals, interior nodes jittered by up to 0.2 h.
TriangleSurface make_tool(int n) {
  std::mt19937 rng(1234u + n);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  const double h = 2 * kHalf / n;
  Matrix3X x(3, (n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      double px = -kHalf + h * i, py = -kHalf + h * j;
      if (i > 0 && i < n && j > 0 && j < n) {
        px += h * u(rng);
        py += h * u(rng);
      }
      x.col(j * (n + 1) + i) = Vec3(px, py, punch(px, py));
    }
  }
  TriConn t(3, 2 * n * n);
  int k = 0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      if ((i + j) % 2 == 0) {
        t.col(k++) << a, b, c;
        t.col(k++) << a, c, d;
      } else {
        t.col(k++) << a, b, d;
        t.col(k++) << b, c, d;
      }
    }
  }
  return TriangleSurface("punch " + std::to_string(2 * n * n), x, t);
}

double mean_edge(const TriangleSurface& s) {
  double sum = 0;
  for (int t = 0; t < s.num_triangles(); ++t) {
    for (int a = 0; a < 3; ++a) {
      sum += (s.nodes().col(s.triangles()((a + 1) % 3, t)) - s.nodes().col(s.triangles()(a, t)))
                 .norm();
    }
  }
  return sum / (3.0 * s.num_triangles());
}

/// Points within +-kOffset (vertically) of the surface, inside [-0.95, 0.95] kHalf.
std::vector<Vec3> static_points(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> p(n);
  for (Vec3& q : p) {
    const double x = 0.95 * kHalf * u(rng), y = 0.95 * kHalf * u(rng);
    q = Vec3(x, y, punch(x, y) + kOffset * u(rng));
  }
  return p;
}

/// A g x g grid of blank nodes over [-0.9, 0.9] kHalf, each with its own offset in [-1, 1] mm and
/// in-plane direction, sliding `step` mm per cycle along the surface: positions[cycle * nodes + i].
std::vector<Vec3> trajectory(int g, int cycles, double step) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(-1, 1);
  const int nodes = g * g;
  std::vector<Vec3> start(nodes);
  std::vector<Vec3> dir(nodes);
  std::vector<double> offset(nodes);
  for (int j = 0; j < g; ++j) {
    for (int i = 0; i < g; ++i) {
      const int k = j * g + i;
      start[k] = Vec3(-0.9 * kHalf + 1.8 * kHalf * i / (g - 1),
                      -0.9 * kHalf + 1.8 * kHalf * j / (g - 1), 0);
      const double a = 3.14159265358979 * u(rng);
      dir[k] = Vec3(std::cos(a), std::sin(a), 0);
      offset[k] = kOffset * u(rng);
    }
  }
  std::vector<Vec3> pos(static_cast<std::size_t>(nodes) * cycles);
  for (int c = 0; c < cycles; ++c) {
    for (int k = 0; k < nodes; ++k) {
      const Vec3 q = start[k] + (c * step) * dir[k];
      pos[static_cast<std::size_t>(c) * nodes + k] =
          Vec3(q.x(), q.y(), punch(q.x(), q.y()) + offset[k]);
    }
  }
  return pos;
}

double g_sink = 0;  // results folded in, so that no query is optimised away

constexpr int kStaticRepeats = 3;  // timed passes of each static measurement; the fastest counts
constexpr int kMotionRepeats = 2;  // the same for the trajectories

/// ns per call of `run` (which makes `calls` calls), the fastest of `repeats` passes, each after
/// `setup` (not timed): the machine is shared, and other jobs only ever slow a pass down.
template <class Setup, class Run>
double best_ns_per_call(long calls, int repeats, Setup&& setup, Run&& run) {
  double best = std::numeric_limits<double>::infinity();
  for (int r = 0; r < repeats; ++r) {
    setup();
    const auto t0 = std::chrono::steady_clock::now();
    run();
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count() /
                              static_cast<double>(calls));
  }
  return best;
}

/// Every field of two answers identical.
bool same_answer(const ClosestPoint& a, const ClosestPoint& b) {
  return a.triangle == b.triangle && a.set_size == b.set_size &&
         std::equal(a.set.begin(), a.set.begin() + a.set_size, b.set.begin()) &&
         a.set_truncated == b.set_truncated && a.feature == b.feature && a.distance == b.distance &&
         a.signed_distance == b.signed_distance && a.point == b.point && a.normal == b.normal &&
         a.barycentric == b.barycentric;
}

// ---- Operation counts of the brute-force searches ----------------------------------------------

struct Ops {
  double mult = 0, div = 0, sqrt = 0;
  double kernels = 0, node_distances = 0, offers = 0;
};

/// Edges projected by the kernel for (tp, p): 0 inside, else the number of negative coordinates.
int kernel_edges(const detail::TriangleProjector& tp, const Vec3& p) {
  const Vec3 s = tp.inverse * (p - tp.x[0]);
  const double t3 = 1.0 - s[0] - s[1];
  if (s[0] >= 0 && s[1] >= 0 && t3 >= 0) {
    return 0;
  }
  return (t3 < 0 ? 1 : 0) + (s[0] < 0 ? 1 : 0) + (s[1] < 0 ? 1 : 0);
}

double counted_kernel(const detail::TriangleProjector& tp, const Vec3& p, Ops& ops) {
  const int edges = kernel_edges(tp, p);
  ops.mult += 9 + (edges == 0 ? 1 : 10 * edges);
  ops.kernels += 1;
  return detail::squared_distance(tp, p);
}

/// The offer loop of both brute-force searches over the given triangles, counted.
template <class Triangles>
void counted_offers(const std::vector<detail::TriangleProjector>& proj,
                    const detail::TieTolerance& tol, const Vec3& p, double cutoff,
                    const Triangles& triangles, detail::TieSet& ties, Ops& ops) {
  double bound = tol.window(cutoff);
  double bound2 = bound * bound;
  for (int t : triangles) {
    const double d2 = counted_kernel(proj[t], p, ops);
    if (d2 <= bound2) {
      const double d = std::sqrt(d2);
      ops.sqrt += 1;
      ops.offers += 1;
      ops.mult += 1 + (d < ties.best() ? 1 : 0) + 2;
      ties.offer(t, d);
      bound = tol.window(std::min(cutoff, ties.best()));
      bound2 = bound * bound;
    }
  }
}

void count_fill(const std::vector<detail::TriangleProjector>& proj, const Vec3& p,
                const ClosestPoint& cp, Ops& ops) {
  if (cp.triangle < 0) {
    return;
  }
  const int edges = kernel_edges(proj[cp.triangle], p);
  ops.mult += 9 + (edges == 0 ? 7 : 10 * edges + 9);
  ops.sqrt += 2;
  ops.mult += 3;
  ops.div += 3;
  if (cp.feature == ClosestPoint::Feature::face || cp.distance == 0) {
    ops.mult += 3;
  } else {
    ops.mult += 6;
    ops.div += 1;
  }
}

/// Range of ints [first, last).
struct IntRange {
  int first, last;
  struct It {
    int i;
    int operator*() const { return i; }
    It& operator++() {
      ++i;
      return *this;
    }
    bool operator!=(const It& o) const { return i != o.i; }
  };
  It begin() const { return {first}; }
  It end() const { return {last}; }
};

struct SpanOf {
  const int* first;
  const int* last;
  const int* begin() const { return first; }
  const int* end() const { return last; }
};

/// Replica of modified_brute_force with counts; checks that it gives the production answer.
bool count_modified_brute(const TriangleSurface& s,
                          const std::vector<detail::TriangleProjector>& proj,
                          const detail::TieTolerance& tol, const ContactSearch& production,
                          const Vec3& p, Ops& ops) {
  detail::TieSet ties(tol);
  counted_offers(proj, tol, p, kCutoff, IntRange{0, s.num_triangles()}, ties, ops);
  ClosestPoint mine, want;
  ties.fill(proj, s, p, kCutoff, mine);
  production.find_closest(p, kCutoff, want);
  count_fill(proj, p, mine, ops);
  return mine.triangle == want.triangle && mine.distance == want.distance;
}

/// Replica of standard_brute_force with counts; checks that it gives the production answer.
bool count_standard_brute(const TriangleSurface& s,
                          const std::vector<detail::TriangleProjector>& proj,
                          const detail::TieTolerance& tol, const ContactSearch& production,
                          const Vec3& p, Ops& ops) {
  int best = -1;
  double best_d2 = std::numeric_limits<double>::infinity();
  const auto& off = s.node_triangle_offsets();
  for (int i = 0; i < s.num_nodes(); ++i) {
    const double d2 = (s.nodes().col(i) - p).squaredNorm();
    ops.mult += 3;
    ops.node_distances += 1;
    if (d2 < best_d2 && off[i + 1] > off[i]) {
      best_d2 = d2;
      best = i;
    }
  }
  detail::TieSet ties(tol);
  if (best >= 0) {
    const int* tri = s.node_triangles().data();
    counted_offers(proj, tol, p, kCutoff, SpanOf{tri + off[best], tri + off[best + 1]}, ties, ops);
  }
  ClosestPoint mine, want;
  ties.fill(proj, s, p, kCutoff, mine);
  production.find_closest(p, kCutoff, want);
  count_fill(proj, p, mine, ops);
  return mine.triangle == want.triangle && mine.distance == want.distance;
}

// ---- Operation counts of the grid searches and of cached ---------------------------------------
// The grid traversal (detail::BoxGrid::visit): 3 div for p's cell; per shell bound checked 6 mult
// (the face positions (c -+ r) h along 3 axes); per cell 6 mult (its corner lo + h (i, j, k): 3,
// squared box distance: 3); per item box checked 3 mult; per item tested 1 mult (the new bound
// squared).

struct GridCounter {
  Ops* ops;
  void shell() const { ops->mult += 6; }
  void cell() const { ops->mult += 6; }
  void item() const { ops->mult += 3; }
};

/// Replica of "modified" with counts; checks that it gives the production answer.
bool count_modified_grid(const ModifiedSearch& m, const Vec3& p, double cutoff, Ops& ops,
                         ClosestPoint& out) {
  const auto& proj = m.projectors();
  const auto& tol = m.tolerance();
  detail::TieSet ties(tol);
  double bound = tol.window(cutoff);
  ops.mult += 2;  // the window, its square
  ops.div += 3;
  m.grid().visit(
      p, bound,
      [&](int t) {
        const double d2 = counted_kernel(proj[t], p, ops);
        ops.mult += 2;  // bound * bound in the test, and the grid's new bound squared
        if (d2 <= bound * bound) {
          const double d = std::sqrt(d2);
          ops.sqrt += 1;
          ops.offers += 1;
          ops.mult += 2 + (d < ties.best() ? 1 : 0);
          ties.offer(t, d);
          bound = tol.window(std::min(cutoff, ties.best()));
        }
        return bound;
      },
      GridCounter{&ops});
  ties.fill(proj, m.surface(), p, cutoff, out);
  count_fill(proj, p, out, ops);
  ClosestPoint want;
  m.find_closest(p, cutoff, want);
  return same_answer(out, want);
}

/// Replica of "standard" with counts; checks that it gives the production answer.
bool count_standard_grid(const TriangleSurface& s, const StandardSearch& st, const Vec3& p,
                         Ops& ops) {
  const auto& proj = st.projectors();
  const auto& tol = st.tolerance();
  const double radius = tol.window(kCutoff + st.longest_edge());
  ops.mult += 2;  // the window, its square
  ops.div += 3;
  int best = -1;
  double best_d2 = std::numeric_limits<double>::infinity();
  double bound = radius;
  st.grid().visit(
      p, bound,
      [&](int item) {
        const int node = st.grid_nodes()[item];
        const double d2 = st.node_distance2(node, p);
        ops.mult += 3 + 1;  // the distance, the grid's new bound squared
        ops.node_distances += 1;
        if (d2 < best_d2 || (d2 == best_d2 && node < best)) {
          best_d2 = d2;
          best = node;
          bound = std::min(bound, std::sqrt(best_d2) + tol.absolute);
          ops.sqrt += 1;
        }
        return bound;
      },
      GridCounter{&ops});
  detail::TieSet ties(tol);
  if (best >= 0) {
    const auto& off = s.node_triangle_offsets();
    const int* tri = s.node_triangles().data();
    counted_offers(proj, tol, p, kCutoff, SpanOf{tri + off[best], tri + off[best + 1]}, ties, ops);
  }
  ClosestPoint mine, want;
  ties.fill(proj, s, p, kCutoff, mine);
  count_fill(proj, p, mine, ops);
  st.find_closest(p, kCutoff, want);
  return same_answer(mine, want);
}

/// Replica of "cached" with counts, its own lists (same margin, capacity, radius and query as
/// CachedSearch; an overflowing list falls back to the grid here, where CachedSearch may keep a
/// shorter reach instead: the counts differ only for such nodes, which are counted). Checked
/// against the production answer at every query.
class CachedReplica {
 public:
  CachedReplica(const ModifiedSearch& m, double margin, int capacity, int nodes)
      : m_(m), margin_(margin), capacity_(capacity), nodes_(nodes), lists_(nodes) {}

  bool query(int node, const Vec3& p, const ClosestPoint& want, Ops& ops) {
    const auto& proj = m_.projectors();
    const auto& tol = m_.tolerance();
    Node& n = nodes_[node];
    double delta = (p - n.anchor).norm();
    ops.mult += 3;
    ops.sqrt += 1;
    if (!n.valid || !(delta <= margin_)) {
      build(n, lists_[node], p, ops);
      delta = 0;
    }
    ClosestPoint out;
    if (n.overflow) {
      ++overflow_queries;
      return count_modified_grid(m_, p, kCutoff, ops, out) && same_answer(out, want);
    }
    detail::TieSet ties(tol);
    double bound = tol.window(kCutoff);
    ops.mult += 1;
    const double slack = delta + tol.absolute;
    for (const auto& c : lists_[node]) {
      if (c.first - slack > bound) {
        break;
      }
      const double d2 = counted_kernel(proj[c.second], p, ops);
      ops.mult += 1;  // bound * bound
      if (d2 <= bound * bound) {
        const double d = std::sqrt(d2);
        ops.sqrt += 1;
        ops.offers += 1;
        ops.mult += 2 + (d < ties.best() ? 1 : 0);
        ties.offer(c.second, d);
        bound = tol.window(std::min(kCutoff, ties.best()));
      }
    }
    ties.fill(proj, m_.surface(), p, kCutoff, out);
    count_fill(proj, p, out, ops);
    if (out.set_truncated) {
      return count_modified_grid(m_, p, kCutoff, ops, out) && same_answer(out, want);
    }
    return same_answer(out, want);
  }
  long overflow_queries = 0;

 private:
  struct Node {
    Vec3 anchor = Vec3::Zero();
    bool valid = false, overflow = false;
  };

  void build(Node& n, std::vector<std::pair<double, int>>& list, const Vec3& p0, Ops& ops) {
    const auto& proj = m_.projectors();
    const auto& tol = m_.tolerance();
    auto radius = [&](double b) {
      ops.mult += 1;
      return tol.window(std::min(kCutoff, b + margin_)) + margin_ + tol.absolute;
    };
    list.clear();
    double best = std::numeric_limits<double>::infinity();
    double bound = radius(best);
    ops.mult += 1;
    ops.div += 3;
    m_.grid().visit(
        p0, bound,
        [&](int t) {
          for (const auto& c : list) {
            if (c.second == t) {
              return bound;
            }
          }
          const double d = std::sqrt(counted_kernel(proj[t], p0, ops));
          ops.sqrt += 1;
          ops.mult += 1;  // the grid's new bound squared
          if (d <= bound) {
            if (d < best) {
              best = d;
              bound = radius(best);
            }
            list.emplace_back(d, t);
          }
          return bound;
        },
        GridCounter{&ops});
    std::vector<std::pair<double, int>> kept;
    for (const auto& c : list) {
      if (c.first <= bound) {
        kept.push_back(c);
      }
    }
    std::sort(kept.begin(), kept.end());
    n.overflow = static_cast<int>(kept.size()) > capacity_;
    list = kept;
    n.anchor = p0;
    n.valid = true;
  }

  const ModifiedSearch& m_;
  double margin_;
  int capacity_;
  std::vector<Node> nodes_;
  std::vector<std::vector<std::pair<double, int>>> lists_;
};

// ---- Timing -------------------------------------------------------------------------------------

double time_static(const ContactSearch& search, const std::vector<Vec3>& pts, int n) {
  return best_ns_per_call(
      n, kStaticRepeats, [] {},
      [&] {
        ClosestPoint cp;
        double sum = 0;
        for (int k = 0; k < n; ++k) {
          search.find_closest(pts[k], kCutoff, cp);
          sum += cp.distance;
        }
        g_sink += sum;
      });
}

/// Node queries over a trajectory, cycle by cycle, each pass with a new cache (so a cached search
/// starts with no lists: its first builds are included). The last pass's cache is left in
/// `cache` (for its statistics).
double time_motion(const ContactSearch& search, const std::vector<Vec3>& pos, int nodes,
                   std::unique_ptr<SearchCache>& cache) {
  const long calls = static_cast<long>(pos.size());
  return best_ns_per_call(
      calls, kMotionRepeats, [&] { cache = search.make_cache(nodes); },
      [&] {
        ClosestPoint cp;
        double sum = 0;
        for (long q = 0; q < calls; ++q) {
          search.find_closest_for_node(cache.get(), static_cast<int>(q % nodes), pos[q], kCutoff,
                                       cp);
          sum += cp.distance;
        }
        g_sink += sum;
      });
}

struct Row {
  long triangles = 0, nodes = 0;
  std::string search, mode;
  long queries = 0;
  double ns = 0;
  double mult = -1, div = -1, sqrt = -1;             // per query (brute force), -1: not counted
  double tests = -1, rebuilds = -1, fallbacks = -1;  // per query (cached)
  double margin = -1;                                // mm (cached)
};

void write_csv(const std::string& path, const std::vector<Row>& rows) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) {
    std::fprintf(stderr, "cannot write %s\n", path.c_str());
    std::exit(2);
  }
  std::fprintf(f,
               "triangles,nodes,search,mode,queries,ns_per_query,mult_per_query,div_per_query,"
               "sqrt_per_query,tests_per_query,rebuilds_per_query,fallbacks_per_query,margin_mm\n");
  auto opt = [&](double v) {
    if (v < 0) {
      std::fprintf(f, ",");
    } else {
      std::fprintf(f, ",%.6g", v);
    }
  };
  for (const Row& r : rows) {
    std::fprintf(f, "%ld,%ld,%s,%s,%ld,%.2f", r.triangles, r.nodes, r.search.c_str(),
                 r.mode.c_str(), r.queries, r.ns);
    opt(r.mult);
    opt(r.div);
    opt(r.sqrt);
    opt(r.tests);
    opt(r.rebuilds);
    opt(r.fallbacks);
    opt(r.margin);
    std::fprintf(f, "\n");
  }
  std::fclose(f);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s <out.csv> [quick]\n", argv[0]);
    return 2;
  }
  const bool quick = argc > 2 && std::string(argv[2]) == "quick";
  const std::vector<int> cells =
      quick ? std::vector<int>{22, 45} : std::vector<int>{22, 45, 90, 180, 255};
  const int grid_nodes = 45;  // 2025 blank nodes
  const int cycles = quick ? 50 : 500;
  const int static_n = 20000;
  std::printf("machine: %s (1 thread)\n", machine_name().c_str());
  std::printf(
      "tool: punch height field over [-100, 100]^2 mm, jittered; cutoff %.1f mm; points "
      "within +-%.0f mm of the surface\n",
      kCutoff, kOffset);
  std::printf("motion: %d nodes x %d cycles at %g mm/cycle (cached also at %g mm/cycle)\n",
              grid_nodes * grid_nodes, cycles, kSmallStep, kLargeStep);
  std::printf(
      "op counts: analytic count per primitive x primitives executed, counted by a replica "
      "of each brute-force loop (checked against the production answer)\n\n");

  const auto pts = static_points(static_n, 7);
  const auto small_motion = trajectory(grid_nodes, cycles, kSmallStep);
  const auto large_motion = trajectory(grid_nodes, cycles, kLargeStep);
  const int nodes = grid_nodes * grid_nodes;
  std::vector<Row> rows;

  std::printf("%9s %7s | %10s %10s | %8s %8s %8s | %8s %8s %8s %8s | %7s %7s %7s\n", "triangles",
              "nodes", "std_brute", "mod_brute", "standard", "modified", "cached", "std_mot",
              "mod_mot", "cach_mot", "cach_fast", "mod/std", "cac/std", "cac/mod");
  struct OpsRow {
    long triangles = 0, nodes = 0;
    Ops std_ops, mod_ops;  // brute force, per `counted` queries
    int counted = 0;
    Ops std_grid, mod_grid;          // per `grid_counted` queries
    Ops cached_small, cached_large;  // per node-cycle (`motion_counted` each)
    double grid_counted = 0, motion_counted = 0;
    long replica_overflows = 0;
    int misses = 0, mismatches = 0;
    double tests = 0, rebuilds = 0, build_tests = 0;
  };
  std::vector<OpsRow> op_rows;

  for (int n : cells) {
    const TriangleSurface tool = make_tool(n);
    const long nt = tool.num_triangles(), nn = tool.num_nodes();
    const auto standard_brute = make_contact_search("standard_brute_force", tool);
    const auto modified_brute = make_contact_search("modified_brute_force", tool);
    const auto standard = make_contact_search("standard", tool);
    const auto modified = make_contact_search("modified", tool);
    CachedSearch cached(tool);
    std::unique_ptr<SearchCache> cache;  // the cached search's lists of the latest pass

    // Static queries.
    const int brute_n = static_cast<int>(std::clamp(40000000L / nt, 100L, 5000L));
    const double t_sb = time_static(*standard_brute, pts, brute_n);
    const double t_mb = time_static(*modified_brute, pts, brute_n);
    const double t_s = time_static(*standard, pts, static_n);
    const double t_m = time_static(*modified, pts, static_n);
    // Cached, one node per point: every query builds its list (the cost of a rebuild).
    const double t_c_build = best_ns_per_call(
        static_n, kStaticRepeats, [&] { cache = cached.make_cache(static_n); },
        [&] {
          ClosestPoint cp;
          double sum = 0;
          for (int k = 0; k < static_n; ++k) {
            cached.find_closest_for_node(cache.get(), k, pts[k], kCutoff, cp);
            sum += cp.distance;
          }
          g_sink += sum;
        });
    const CachedSearchStatistics st_build = cached.statistics(*cache);
    // Check: cached equals modified, and count the standard search's misses.
    int mismatches = 0, misses = 0;
    for (int k = 0; k < static_n; ++k) {
      ClosestPoint a, b, c;
      cached.find_closest_for_node(cache.get(), k, pts[k], kCutoff, a);
      modified->find_closest(pts[k], kCutoff, b);
      standard->find_closest(pts[k], kCutoff, c);
      mismatches += same_answer(a, b) ? 0 : 1;
      const bool in_set = c.triangle >= 0 && std::find(b.set.begin(), b.set.begin() + b.set_size,
                                                       c.triangle) != b.set.begin() + b.set_size;
      misses += (b.triangle >= 0 && !in_set) ? 1 : 0;
    }

    // Motion.
    const double t_s_mot = time_motion(*standard, small_motion, nodes, cache);
    const double t_m_mot = time_motion(*modified, small_motion, nodes, cache);
    const double t_c_mot = time_motion(cached, small_motion, nodes, cache);
    const CachedSearchStatistics st = cached.statistics(*cache);
    const double t_c_fast = time_motion(cached, large_motion, nodes, cache);
    const CachedSearchStatistics st_fast = cached.statistics(*cache);

    // Operation counts of the brute-force searches.
    const auto& proj = dynamic_cast<const ModifiedSearch&>(*modified).projectors();
    const auto& tol = dynamic_cast<const ModifiedSearch&>(*modified).tolerance();
    OpsRow o;
    o.triangles = nt;
    o.nodes = nn;
    o.counted = std::min(200, brute_n);
    o.misses = misses;
    o.mismatches = mismatches;
    o.build_tests =
        static_cast<double>(st_build.rebuild_tests) / static_cast<double>(st_build.rebuilds);
    int wrong = 0;
    for (int k = 0; k < o.counted; ++k) {
      wrong += count_standard_brute(tool, proj, tol, *standard_brute, pts[k], o.std_ops) ? 0 : 1;
      wrong += count_modified_brute(tool, proj, tol, *modified_brute, pts[k], o.mod_ops) ? 0 : 1;
    }
    if (wrong > 0) {
      std::printf("ERROR: the counting replicas disagree with the searches on %d queries\n", wrong);
      return 1;
    }
    // The grid searches on the first 2000 static points; cached over both trajectories.
    const auto& ms = dynamic_cast<const ModifiedSearch&>(*modified);
    const auto& ss = dynamic_cast<const StandardSearch&>(*standard);
    o.grid_counted = 2000;
    for (int k = 0; k < 2000; ++k) {
      ClosestPoint scratch;
      wrong += count_modified_grid(ms, pts[k], kCutoff, o.mod_grid, scratch) ? 0 : 1;
      wrong += count_standard_grid(tool, ss, pts[k], o.std_grid) ? 0 : 1;
    }
    for (int pass = 0; pass < 2; ++pass) {
      const auto& motion = pass == 0 ? small_motion : large_motion;
      Ops& ops = pass == 0 ? o.cached_small : o.cached_large;
      CachedReplica replica(ms, cached.margin(), cached.capacity(), nodes);
      cache = cached.make_cache(nodes);
      for (std::size_t q = 0; q < motion.size(); ++q) {
        const int node = static_cast<int>(q % nodes);
        ClosestPoint want;
        cached.find_closest_for_node(cache.get(), node, motion[q], kCutoff, want);
        wrong += replica.query(node, motion[q], want, ops) ? 0 : 1;
      }
      o.replica_overflows += replica.overflow_queries;
    }
    o.motion_counted = static_cast<double>(small_motion.size());
    if (wrong > 0) {
      std::printf("ERROR: the counting replicas disagree with the searches on %d queries\n", wrong);
      return 1;
    }
    const double q = o.counted;
    o.tests = static_cast<double>(st.candidates_tested) / static_cast<double>(st.queries);
    o.rebuilds = static_cast<double>(st.rebuilds) / static_cast<double>(st.queries);
    op_rows.push_back(o);

    std::printf(
        "%9ld %7ld | %10.0f %10.0f | %8.0f %8.0f %8.0f | %8.0f %8.0f %8.0f %8.0f | %7.2f "
        "%7.2f %7.2f\n",
        nt, nn, t_sb, t_mb, t_s, t_m, t_c_build, t_s_mot, t_m_mot, t_c_mot, t_c_fast, t_mb / t_sb,
        t_c_mot / t_s_mot, t_c_mot / t_m_mot);
    std::fflush(stdout);

    auto row = [&](const char* search, const char* mode, long queries, double ns) {
      Row r;
      r.triangles = nt;
      r.nodes = nn;
      r.search = search;
      r.mode = mode;
      r.queries = queries;
      r.ns = ns;
      return r;
    };
    Row r = row("standard_brute_force", "static", brute_n, t_sb);
    r.mult = o.std_ops.mult / q;
    r.div = o.std_ops.div / q;
    r.sqrt = o.std_ops.sqrt / q;
    rows.push_back(r);
    r = row("modified_brute_force", "static", brute_n, t_mb);
    r.mult = o.mod_ops.mult / q;
    r.div = o.mod_ops.div / q;
    r.sqrt = o.mod_ops.sqrt / q;
    rows.push_back(r);
    r = row("standard", "static", static_n, t_s);
    r.mult = o.std_grid.mult / o.grid_counted;
    r.div = o.std_grid.div / o.grid_counted;
    r.sqrt = o.std_grid.sqrt / o.grid_counted;
    rows.push_back(r);
    r = row("modified", "static", static_n, t_m);
    r.mult = o.mod_grid.mult / o.grid_counted;
    r.div = o.mod_grid.div / o.grid_counted;
    r.sqrt = o.mod_grid.sqrt / o.grid_counted;
    rows.push_back(r);
    r = row("cached", "static_build", static_n, t_c_build);
    r.margin = cached.margin();
    rows.push_back(r);
    rows.push_back(row("standard", "motion_1e-3", static_cast<long>(small_motion.size()), t_s_mot));
    rows.push_back(row("modified", "motion_1e-3", static_cast<long>(small_motion.size()), t_m_mot));
    r = row("cached", "motion_1e-3", static_cast<long>(small_motion.size()), t_c_mot);
    r.mult = o.cached_small.mult / o.motion_counted;
    r.div = o.cached_small.div / o.motion_counted;
    r.sqrt = o.cached_small.sqrt / o.motion_counted;
    r.tests = o.tests;
    r.rebuilds = o.rebuilds;
    r.fallbacks = static_cast<double>(st.fallbacks()) / static_cast<double>(st.queries);
    r.margin = cached.margin();
    rows.push_back(r);
    r = row("cached", "motion_2e-2", static_cast<long>(large_motion.size()), t_c_fast);
    r.mult = o.cached_large.mult / o.motion_counted;
    r.div = o.cached_large.div / o.motion_counted;
    r.sqrt = o.cached_large.sqrt / o.motion_counted;
    r.tests = static_cast<double>(st_fast.candidates_tested) / static_cast<double>(st_fast.queries);
    r.rebuilds = static_cast<double>(st_fast.rebuilds) / static_cast<double>(st_fast.queries);
    r.fallbacks = static_cast<double>(st_fast.fallbacks()) / static_cast<double>(st_fast.queries);
    r.margin = cached.margin();
    rows.push_back(r);
  }

  std::printf(
      "\nns: per query (static) or per node-cycle (_mot: %g mm/cycle; cach_fast: %g "
      "mm/cycle); cached static = node query whose list is built at the query\n",
      kSmallStep, kLargeStep);
  std::printf(
      "ratios: mod/std = modified_brute / standard_brute; cac/std, cac/mod = cached / "
      "standard, cached / modified per node-cycle (motion %g mm/cycle)\n\n",
      kSmallStep);

  std::printf("per query (brute force, mean over the counted queries):\n");
  std::printf("%9s %7s | %9s %9s %5s %5s %8s | %9s %9s %5s %5s %8s | %7s | %8s %8s %9s %9s %9s\n",
              "triangles", "nodes", "std_mult", "std_div", "sqrt", "tris", "node_d", "mod_mult",
              "mod_div", "sqrt", "tris", "offers", "mod/std", "std_miss", "cac_err", "cac_tests",
              "cac_rebld", "bld_tests");
  for (const OpsRow& o : op_rows) {
    const double q = o.counted;
    std::printf(
        "%9ld %7ld | %9.0f %9.1f %5.1f %5.1f %8.0f | %9.0f %9.1f %5.1f %5.0f %8.1f | %7.2f "
        "| %8.4f %8d %9.2f %9.5f %9.1f\n",
        o.triangles, o.nodes, o.std_ops.mult / q, o.std_ops.div / q, o.std_ops.sqrt / q,
        o.std_ops.kernels / q, o.std_ops.node_distances / q, o.mod_ops.mult / q, o.mod_ops.div / q,
        o.mod_ops.sqrt / q, o.mod_ops.kernels / q, o.mod_ops.offers / q,
        o.mod_ops.mult / o.std_ops.mult, static_cast<double>(o.misses) / static_n, o.mismatches,
        o.tests, o.rebuilds, o.build_tests);
  }
  std::printf(
      "(std_miss: fraction of the static queries where standard's triangle is not in "
      "modified's tie set; cac_err: static queries where cached differs from modified; "
      "cac_tests, cac_rebld: candidates tested and rebuilds per node-cycle, motion %g "
      "mm/cycle)\n",
      kSmallStep);

  std::printf(
      "\nmult / div / sqrt per query of the grid searches (2000 static points) and per "
      "node-cycle of cached (replica over the trajectories, list builds included):\n");
  std::printf("%9s | %18s %18s | %18s %18s | %9s\n", "triangles", "standard", "modified",
              "cached 1e-3", "cached 2e-2", "repl_ovf");
  for (const OpsRow& o : op_rows) {
    auto cell = [](const Ops& x, double qn) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%6.0f/%4.1f/%5.2f", x.mult / qn, x.div / qn, x.sqrt / qn);
      return std::string(buf);
    };
    std::printf("%9ld | %18s %18s | %18s %18s | %9ld\n", o.triangles,
                cell(o.std_grid, o.grid_counted).c_str(), cell(o.mod_grid, o.grid_counted).c_str(),
                cell(o.cached_small, o.motion_counted).c_str(),
                cell(o.cached_large, o.motion_counted).c_str(), o.replica_overflows);
  }
  std::printf("(repl_ovf: replica queries on overflowed lists, counted as grid queries)\n");

  // Margin study on the mesh closest to a 2 mm tool (16k triangles, mean edge ~2.4 mm).
  if (!quick) {
    const TriangleSurface tool = make_tool(90);
    const double edge = mean_edge(tool);
    std::printf(
        "\nmargin study, %d triangles (mean edge %.2f mm), capacity %d: ns per node-cycle "
        "[rebuilds per node-cycle, fallbacks per node-cycle, candidates tested per "
        "query]\n",
        tool.num_triangles(), edge, CachedSearch::default_capacity);
    std::printf("%12s %10s | %36s | %36s\n", "margin/edge", "margin mm", "1e-3 mm/cycle",
                "2e-2 mm/cycle");
    for (double f : {0.05, 0.1, 0.25, 0.5, 1.0, 2.0}) {
      CachedSearch c(tool, f * edge);
      std::unique_ptr<SearchCache> c_cache;
      const double t1 = time_motion(c, small_motion, nodes, c_cache);
      const auto s1 = c.statistics(*c_cache);
      const double t2 = time_motion(c, large_motion, nodes, c_cache);
      const auto s2 = c.statistics(*c_cache);
      auto per = [](long v, long qn) { return static_cast<double>(v) / static_cast<double>(qn); };
      std::printf("%12.2f %10.3f | %7.0f [%8.5f %8.5f %6.2f] | %7.0f [%8.5f %8.5f %6.2f]\n", f,
                  f * edge, t1, per(s1.rebuilds, s1.queries), per(s1.fallbacks(), s1.queries),
                  per(s1.candidates_tested, s1.queries), t2, per(s2.rebuilds, s2.queries),
                  per(s2.fallbacks(), s2.queries), per(s2.candidates_tested, s2.queries));
      Row r;
      r.triangles = tool.num_triangles();
      r.nodes = tool.num_nodes();
      r.search = "cached";
      r.queries = static_cast<long>(small_motion.size());
      r.margin = f * edge;
      r.mode = "margin_1e-3";
      r.ns = t1;
      r.tests = per(s1.candidates_tested, s1.queries);
      r.rebuilds = per(s1.rebuilds, s1.queries);
      r.fallbacks = per(s1.fallbacks(), s1.queries);
      rows.push_back(r);
      r.mode = "margin_2e-2";
      r.ns = t2;
      r.tests = per(s2.candidates_tested, s2.queries);
      r.rebuilds = per(s2.rebuilds, s2.queries);
      r.fallbacks = per(s2.fallbacks(), s2.queries);
      rows.push_back(r);
    }
  }
  write_csv(argv[1], rows);
  std::printf("\nwrote %s (checksum %g)\n", argv[1], g_sink);
  return 0;
}
