// The modified contact search (Wawrzyk & Kowalczyk, /work/shared/seed/modified-contact-search.txt)
// against the brute-force oracle (tests/contact/brute_force_oracle.hpp), and the contact
// configurations of /work/shared/REFERENCES.md ("Contact search: configurations every search must
// handle").
//
// Tolerances: distances agree within 1e-12 relative plus 1e-12 of the surface size (rounding in
// both codes is ~1e-16 relative; see detail::make_tie_tolerance); the reported triangle must be in
// the oracle's tie set built with the same tolerance (slightly widened, 4x, so that the oracle's
// own rounding cannot exclude a true tie).
#include <gtest/gtest.h>

#include <chrono>
#include <numbers>
#include <random>

#include "allocation_counter.hpp"
#include "brute_force_oracle.hpp"
#include "contact/contact_search.hpp"
#include "contact/modified_search.hpp"
#include "core/errors.hpp"
#include "test_meshes.hpp"

namespace sf {
namespace {

using Feature = ClosestPoint::Feature;
using test::make_fold;
using test::make_thin_trap;
using test::make_trap;
using test::random_points;
using test::warp;

/// Every search the factory makes.
constexpr const char* kAllSearches[] = {"standard", "standard_brute_force", "modified",
                                        "modified_brute_force", "cached"};

/// Makes `name` over s, prepared for one blank node: the configuration tests query node 0, so
/// that the cached search answers from its candidate list (the others from find_closest).
struct OneNodeSearch {
  std::unique_ptr<ContactSearch> search;
  std::unique_ptr<SearchCache> cache;  ///< for one node
  /// The query of node 0.
  void query(const Vec3& p, double cutoff, ClosestPoint& out) const {
    search->find_closest_for_node(cache.get(), 0, p, cutoff, out);
  }
};
OneNodeSearch make_for_one_node(const char* name, const TriangleSurface& s) {
  OneNodeSearch one{make_contact_search(name, s), nullptr};
  one.cache = one.search->make_cache(1);
  return one;
}

double surface_size(const TriangleSurface& s) {
  const Matrix3X& x = s.nodes();
  return std::max((x.rowwise().maxCoeff() - x.rowwise().minCoeff()).norm(),
                  x.cwiseAbs().maxCoeff());
}

bool contains(const std::vector<int>& v, int t) {
  return std::find(v.begin(), v.end(), t) != v.end();
}

/// Compares both searches with the oracle at every query point; returns the number of points
/// that found something within the cutoff.
int check_against_oracle(const TriangleSurface& s, const std::vector<Vec3>& points, double cutoff) {
  const double scale = surface_size(s);
  const auto modified = make_contact_search("modified", s);
  const auto brute = make_contact_search("modified_brute_force", s);
  int found = 0;
  for (const Vec3& p : points) {
    const auto want = oracle::closest(s.nodes(), s.triangles(), p, 0.0);
    const double tie = 4e-12 * (want.distance + scale);
    const auto ties = oracle::closest(s.nodes(), s.triangles(), p, tie).ties;
    for (const ContactSearch* search : {modified.get(), brute.get()}) {
      ClosestPoint cp;
      search->find_closest(p, cutoff, cp);
      SCOPED_TRACE(::testing::Message() << search->name() << " p = " << p.transpose()
                                        << " oracle distance " << want.distance);
      if (want.distance > cutoff * (1 + 1e-12) + 1e-12 * scale) {
        EXPECT_EQ(cp.triangle, -1);
        continue;
      }
      if (want.distance < cutoff * (1 - 1e-12) - 1e-12 * scale) {
        EXPECT_GE(cp.triangle, 0);
      }
      if (cp.triangle < 0) {
        continue;  // at the cutoff within rounding: either answer is right
      }
      EXPECT_NEAR(cp.distance, want.distance, 1e-12 * (want.distance + scale));
      EXPECT_TRUE(contains(ties, cp.triangle)) << "triangle " << cp.triangle;
      // The reported point lies on the reported triangle, at the reported distance.
      EXPECT_NEAR((p - cp.point).norm(), cp.distance, 1e-12 * (cp.distance + scale));
      EXPECT_NEAR(oracle::distance_to_triangle(s.nodes(), s.triangles(), cp.triangle, cp.point),
                  0.0, 1e-11 * scale);
      EXPECT_NEAR(std::abs(cp.signed_distance), cp.distance, 1e-15 * scale);
      EXPECT_NEAR(cp.normal.norm(), 1.0, 1e-12);
      // Every tie-set member is a true tie.
      for (int i = 0; i < cp.set_size; ++i) {
        EXPECT_TRUE(contains(ties, cp.set[i])) << "set member " << cp.set[i];
      }
      // The tie set is complete (up to the cap) ...
      if (!cp.set_truncated) {
        const double strict = 0.25e-12 * (want.distance + scale);
        for (int t : oracle::closest(s.nodes(), s.triangles(), p, strict).ties) {
          EXPECT_TRUE(std::find(cp.set.begin(), cp.set.begin() + cp.set_size, t) !=
                      cp.set.begin() + cp.set_size)
              << "tie " << t << " missing from the set";
        }
      }
      if (search == modified.get()) {
        ++found;
      }
    }
  }
  return found;
}

TEST(ModifiedSearch, RandomSoupMatchesOracle) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const TriangleSurface s = test::make_random_soup(300, seed);
    const auto pts = random_points(1500, Vec3::Constant(-0.5), Vec3::Constant(1.5), 10 + seed);
    EXPECT_EQ(check_against_oracle(s, pts, std::numeric_limits<double>::infinity()), 1500);
  }
}

