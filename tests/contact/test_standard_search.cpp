// The standard contact search (Benson & Hallquist 1990; Wriggers 2002): the triangles around the
// tool node closest to the point. Checked here: the grid variant gives exactly the brute-force
// answer; against the oracle (tests/contact/brute_force_oracle.hpp) it is right whenever its
// triangle is a true closest one, and its misses are counted: some on adversarial meshes (the
// trap of Wawrzyk & Kowalczyk, /work/shared/seed/modified-contact-search.txt), none on a flat
// regular mesh where it provably cannot miss. The configurations of /work/shared/REFERENCES.md
// are in test_search.cpp (run for every search).
#include <gtest/gtest.h>

#include <cstdio>
#include <limits>
#include <string>

#include "allocation_counter.hpp"
#include "brute_force_oracle.hpp"
#include "closest_point_comparison.hpp"
#include "contact/contact_search.hpp"
#include "contact/standard_search.hpp"
#include "test_meshes.hpp"

namespace sf {
namespace {

using test::random_points;
using test::warp;
constexpr double kInf = std::numeric_limits<double>::infinity();

double surface_size(const TriangleSurface& s) {
  const Matrix3X& x = s.nodes();
  return std::max((x.rowwise().maxCoeff() - x.rowwise().minCoeff()).norm(),
                  x.cwiseAbs().maxCoeff());
}

bool contains(const std::vector<int>& v, int t) {
  return std::find(v.begin(), v.end(), t) != v.end();
}

/// Every field of "standard" equals "standard_brute_force" at every point.
void expect_grid_equals_brute_force(const TriangleSurface& s, const std::vector<Vec3>& points) {
  const auto grid = make_contact_search("standard", s);
  const auto brute = make_contact_search("standard_brute_force", s);
  for (double cutoff : {kInf, 0.05, 0.2, 0.5}) {
    int found = 0;
    for (const Vec3& p : points) {
      ClosestPoint a, b;
      grid->find_closest(p, cutoff, a);
      brute->find_closest(p, cutoff, b);
      ASSERT_TRUE(test::identical(a, b))
          << s.name() << " cutoff " << cutoff << " p " << p.transpose();
      found += a.triangle >= 0 ? 1 : 0;
    }
    if (cutoff == kInf) {
      EXPECT_EQ(found, static_cast<int>(points.size())) << s.name();
    }
  }
}

struct Misses {
  int queries = 0;  ///< points with a triangle within the cutoff (oracle)
  int misses = 0;   ///< of those, answers whose triangle is not a true closest one
};

/// Compares "standard" with the oracle: when its triangle is in the oracle's tie set its distance
/// is the least distance; otherwise (a miss: a wrong triangle, or none within the cutoff) its
/// distance is larger than the least one. Prints and returns the count of misses.
Misses count_standard_misses(const TriangleSurface& s, const std::vector<Vec3>& points,
                             double cutoff) {
  const double scale = surface_size(s);
  const auto standard = make_contact_search("standard", s);
  Misses m;
  for (const Vec3& p : points) {
    const auto want = oracle::closest(s.nodes(), s.triangles(), p, 0.0);
    const double tie = 4e-12 * (want.distance + scale);
    const auto ties = oracle::closest(s.nodes(), s.triangles(), p, tie).ties;
    ClosestPoint cp;
    standard->find_closest(p, cutoff, cp);
    SCOPED_TRACE(::testing::Message()
                 << s.name() << " p = " << p.transpose() << " oracle distance " << want.distance);
    if (want.distance > cutoff * (1 + 1e-12) + 1e-12 * scale) {
      EXPECT_EQ(cp.triangle, -1);  // nothing is closer than the least distance
      continue;
    }
    if (want.distance > cutoff * (1 - 1e-12) - 1e-12 * scale) {
      continue;  // at the cutoff within rounding
    }
    ++m.queries;
    if (cp.triangle >= 0 && contains(ties, cp.triangle)) {
      EXPECT_NEAR(cp.distance, want.distance, 1e-12 * (want.distance + scale));
      for (int i = 0; i < cp.set_size; ++i) {
        EXPECT_TRUE(contains(ties, cp.set[i])) << "set member " << cp.set[i];
      }
    } else {
      ++m.misses;
      if (cp.triangle >= 0) {
        EXPECT_GT(cp.distance, want.distance);
        EXPECT_NEAR(oracle::distance_to_triangle(s.nodes(), s.triangles(), cp.triangle, p),
                    cp.distance, 1e-12 * (cp.distance + scale));
      }
    }
  }
  std::printf("standard misses %d of %d queries on the %s mesh (cutoff %g)\n", m.misses, m.queries,
              s.name().c_str(), cutoff);
  return m;
}

TEST(StandardSearch, GridMatchesBruteForceOnRandomSoups) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const TriangleSurface s = test::make_random_soup(300, seed);
    expect_grid_equals_brute_force(
        s, random_points(1500, Vec3::Constant(-0.5), Vec3::Constant(1.5), 20 + seed));
  }
}

