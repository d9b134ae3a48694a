// surface_boundary: free edges, boundaries and their length on surfaces of exact geometry (a
// closed sphere, an open hemisphere, a cylindrical band, flat patches apart and touching).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesh/surface_boundary.hpp"
#include "support/surface_builder.hpp"

namespace sf {
namespace {

TEST(SurfaceBoundary, ClosedSphereHasNoFreeEdge) {
  test::SurfaceBuilder b;
  b.add_sphere(Vec3(1, 2, 3), 5.0, 6, 12, std::numbers::pi);
  const SurfaceBoundary boundary = surface_boundary(b.build());
  EXPECT_TRUE(boundary.closed());
  EXPECT_EQ(boundary.free_edges, 0);
  EXPECT_EQ(boundary.boundaries, 0);
  EXPECT_EQ(boundary.length, 0.0);
}

TEST(SurfaceBoundary, HemisphereHasOneBoundaryTheEquatorPolygon) {
  // The lower half (polar angle up to pi/2): its rim is the regular 16-gon of radius r, whose
  // perimeter is 16 x 2 r sin(pi/16).
  const double r = 7.5;
  test::SurfaceBuilder b;
  b.add_sphere(Vec3::Zero(), r, 4, 16, 0.5 * std::numbers::pi);
  const SurfaceBoundary boundary = surface_boundary(b.build());
  EXPECT_FALSE(boundary.closed());
  EXPECT_EQ(boundary.free_edges, 16);
  EXPECT_EQ(boundary.boundaries, 1);
  EXPECT_NEAR(boundary.length, 16 * 2 * r * std::sin(std::numbers::pi / 16), 1e-12 * r);
}

TEST(SurfaceBoundary, CylindricalBandHasTwoRims) {
  // A band around the z axis, 12 segments closed on themselves, 3 rows high: the two rims are
  // 12-gons of radius R.
  const double radius = 20.0;
  test::SurfaceBuilder b;
  b.add_patch(
      12, 3,
      [radius](double u, double v) {
        const double a = 2 * std::numbers::pi * u;
        return Vec3(radius * std::cos(a), radius * std::sin(a), 10 * v);
      },
      false, true);
  const SurfaceBoundary boundary = surface_boundary(b.build());
  EXPECT_EQ(boundary.free_edges, 24);
  EXPECT_EQ(boundary.boundaries, 2);
  EXPECT_NEAR(boundary.length, 2 * 12 * 2 * radius * std::sin(std::numbers::pi / 12),
              1e-12 * radius);
}

TEST(SurfaceBoundary, PatchesApartHaveABoundaryEachAndTouchingOnesShareOne) {
  test::SurfaceBuilder apart;
  apart.add_patch(4, 2, test::rectangle(0, 4, 0, 2, 0));    // perimeter 12, 12 edges
  apart.add_patch(3, 3, test::rectangle(10, 13, 0, 3, 0));  // perimeter 12, 12 edges
  SurfaceBoundary boundary = surface_boundary(apart.build());
  EXPECT_EQ(boundary.free_edges, 24);
  EXPECT_EQ(boundary.boundaries, 2);
  EXPECT_NEAR(boundary.length, 24.0, 1e-12);
  // Two unit squares meeting at the corner (1, 1): joined there, their outlines are one set of
  // free edges (SurfaceBoundary::boundaries counts connected sets).
  test::SurfaceBuilder touching;
  touching.add_patch(1, 1, test::rectangle(0, 1, 0, 1, 0));
  touching.add_patch(1, 1, test::rectangle(1, 2, 1, 2, 0));
  boundary = surface_boundary(touching.joined(1e-9).build());
  EXPECT_EQ(boundary.free_edges, 8);
  EXPECT_EQ(boundary.boundaries, 1);
  EXPECT_NEAR(boundary.length, 8.0, 1e-12);
}

}  // namespace
}  // namespace sf