TEST(ModifiedSearch, RandomSoupFiniteCutoff) {
  // With cutoff 0.05 some points find a triangle and some find none: both branches are checked.
  const TriangleSurface s = test::make_random_soup(200, 7);
  const auto pts = random_points(3000, Vec3::Constant(-0.3), Vec3::Constant(1.3), 77);
  const int found = check_against_oracle(s, pts, 0.05);
  EXPECT_GT(found, 100);
  EXPECT_LT(found, 2900);
}

TEST(ModifiedSearch, RefinedWarpedSurfaceMatchesOracle) {
  const TriangleSurface s = test::make_height_field("refined", 40, 40, -1, 1, -1, 1, warp);
  // Above, below and off the edges of the surface.
  const auto pts = random_points(3000, Vec3(-1.5, -1.5, -1.0), Vec3(1.5, 1.5, 1.0), 5);
  EXPECT_EQ(check_against_oracle(s, pts, std::numeric_limits<double>::infinity()), 3000);
  const int found = check_against_oracle(s, pts, 0.1);
  EXPECT_GT(found, 100);
  EXPECT_LT(found, 2900);
}

TEST(ModifiedSearch, CoarseWarpedSurfaceMatchesOracle) {
  const TriangleSurface s = test::make_height_field("coarse", 3, 4, -1, 1, -1, 1, warp);
  const auto pts = random_points(3000, Vec3(-1.5, -1.5, -1.0), Vec3(1.5, 1.5, 1.0), 6);
  EXPECT_EQ(check_against_oracle(s, pts, std::numeric_limits<double>::infinity()), 3000);
  check_against_oracle(s, pts, 0.2);
}

TEST(ModifiedSearch, PaperTrapClosestNodeNotOnContactTriangle) {
  const TriangleSurface s = make_trap();
  const Vec3 p(0, -0.2, 0.8);
  // The configuration is a trap: the closest node (K = 3) is not a vertex of the triangle
  // holding the projection (N_min = 0).
  int closest_node = 0;
  for (int i = 1; i < s.num_nodes(); ++i) {
    if ((s.nodes().col(i) - p).norm() < (s.nodes().col(closest_node) - p).norm()) {
      closest_node = i;
    }
  }
  ASSERT_EQ(closest_node, 3);
  const auto want = oracle::closest(s.nodes(), s.triangles(), p, 1e-12);
  ASSERT_EQ(want.ties, std::vector<int>{0});
  for (const char* name : {"modified", "modified_brute_force"}) {
    const auto search = make_contact_search(name, s);
    ClosestPoint cp;
    search->find_closest(p, std::numeric_limits<double>::infinity(), cp);
    EXPECT_EQ(cp.triangle, 0) << name;
    EXPECT_EQ(cp.feature, Feature::face) << name;
    EXPECT_NEAR(cp.distance, want.distance, 1e-12) << name;
  }
}

TEST(ModifiedSearch, ThinTriangleTrapsMatchOracle) {
  // Adversarial: fans of long thin triangles beside small ones, randomly perturbed heights.
  const TriangleSurface s = make_thin_trap();
  const auto pts = random_points(4000, Vec3(-1.5, -2.5, -1), Vec3(1.5, 2.5, 1), 9);
  EXPECT_EQ(check_against_oracle(s, pts, std::numeric_limits<double>::infinity()), 4000);
  check_against_oracle(s, pts, 0.05);
}

