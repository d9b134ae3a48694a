// closest_approach: the distance from a tool to a shell's mid-surface, exact for the geometry built
// here (planes, a sphere's pole, crossed ridges whose closest points lie inside two edges), where
// it is reached, and which way the tool faces there.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "mesh/surface_approach.hpp"
#include "support/surface_builder.hpp"

namespace sf {
namespace {

using test::rectangle;
using test::SurfaceBuilder;

// A flat blank of 10 x 10 quadrilaterals on [0, 10] x [0, 10] at z = 0.
struct Shell {
  Matrix3X nodes;
  QuadConn quads;
  TriConn triangles = TriConn(3, 0);
};
Shell flat_blank() {
  Shell s;
  s.nodes.resize(3, 121);
  s.quads.resize(4, 100);
  for (int j = 0; j <= 10; ++j) {
    for (int i = 0; i <= 10; ++i) {
      s.nodes.col(11 * j + i) = Vec3(i, j, 0);
    }
  }
  for (int j = 0; j < 10; ++j) {
    for (int i = 0; i < 10; ++i) {
      s.quads.col(10 * j + i) << 11 * j + i, 11 * j + i + 1, 11 * (j + 1) + i + 1, 11 * (j + 1) + i;
    }
  }
  return s;
}

SurfaceApproach approach(const TriangleSurface& tool, const Shell& s,
                         const Vec3& offset = Vec3::Zero()) {
  return closest_approach(tool, offset, s.nodes, s.quads, s.triangles);
}

TEST(SurfaceApproach, PlaneToolAbovePlaneBlank) {
  // Tool plane at z = 1.7 facing down: with a 1 mm blank, a clearance of 1.7 - 0.5 = 1.2 mm.
  SurfaceBuilder b;
  b.add_patch(6, 6, rectangle(2, 8, 2, 8, 1.7), true);
  const TriangleSurface tool = b.build();
  const Shell blank = flat_blank();
  const SurfaceApproach a = approach(tool, blank);
  EXPECT_NEAR(a.distance, 1.7, 1e-15);
  EXPECT_NEAR(a.distance - 0.5 * 1.0, 1.2, 1e-15);
  EXPECT_NEAR(a.tool_point.z(), 1.7, 1e-15);
  EXPECT_NEAR(a.shell_point.z(), 0.0, 1e-15);
  EXPECT_NEAR((a.tool_point - a.shell_point).head<2>().norm(), 0.0, 1e-15);
  EXPECT_NEAR(a.facing, 1.0, 1e-15);
  // Moved down by 0.3 mm (the tool's displacement at time 0).
  EXPECT_NEAR(approach(tool, blank, Vec3(0, 0, -0.3)).distance, 1.4, 1e-15);
  // Facing up, away from the blank.
  SurfaceBuilder up;
  up.add_patch(6, 6, rectangle(2, 8, 2, 8, 1.7));
  EXPECT_NEAR(approach(up.build(), blank).facing, -1.0, 1e-15);
}

TEST(SurfaceApproach, SphereAbovePlaneComesClosestAtItsPole) {
  // Radius 5 about (5.3, 4.7, 7): its lowest node, the south pole, 2 mm above the blank.
  for (const bool inward : {false, true}) {
    SurfaceBuilder b;
    b.add_sphere({5.3, 4.7, 7}, 5.0, 12, 24, std::numbers::pi, inward);
    const SurfaceApproach a = approach(b.build(), flat_blank());
    EXPECT_NEAR(a.distance, 2.0, 1e-14);
    EXPECT_NEAR((a.tool_point - Vec3(5.3, 4.7, 2)).norm(), 0.0, 1e-14);
    EXPECT_NEAR((a.shell_point - Vec3(5.3, 4.7, 0)).norm(), 0.0, 1e-14);
    EXPECT_NEAR(a.facing, inward ? -1.0 : 1.0, 1e-14);
  }
}

TEST(SurfaceApproach, CrossedRidgesComeClosestInsideTwoEdges) {
  // A tool valley whose bottom line runs along x at z = 1, over a blank ridge whose crest runs
  // along y at z = 0: the closest points are (0, 0, 1) and (0, 0, 0), inside an edge of each, no
  // node near (vertex-triangle distances alone give more than 1).
  SurfaceBuilder tool;
  const int a0 = tool.add_node({-5, 0, 1}), a1 = tool.add_node({5, 0, 1});
  const int l0 = tool.add_node({-5, -3, 2}), l1 = tool.add_node({5, -3, 2});
  const int r0 = tool.add_node({-5, 3, 2}), r1 = tool.add_node({5, 3, 2});
  tool.add_triangle(a0, a1, l1);  // normals down, towards the blank
  tool.add_triangle(a0, l1, l0);
  tool.add_triangle(a0, r1, a1);
  tool.add_triangle(a0, r0, r1);
  Shell blank;
  blank.nodes.resize(3, 6);
  blank.nodes << 0, 0, -3, -3, 3, 3,  //
      -5, 5, -5, 5, -5, 5,            //
      0, 0, -1, -1, -1, -1;
  blank.quads.resize(4, 0);
  blank.triangles.resize(3, 4);
  blank.triangles << 2, 2, 0, 0,  //
      0, 1, 4, 5,                 //
      1, 3, 5, 1;
  const SurfaceApproach a = approach(tool.build(), blank);
  EXPECT_NEAR(a.distance, 1.0, 1e-15);
  EXPECT_NEAR((a.tool_point - Vec3(0, 0, 1)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((a.shell_point - Vec3(0, 0, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(a.facing, 1.0, 1e-15);  // the nodal normals there: straight down
}

TEST(SurfaceApproach, ToolThroughTheBlankMeetsIt) {
  SurfaceBuilder b;
  b.add_patch(2, 2, [](double u, double v) { return Vec3(3 + 4 * u, 5, -1 + 2 * v); });
  const SurfaceApproach a = approach(b.build(), flat_blank());
  EXPECT_EQ(a.distance, 0.0);
  EXPECT_NEAR(a.tool_point.z(), 0.0, 1e-15);
  EXPECT_EQ(a.facing, 0.0);
}

TEST(SurfaceApproach, FarToolOfManyTrianglesIsQuick) {
  // 100,352 triangles 50 mm above a 10,000-quad blank, a trough whose bottom line x = 50 is
  // lowest: a tree search, not a walk through the empty cells of a grid.
  SurfaceBuilder tool;
  tool.add_patch(
      224, 224,
      [](double u, double v) {
        return Vec3(-50 + 200 * u, -50 + 200 * v, 50 + 40 * (u - 0.5) * (u - 0.5));
      },
      true);
  Shell blank;
  blank.nodes.resize(3, 101 * 101);
  blank.quads.resize(4, 100 * 100);
  for (int j = 0; j <= 100; ++j) {
    for (int i = 0; i <= 100; ++i) {
      blank.nodes.col(101 * j + i) = Vec3(i, j, 0);
    }
  }
  for (int j = 0; j < 100; ++j) {
    for (int i = 0; i < 100; ++i) {
      blank.quads.col(100 * j + i) << 101 * j + i, 101 * j + i + 1, 101 * (j + 1) + i + 1,
          101 * (j + 1) + i;
    }
  }
  const TriangleSurface s = tool.build();
  const auto start = std::chrono::steady_clock::now();
  const SurfaceApproach a = approach(s, blank);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  EXPECT_NEAR(a.distance, 50.0, 1e-12);
  EXPECT_NEAR(a.tool_point.x(), 50.0, 1e-12);
  std::printf("closest_approach: %d tool triangles, %ld blank quads in %.0f ms\n",
              s.num_triangles(), static_cast<long>(blank.quads.cols()), ms);
}

}  // namespace
}  // namespace sf