TEST(StandardSearch, GridMatchesBruteForceOnWarpedAndTrapMeshes) {
  const auto pts = random_points(3000, Vec3(-1.5, -1.5, -1.0), Vec3(1.5, 1.5, 1.0), 31);
  expect_grid_equals_brute_force(test::make_height_field("refined", 40, 40, -1, 1, -1, 1, warp),
                                 pts);
  expect_grid_equals_brute_force(test::make_height_field("coarse", 3, 4, -1, 1, -1, 1, warp), pts);
  expect_grid_equals_brute_force(test::make_thin_trap(),
                                 random_points(3000, Vec3(-1.5, -2.5, -1), Vec3(1.5, 2.5, 1), 32));
  expect_grid_equals_brute_force(test::make_trap(),
                                 random_points(3000, Vec3(-12, -4, -3), Vec3(12, 5, 3), 33));
}

TEST(StandardSearch, NodesWithoutTrianglesAreNotCandidates) {
  // A loose node right at the query point: both variants look past it.
  const TriangleSurface flat =
      test::make_height_field("flat", 4, 4, 0, 4, 0, 4, [](double, double) { return 0.0; });
  Matrix3X x(3, flat.num_nodes() + 1);
  x << flat.nodes(), Vec3(1.3, 1.4, 0.5);
  const TriangleSurface s("loose node", x, flat.triangles());
  for (const char* name : {"standard", "standard_brute_force"}) {
    const auto search = make_contact_search(name, s);
    ClosestPoint cp;
    search->find_closest(Vec3(1.3, 1.4, 0.5), kInf, cp);
    ASSERT_GE(cp.triangle, 0) << name;
    EXPECT_NEAR(cp.distance, 0.5, 1e-15) << name;
  }
}

TEST(StandardSearch, MissesCountedOnAdversarialMeshes) {
  // The modified search finds the closest triangle on all of these (test_search.cpp); the
  // standard search must miss on some points of each, and be right whenever its triangle is a
  // closest one.
  const auto box = random_points(2000, Vec3(-1.5, -1.5, -1.0), Vec3(1.5, 1.5, 1.0), 41);
  const TriangleSurface coarse = test::make_height_field("coarse warped", 3, 4, -1, 1, -1, 1, warp);
  EXPECT_GT(count_standard_misses(coarse, box, kInf).misses, 0);
  // With a cutoff, points near the surface (as blank nodes in contact are).
  auto slab = random_points(2000, Vec3(-1.2, -1.2, -0.3), Vec3(1.2, 1.2, 0.3), 45);
  for (Vec3& q : slab) {
    q.z() += warp(q.x(), q.y());
  }
  EXPECT_GT(count_standard_misses(coarse, slab, 0.3).misses, 0);
  const TriangleSurface thin = test::make_thin_trap();
  EXPECT_GT(count_standard_misses(
                thin, random_points(2000, Vec3(-1.5, -2.5, -1), Vec3(1.5, 2.5, 1), 42), kInf)
                .misses,
            0);
  const TriangleSurface soup = test::make_random_soup(300, 4);
  EXPECT_GT(count_standard_misses(
                soup, random_points(2000, Vec3::Constant(-0.5), Vec3::Constant(1.5), 43), kInf)
                .misses,
            0);
  // A smooth, refined mesh: printed for the record, no claim.
  count_standard_misses(test::make_height_field("refined warped", 40, 40, -1, 1, -1, 1, warp), box,
                        kInf);
}

