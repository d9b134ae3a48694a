// The search audit: misses of a deliberately wrong search are found, counted and measured.
// Exact answers: the closest point on a triangle by the independent Voronoi-region oracle
// (brute_force_oracle.hpp, Ericson 2005), so the expected gap errors are computed independently.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "brute_force_oracle.hpp"
#include "contact/search_audit.hpp"
#include "test_meshes.hpp"

namespace sf {
namespace {

/// A search that always answers with one fixed triangle (a caricature of a search that picks the
/// wrong triangle): its distance is the true distance to that triangle.
class FixedTriangleSearch final : public ContactSearch {
 public:
  FixedTriangleSearch(const TriangleSurface& s, int triangle) : s_(s), triangle_(triangle) {}
  void find_closest(const Vec3& p, double cutoff, ClosestPoint& out) const override {
    out = ClosestPoint{};
    const double d = oracle::distance_to_triangle(s_.nodes(), s_.triangles(), triangle_, p);
    if (d > cutoff) {
      return;
    }
    out.triangle = triangle_;
    out.distance = d;
    const Vec3 n = s_.triangle_normals().col(triangle_);
    const Vec3 q = oracle::closest_point_on_triangle(
        p, s_.nodes().col(s_.triangles()(0, triangle_)),
        s_.nodes().col(s_.triangles()(1, triangle_)), s_.nodes().col(s_.triangles()(2, triangle_)));
    out.signed_distance = (p - q).dot(n) >= 0 ? d : -d;
    out.set[0] = triangle_;
    out.set_size = 1;
  }
  std::string_view name() const override { return "fixed"; }

 private:
  const TriangleSurface& s_;
  int triangle_;
};

TEST(SearchAudit, CountsAndMeasuresTheMissesOfAWrongSearch) {
  // Flat tool z = 0 on [0, 4]^2 (4 x 4 cells, 32 triangles, normal +z); nodes 0.3 mm above it.
  const TriangleSurface s =
      test::make_height_field("die", 4, 4, 0, 4, 0, 4, [](double, double) { return 0.0; });
  const FixedTriangleSearch wrong(s, 0);  // triangle 0 = nodes (0,0), (1,0), (1,1)
  Matrix3X x(3, 4);
  x.col(0) = Vec3(0.8, 0.2, 0.3);            // above triangle 0: right answer
  x.col(1) = Vec3(3.5, 3.5, 0.3);            // far from triangle 0: a miss
  x.col(2) = Vec3(1.5, 0.5, 0.3);            // next cell: a miss
  x.col(3) = Vec3(2.0, 2.0, 5.0);            // beyond the cutoff: not checked
  const Vec3 tool_displacement(0, 0, -0.1);  // the tool moved down 0.1 mm: gaps 0.4 mm
  const double cutoff = 1.0;
  SearchAudit audit(s);
  VectorX miss, gap_error;
  const SearchAuditCount c =
      audit.run(wrong, x, {Mat3::Identity(), tool_displacement}, cutoff, miss, gap_error);
  EXPECT_EQ(c.nodes_checked, 3);
  EXPECT_EQ(c.misses, 2);
  EXPECT_EQ(miss[0], 0.0);
  EXPECT_EQ(miss[1], 1.0);
  EXPECT_EQ(miss[2], 1.0);
  EXPECT_EQ(miss[3], 0.0);
  // Gap error = the wrong triangle's distance - the exact one (0.4 mm), from the oracle.
  for (int i : {1, 2}) {
    const Vec3 p = x.col(i) - tool_displacement;
    const double expected = oracle::distance_to_triangle(s.nodes(), s.triangles(), 0, p) - 0.4;
    EXPECT_NEAR(gap_error[i], expected, 1e-12) << "node " << i;
    EXPECT_GT(gap_error[i], 0.0);
  }
  EXPECT_EQ(gap_error[0], 0.0);
  EXPECT_NEAR(c.max_gap_error, std::max(gap_error[1], gap_error[2]), 0.0);
}

TEST(SearchAudit, TheExactSearchHasNoMisses) {
  const TriangleSurface s = test::make_height_field(
      "punch", 12, 9, -5, 5, -4, 4, [](double x, double y) { return 0.3 * x * y - 0.1 * x * x; });
  const auto exact = make_contact_search("modified", s);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Matrix3X x(3, 500);
  for (int i = 0; i < x.cols(); ++i) {
    x.col(i) = Vec3(6 * u(rng), 5 * u(rng), 8 * u(rng));
  }
  SearchAudit audit(s);
  VectorX miss, gap_error;
  const SearchAuditCount c = audit.run(*exact, x, ToolPlacement{}, 2.0, miss, gap_error);
  EXPECT_GT(c.nodes_checked, 50);
  EXPECT_EQ(c.misses, 0);
  EXPECT_EQ(miss.sum(), 0.0);
}

}  // namespace
}  // namespace sf