TEST(ContactConfigurations, ConcaveFoldDeadZone) {
  // Valley z = |y| (normals up, into the valley). A node that has gone through the fold to
  // (0, 0.1, -0.5) projects onto neither face's interior (dead zone): the contact must be found
  // anyway, at the fold edge, with gap = -distance to the fold edge.
  const TriangleSurface s = make_fold(1.0);
  for (const char* name : kAllSearches) {
    const auto search = make_for_one_node(name, s);
    const Vec3 p(0.2, 0.1, -0.5);
    ClosestPoint cp;
    search.query(p, 2.0, cp);
    ASSERT_GE(cp.triangle, 0) << name;
    EXPECT_EQ(cp.feature, Feature::edge) << name;
    EXPECT_NEAR(cp.distance, std::hypot(0.1, 0.5), 1e-14) << name;
    EXPECT_NEAR(cp.signed_distance, -std::hypot(0.1, 0.5), 1e-14) << name;
    EXPECT_NEAR((cp.point - Vec3(0.2, 0, 0)).norm(), 0.0, 1e-14) << name;
    // Normal = gradient of the signed distance: from p back toward the fold, i.e. out of the
    // material on the positive side.
    EXPECT_NEAR((cp.normal - Vec3(0, -0.1, 0.5).normalized()).norm(), 0.0, 1e-14) << name;
    EXPECT_EQ(cp.set_size, 2) << name;
  }
}

TEST(ContactConfigurations, ConvexRidgeNormalIsContinuous) {
  // Ridge z = -0.5 |y| seen from above: a point at constant height 0.3 above the ridge line
  // sweeps across it; the normal and the distance must vary continuously (no jump larger than
  // the sweep step allows: |dn| <= |dp| / D for the edge region, |dn| = 0 on the faces).
  const TriangleSurface s = make_fold(-0.5);
  for (const char* name : kAllSearches) {
    SCOPED_TRACE(name);
    const auto search = make_for_one_node(name, s);
    ClosestPoint prev, cp;
    const int steps = 2000;
    const double dy = 1.0 / steps;
    double max_jump = 0;
    for (int k = 0; k <= steps; ++k) {
      const Vec3 p(0.1, -0.5 + k * dy, 0.3);
      search.query(p, 5.0, cp);
      ASSERT_GE(cp.triangle, 0);
      EXPECT_GT(cp.signed_distance, 0);
      if (k > 0) {
        max_jump = std::max(max_jump, (cp.normal - prev.normal).norm());
        EXPECT_LT(std::abs(cp.distance - prev.distance), 1.01 * dy);
      }
      prev = cp;
    }
    EXPECT_LT(max_jump, 1.01 * dy / 0.3);
    // Over the ridge line the normal is +z, and far on either side the face normals.
    search.query(Vec3(0.1, 0, 0.3), 5.0, cp);
    EXPECT_NEAR((cp.normal - Vec3::UnitZ()).norm(), 0.0, 1e-14);
    EXPECT_EQ(cp.set_size, 2);
    search.query(Vec3(0.1, 0.5, 0.3), 5.0, cp);
    EXPECT_EQ(cp.feature, Feature::face);
    EXPECT_NEAR((cp.normal - s.triangle_normals().col(cp.triangle)).norm(), 0.0, 1e-14);
  }
}

TEST(ContactConfigurations, ExactEdgeHitGivesBothTriangles) {
  const TriangleSurface s =
      test::make_height_field("flat", 4, 4, 0, 4, 0, 4, [](double, double) { return 0.0; });
  for (const char* name : kAllSearches) {
    const auto search = make_for_one_node(name, s);
    ClosestPoint cp;
    // Cell (0, 0) is split by its diagonal (0,0)-(1,1): the point above (0.3, 0.3) is on it.
    for (double h : {0.7, 0.0, -0.4}) {
      search.query(Vec3(0.3, 0.3, h), 1.0, cp);
      EXPECT_EQ(cp.set_size, 2) << name << " h = " << h;
      EXPECT_EQ(cp.set[0], 0);
      EXPECT_EQ(cp.set[1], 1);
      EXPECT_EQ(cp.feature, Feature::edge) << name;
      EXPECT_NEAR(cp.signed_distance, h, 1e-15);
      EXPECT_NEAR((cp.normal - Vec3::UnitZ()).norm(), 0.0, 1e-15);
    }
  }
}

TEST(ContactConfigurations, ExactVertexHitGivesAllTrianglesAtTheVertex) {
  // Flat: node (2, 2) of a 4 x 4 height field; pyramid apex: a warped node.
  for (double apex : {0.0, 0.4}) {
    const TriangleSurface s = test::make_height_field(
        "vertex", 4, 4, 0, 4, 0, 4,
        [apex](double x, double y) { return (x == 2 && y == 2) ? apex : 0.0; });
    const int node = 2 * 5 + 2;
    std::vector<int> expected(s.node_triangles().begin() + s.node_triangle_offsets()[node],
                              s.node_triangles().begin() + s.node_triangle_offsets()[node + 1]);
    ASSERT_GE(expected.size(), 4u);
    for (const char* name : kAllSearches) {
      const auto search = make_for_one_node(name, s);
      ClosestPoint cp;
      search.query(Vec3(2, 2, apex + 0.5), 2.0, cp);
      ASSERT_EQ(cp.set_size, static_cast<int>(expected.size())) << name;
      EXPECT_TRUE(std::equal(expected.begin(), expected.end(), cp.set.begin())) << name;
      EXPECT_EQ(cp.feature, Feature::vertex) << name;
      EXPECT_NEAR(cp.distance, 0.5, 1e-14);
      EXPECT_NEAR((cp.point - Vec3(2, 2, apex)).norm(), 0.0, 1e-14);
    }
  }
}