TEST(StandardSearch, NoMissOnFlatRegularMesh) {
  // Flat mesh of unit-aspect square cells, each split by a diagonal (alternating). Why the
  // standard search cannot miss here: for a plane, |p - x|^2 = h^2 + |p' - x|^2 (p' the in-plane
  // projection of p, h its height), so the closest node to p is the closest lattice node to p',
  // found per axis: i = clamp(round(x')), j = clamp(round(y')); it is also the closest node to
  // the closest point q = (clamp(x'), clamp(y')). q lies in a cell and the closest node is the
  // cell corner in q's quadrant of the cell. The corner missing from q's triangle is always the
  // one on the far side of the diagonal from q: with the diagonal (0,0)-(1,1), the lower triangle
  // (y <= x) lacks (0,1), which is the closest corner only when x < 1/2 < y, i.e. y > x; the
  // other diagonal likewise. On the boundary q lies on a boundary edge, whose two nodes belong to
  // its triangle. Near-ties between corners only occur where both corners belong to q's triangle,
  // or (at the cell centre) where q lies on the diagonal, in both triangles within the tie
  // tolerance.
  const TriangleSurface s = test::make_height_field("flat regular", 20, 20, -1, 1, -1, 1,
                                                    [](double, double) { return 0.0; });
  const auto pts = random_points(2000, Vec3(-1.5, -1.5, -1.0), Vec3(1.5, 1.5, 1.0), 44);
  const Misses inf = count_standard_misses(s, pts, kInf);
  EXPECT_EQ(inf.queries, 2000);
  EXPECT_EQ(inf.misses, 0);
  const Misses finite = count_standard_misses(s, pts, 0.3);
  EXPECT_GT(finite.queries, 100);
  EXPECT_EQ(finite.misses, 0);
}

TEST(StandardSearch, PaperTrapPicksTheWrongTriangle) {
  // The seed's figure 1 (REFERENCES.md configuration 1): the closest node K = 3 is not a vertex
  // of N_min = triangle 0, which holds the projection; the standard search takes a triangle
  // around K, farther than N_min; the modified search takes N_min.
  const TriangleSurface s = test::make_trap();
  const Vec3 p(0, -0.2, 0.8);
  const auto want = oracle::closest(s.nodes(), s.triangles(), p, 1e-12);
  ASSERT_EQ(want.ties, std::vector<int>{0});
  for (const char* name : {"standard", "standard_brute_force"}) {
    const auto search = make_contact_search(name, s);
    ClosestPoint cp;
    search->find_closest(p, kInf, cp);
    ASSERT_GE(cp.triangle, 0) << name;
    EXPECT_NE(cp.triangle, 0) << name;
    const int k_first = s.node_triangle_offsets()[3], k_last = s.node_triangle_offsets()[4];
    EXPECT_TRUE(contains(
        std::vector<int>(s.node_triangles().begin() + k_first, s.node_triangles().begin() + k_last),
        cp.triangle))
        << name;
    EXPECT_GT(cp.distance, want.distance + 0.1) << name;
    std::printf("%s on the trap: triangle %d at %.4f mm; the closest, triangle 0, at %.4f mm\n",
                name, cp.triangle, cp.distance, want.distance);
  }
  const auto modified = make_contact_search("modified", s);
  ClosestPoint cp;
  modified->find_closest(p, kInf, cp);
  EXPECT_EQ(cp.triangle, 0);
  EXPECT_NEAR(cp.distance, want.distance, 1e-12);
}

TEST(StandardSearch, QueriesDoNotAllocate) {
  const TriangleSurface s = test::make_height_field("refined", 20, 20, -1, 1, -1, 1, warp);
  const auto pts = random_points(500, Vec3(-1.5, -1.5, -1), Vec3(1.5, 1.5, 1), 3);
  const auto grid = make_contact_search("standard", s);
  const auto brute = make_contact_search("standard_brute_force", s);
  ClosestPoint cp;
  const long before = test::allocation_count();
  double sum = 0;
  for (const Vec3& p : pts) {
    grid->find_closest(p, 0.2, cp);
    sum += cp.distance;
    grid->find_closest(p, kInf, cp);
    sum += cp.distance;
    brute->find_closest(p, kInf, cp);
    sum += cp.distance;
  }
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_GT(sum, 0);
}

}  // namespace
}  // namespace sf
