// The closest-point kernels of the tool diagnosis and the clearance: exact answers in each region
// of a triangle and for segments skew, parallel or degenerate; triangle pairs against a dense
// sampling (the exact answer is never above it and at most its spacing below).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "mesh/triangle_distance.hpp"

namespace sf {
namespace {

Tri3 triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  Tri3 t;
  t << a, b, c;
  return t;
}

void expect_point(const Vec3& actual, const Vec3& expected) {
  EXPECT_NEAR((actual - expected).norm(), 0.0, 1e-15) << actual.transpose();
}

TEST(TriangleDistance, ClosestPointInEachRegion) {
  const Tri3 t = triangle({0, 0, 0}, {2, 0, 0}, {0, 2, 0});
  expect_point(closest_point_on_triangle({0.5, 0.5, 3}, t), {0.5, 0.5, 0});  // face
  expect_point(closest_point_on_triangle({-1, -1, 1}, t), {0, 0, 0});        // vertex
  expect_point(closest_point_on_triangle({3, -1, 0}, t), {2, 0, 0});
  expect_point(closest_point_on_triangle({-1, 3, 0}, t), {0, 2, 0});
  expect_point(closest_point_on_triangle({1, -1, 1}, t), {1, 0, 0});  // edges
  expect_point(closest_point_on_triangle({-1, 1, 0}, t), {0, 1, 0});
  expect_point(closest_point_on_triangle({2, 2, 0}, t), {1, 1, 0});
}

TEST(TriangleDistance, SegmentsSkewParallelAndDegenerate) {
  ClosestPair c = closest_segment_points({-1, 0, 0}, {1, 0, 0}, {0, -1, 1}, {0, 1, 1});
  EXPECT_EQ(c.distance, 1.0);
  expect_point(c.first, {0, 0, 0});
  expect_point(c.second, {0, 0, 1});
  c = closest_segment_points({0, 0, 0}, {2, 0, 0}, {1, 0.5, 0}, {3, 0.5, 0});  // parallel
  EXPECT_EQ(c.distance, 0.5);
  c = closest_segment_points({0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {4, 0, 0});  // in line, apart
  EXPECT_EQ(c.distance, 2.0);
  expect_point(c.first, {1, 0, 0});
  c = closest_segment_points({1, 1, 0}, {1, 1, 0}, {0, 0, 0}, {2, 0, 0});  // a point
  EXPECT_EQ(c.distance, 1.0);
  expect_point(c.second, {1, 0, 0});
}

TEST(TriangleDistance, CrossingAndInsideMargin) {
  const Tri3 t = triangle({0, 0, 0}, {3, 0, 0}, {0, 4, 0});
  const auto p = segment_triangle_crossing({1, 1, -1}, {1, 1, 3}, t);
  ASSERT_TRUE(p.has_value());
  expect_point(*p, {1, 1, 0});
  EXPECT_FALSE(segment_triangle_crossing({3, 3, -1}, {3, 3, 1}, t));  // beside it
  EXPECT_FALSE(segment_triangle_crossing({1, 1, 1}, {1, 1, 3}, t));   // above it
  // The 3-4-5 right triangle's incircle has radius (3 + 4 - 5) / 2 = 1, centre (1, 1).
  EXPECT_NEAR(inside_margin({1, 1, 0}, t), 1.0, 1e-15);
  EXPECT_NEAR(inside_margin({-0.5, 1, 0}, t), -0.5, 1e-15);
  const ClosestPair crossing =
      closest_triangle_points(t, triangle({1, 1, -1}, {1, 1, 3}, {1.5, 0.5, 3}));
  EXPECT_EQ(crossing.distance, 0.0);
}

TEST(TriangleDistance, TrianglePairsAgainstSampling) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto random_point = [&](double shift) { return Vec3(u(rng), u(rng), u(rng) + shift); };
  constexpr int n = 40;  // samples of a: barycentric grid with spacing 1/n
  for (int pair = 0; pair < 200; ++pair) {
    const double shift = 0.5 * (pair % 6);
    const Tri3 a = triangle(random_point(0), random_point(0), random_point(0));
    const Tri3 b = triangle(random_point(shift), random_point(shift), random_point(shift));
    const ClosestPair exact = closest_triangle_points(a, b);
    EXPECT_NEAR((exact.first - exact.second).norm(), exact.distance, 1e-15);
    double sampled = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        const Vec3 p = a.col(0) + (a.col(1) - a.col(0)) * i / n + (a.col(2) - a.col(0)) * j / n;
        sampled = std::min(sampled, (closest_point_on_triangle(p, b) - p).norm());
      }
    }
    // A sample lies within the spacing of a's longest edge / n of every point of a.
    const double spacing = std::max({(a.col(1) - a.col(0)).norm(), (a.col(2) - a.col(0)).norm(),
                                     (a.col(2) - a.col(1)).norm()}) /
                           n;
    EXPECT_LE(exact.distance, sampled + 1e-12) << "pair " << pair;
    EXPECT_GE(exact.distance, sampled - spacing) << "pair " << pair;
  }
}

}  // namespace
}  // namespace sf