TEST(ContactConfigurations, NothingWithinCutoff) {
  const TriangleSurface s =
      test::make_height_field("flat", 4, 4, 0, 4, 0, 4, [](double, double) { return 0.0; });
  for (const char* name : kAllSearches) {
    const auto search = make_for_one_node(name, s);
    ClosestPoint cp;
    search.query(Vec3(2, 2, 1.5), 1.0, cp);
    EXPECT_EQ(cp.triangle, -1) << name;
    EXPECT_EQ(cp.set_size, 0) << name;
    search.query(Vec3(2, 2, 0.9), 1.0, cp);
    EXPECT_GE(cp.triangle, 0) << name;
    search.query(Vec3(50, 2, 0), 1.0, cp);  // far off the grid
    EXPECT_EQ(cp.triangle, -1) << name;
    search.query(Vec3(50, 2, 0), std::numeric_limits<double>::infinity(), cp);
    EXPECT_NEAR(cp.distance, 46.0, 1e-12) << name;
  }
}

TEST(ModifiedSearch, FactoryNamesAndErrors) {
  const TriangleSurface s = make_trap();
  for (const char* name : kAllSearches) {
    EXPECT_EQ(make_contact_search(name, s)->name(), name);
  }
  try {
    make_contact_search("closest_node", s);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "standard, standard_brute_force, modified, modified_brute_force, cached"),
              std::string::npos);
    EXPECT_NE(std::string(e.what()).find("closest_node"), std::string::npos);
  }
}

TEST(ModifiedSearch, QueriesDoNotAllocate) {
  const TriangleSurface s = test::make_height_field("refined", 20, 20, -1, 1, -1, 1, warp);
  const auto pts = random_points(500, Vec3(-1.5, -1.5, -1), Vec3(1.5, 1.5, 1), 3);
  const auto modified = make_contact_search("modified", s);
  const auto brute = make_contact_search("modified_brute_force", s);
  ClosestPoint cp;
  const long before = test::allocation_count();
  double sum = 0;
  for (const Vec3& p : pts) {
    modified->find_closest(p, 0.2, cp);
    sum += cp.distance;
    brute->find_closest(p, std::numeric_limits<double>::infinity(), cp);
    sum += cp.distance;
  }
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_GT(sum, 0);
}

TEST(ModifiedSearch, CostOnFiveThousandTriangles) {
  // Not a gate: prints ns per query on a 50 x 50 x 2 = 5000-triangle warped tool (mm), for the
  // record; only checks that the grid is faster than the brute force.
  const TriangleSurface s = test::make_height_field(
      "punch", 50, 50, -100, 100, -100, 100,
      [](double x, double y) { return 20.0 * std::exp(-(x * x + y * y) / 5000.0); });
  // Points within +-1 mm of the surface (where blank nodes are during forming).
  auto pts = random_points(20000, Vec3(-100, -100, -1), Vec3(100, 100, 1), 4);
  for (Vec3& p : pts) {
    p.z() += 20.0 * std::exp(-(p.x() * p.x() + p.y() * p.y()) / 5000.0);
  }
  auto time = [&](const ContactSearch& search, double cutoff, int n) {
    ClosestPoint cp;
    double sum = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < n; ++k) {
      search.find_closest(pts[k], cutoff, cp);
      sum += cp.triangle;
    }
    const auto t1 = std::chrono::steady_clock::now();
    EXPECT_NE(sum, 0.5);
    return std::chrono::duration<double, std::nano>(t1 - t0).count() / n;
  };
  const auto modified = make_contact_search("modified", s);
  const auto brute = make_contact_search("modified_brute_force", s);
  const double ns_grid_1 = time(*modified, 1.0, 20000);
  const double ns_grid_inf = time(*modified, std::numeric_limits<double>::infinity(), 20000);
  const double ns_brute = time(*brute, std::numeric_limits<double>::infinity(), 1000);
  std::printf(
      "5000 triangles: modified (grid) %.0f ns/query (cutoff 1 mm), %.0f ns/query "
      "(no cutoff); modified_brute_force %.0f ns/query\n",
      ns_grid_1, ns_grid_inf, ns_brute);
  EXPECT_LT(ns_grid_inf, ns_brute);
}

}  // namespace
}  // namespace sf
