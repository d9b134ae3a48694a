// diagnose_tool on surfaces with known defects (docs/tool-diagnosis.md): each defect found where
// it is, measured exactly (the widths, areas and angles of the geometry built here, to round-off),
// and nothing found on clean curved tools.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "mesh/tool_diagnosis.hpp"
#include "support/surface_builder.hpp"

namespace sf {
namespace {

using test::rectangle;
using test::SurfaceBuilder;
constexpr double kPi = std::numbers::pi;

void expect_clean(const ToolDiagnosis& d) {
  EXPECT_TRUE(d.gaps.empty()) << d.gaps.size() << " gap edges, the first at "
                              << d.gaps.front().position.transpose();
  EXPECT_TRUE(d.flipped.empty());
  EXPECT_TRUE(d.overlaps.empty()) << d.overlaps.size() << " overlapping, the first at "
                                  << d.overlaps.front().position.transpose();
  EXPECT_TRUE(d.slivers.empty()) << d.slivers.size() << " slivers, the first at "
                                 << d.slivers.front().position.transpose();
  EXPECT_TRUE(d.folds.empty()) << d.folds.size() << " folds, the first at "
                               << d.folds.front().position.transpose();
}

// Two flat faces [0, 4] x [0, 4] and [4 + gap, 8 + gap] x [0, 4], 4 x 4 cells each (the right one
// ny_right cells along y), not joined: a crack of width `gap` along x = 4 + gap / 2.
SurfaceBuilder two_faces(double gap, int ny_right = 4, bool flip_right = false) {
  SurfaceBuilder b;
  b.add_patch(4, 4, rectangle(0, 4, 0, 4, 0));
  b.add_patch(4, ny_right, rectangle(4 + gap, 8 + gap, 0, 4, 0), flip_right);
  return b;
}

TEST(ToolDiagnosis, GapBetweenTwoFacesIsMeasuredAndLocated) {
  const ToolDiagnosis d = diagnose_tool(two_faces(0.05).build(), 1.0);
  ASSERT_EQ(d.gaps.size(), 8u);  // the 4 edges on either side of the crack
  for (const ToolFinding& g : d.gaps) {
    EXPECT_NEAR(g.value, 0.05, 1e-12);
    EXPECT_NEAR(g.position.x(), 4.025, 1e-12);
    EXPECT_GE(g.position.y(), 0.0);
    EXPECT_LE(g.position.y(), 4.0);
    EXPECT_EQ(g.position.z(), 0.0);
  }
  EXPECT_TRUE(d.flipped.empty());
  EXPECT_TRUE(d.overlaps.empty());
  EXPECT_TRUE(d.slivers.empty());
  EXPECT_TRUE(d.folds.empty());
}

TEST(ToolDiagnosis, NonConformingGapIsFoundOnBothSides) {
  // 4 edges of 1 mm on the left, 5 of 0.8 mm on the right.
  const ToolDiagnosis d = diagnose_tool(two_faces(0.05, 5).build(), 1.0);
  ASSERT_EQ(d.gaps.size(), 9u);
  for (const ToolFinding& g : d.gaps) {
    EXPECT_NEAR(g.value, 0.05, 1e-12);
    EXPECT_NEAR(g.position.x(), 4.025, 1e-12);
  }
}

TEST(ToolDiagnosis, UnsewnSeamIsAGapOfZeroWidth) {
  // The faces meet along x = 4 but each has its own nodes there (faces meshed apart, not sewn).
  const ToolDiagnosis d = diagnose_tool(two_faces(0.0).build(), 1.0);
  ASSERT_EQ(d.gaps.size(), 8u);
  EXPECT_EQ(d.gaps.front().value, 0.0);
  EXPECT_TRUE(d.overlaps.empty());
}

TEST(ToolDiagnosis, GapAlongACurveIsTheDifferenceOfTheChordsApothems) {
  // A quarter annulus r in [20, 30] and a quarter annulus r in [10, 19.9] in one plane, 16
  // segments each over the same angles: facing chords 5.625 degrees long, whose lines lie
  // (20 - 19.9) cos(2.8125 degrees) apart.
  SurfaceBuilder b;
  const auto annulus = [](double r0, double r1) {
    return [=](double u, double v) {
      const double r = r0 + v * (r1 - r0), phi = u * kPi / 2;
      return Vec3(r * std::cos(phi), r * std::sin(phi), 0.0);
    };
  };
  b.add_patch(16, 4, annulus(20, 30));
  b.add_patch(16, 4, annulus(10, 19.9));
  const ToolDiagnosis d = diagnose_tool(b.build(), 0.8);
  ASSERT_EQ(d.gaps.size(), 32u);
  const double width = (20.0 - 19.9) * std::cos(kPi / 64);
  for (const ToolFinding& g : d.gaps) {
    EXPECT_NEAR(g.value, width, 1e-12);
    EXPECT_NEAR(std::hypot(g.position.x(), g.position.y()), 19.95, 3e-2);  // on the crack
  }
  EXPECT_TRUE(d.flipped.empty());
  EXPECT_TRUE(d.overlaps.empty());
}

TEST(ToolDiagnosis, GapThresholdIsTheThicknessOrTheLongerEdge) {
  // Edges of 1 mm: a gap up to 1 mm is one whatever the thickness; beyond, up to the thickness.
  EXPECT_EQ(diagnose_tool(two_faces(0.99).build(), 0.5).gaps.size(), 8u);
  EXPECT_TRUE(diagnose_tool(two_faces(1.01).build(), 0.5).gaps.empty());
  EXPECT_EQ(diagnose_tool(two_faces(1.01).build(), 1.2).gaps.size(), 8u);
  EXPECT_TRUE(diagnose_tool(two_faces(1.3).build(), 1.2).gaps.empty());
}

TEST(ToolDiagnosis, OuterBoundariesAreNoGaps) {
  // A U-shaped face (a 2 mm slot cut into it) of 1 mm cells: its boundary turns corners and faces
  // itself across the slot 2 mm wide, wider than the edges and the 1 mm thickness.
  SurfaceBuilder b;
  b.add_patch(6, 2, rectangle(0, 6, 0, 2, 0));
  b.add_patch(2, 4, rectangle(0, 2, 2, 6, 0));
  b.add_patch(2, 4, rectangle(4, 6, 2, 6, 0));
  expect_clean(diagnose_tool(b.joined(1e-12).build(), 1.0));  // one face
  EXPECT_EQ(diagnose_tool(b.build(), 1.0).gaps.size(), 8u);   // apart: 2 seams of 2 + 2 edges
  // A slot 1 mm wide, as wide as the edges, is one: its sides above the bottom row's
  // neighbourhood (3 edges each) face each other 1 mm apart.
  SurfaceBuilder narrow;
  narrow.add_patch(5, 2, rectangle(0, 5, 0, 2, 0));
  narrow.add_patch(2, 4, rectangle(0, 2, 2, 6, 0));
  narrow.add_patch(2, 4, rectangle(3, 5, 2, 6, 0));
  const ToolDiagnosis d = diagnose_tool(narrow.joined(1e-12).build(), 1.0);
  ASSERT_EQ(d.gaps.size(), 6u);
  EXPECT_EQ(d.gaps.front().value, 1.0);
  EXPECT_EQ(d.gaps.back().value, 1.0);
}

TEST(ToolDiagnosis, FaceGivenTwiceOverlapsEverywhere) {
  for (const bool reversed : {false, true}) {
    SurfaceBuilder b;
    b.add_patch(4, 4, rectangle(0, 4, 0, 4, 0));
    b.add_patch(4, 4, rectangle(0, 4, 0, 4, 0), reversed);
    const ToolDiagnosis d = diagnose_tool(b.build(), 1.0);
    ASSERT_EQ(d.overlaps.size(), 64u) << "reversed " << reversed;  // every triangle of both
    for (const ToolFinding& o : d.overlaps) {
      EXPECT_EQ(o.value, 0.0);
      EXPECT_EQ(o.position.z(), 0.0);
      EXPECT_GT(o.position.x(), 0.0);
      EXPECT_LT(o.position.x(), 4.0);
    }
    // The coinciding boundaries are the stacked edges of an overlap, not a gap.
    EXPECT_TRUE(d.gaps.empty());
    EXPECT_TRUE(d.flipped.empty());
  }
}

TEST(ToolDiagnosis, ShiftedPatchOverlapsWhereItLiesOnTheOther) {
  SurfaceBuilder b;
  b.add_patch(4, 4, rectangle(0, 4, 0, 4, 0));
  b.add_patch(4, 4, rectangle(1.5, 5.5, 0.5, 4.5, 0));
  const ToolDiagnosis d = diagnose_tool(b.build(), 1.0);
  EXPECT_GT(d.overlaps.size(), 20u);
  for (const ToolFinding& o : d.overlaps) {
    EXPECT_GT(o.position.x(), 1.5);
    EXPECT_LT(o.position.x(), 4.0);
    EXPECT_GT(o.position.y(), 0.5);
    EXPECT_LT(o.position.y(), 4.0);
    EXPECT_EQ(o.position.z(), 0.0);
  }
}

TEST(ToolDiagnosis, CrossingFacesAreFoundOnTheirIntersection) {
  // A horizontal face z = 0 and a vertical face x = 2.3 through it (no node on z = 0).
  SurfaceBuilder b;
  b.add_patch(4, 4, rectangle(0, 4, 0, 4, 0));
  b.add_patch(3, 5, [](double u, double v) { return Vec3(2.3, 0.5 + 3 * u, -1.3 + 2.5 * v); });
  const ToolDiagnosis d = diagnose_tool(b.build(), 1.0);
  EXPECT_GE(d.overlaps.size(), 6u);  // at least the vertical face's 6 triangles across z = 0
  for (const ToolFinding& o : d.overlaps) {
    EXPECT_NEAR(o.position.x(), 2.3, 1e-12);
    EXPECT_NEAR(o.position.z(), 0.0, 1e-12);
    EXPECT_NEAR(o.value, 90.0, 1e-9);
  }
  EXPECT_TRUE(d.gaps.empty());
}

TEST(ToolDiagnosis, CurvedSeamMeshedApartIsAGapNotAnOverlap) {
  // Two quarter annuli meeting on the circle r = 10 in one plane, 24 and 17 segments: their chords
  // meet at angle 0 (width 0), cross, or lie one inside the other (at most the sagitta of the
  // longer, 10 (1 - cos(90/17/2 deg)) = 0.011 mm, apart), and overlap by slivers no deeper: the
  // facets of a curve, not faces lying on each other.
  SurfaceBuilder b;
  const auto annulus = [](double r0, double r1) {
    return [=](double u, double v) {
      const double r = r0 + v * (r1 - r0), phi = u * kPi / 2;
      return Vec3(r * std::cos(phi), r * std::sin(phi), 0.0);
    };
  };
  b.add_patch(24, 4, annulus(5, 10));
  b.add_patch(17, 4, annulus(10, 15));
  const ToolDiagnosis d = diagnose_tool(b.build(), 1.0);
  EXPECT_EQ(d.gaps.size(), 41u);
  const double sagitta = 10 * (1 - std::cos(kPi / 68));
  for (const ToolFinding& g : d.gaps) {
    EXPECT_LE(g.value, sagitta);
  }
  EXPECT_EQ(d.gaps.back().value, 0.0);  // the narrowest
  EXPECT_TRUE(d.overlaps.empty());
  EXPECT_TRUE(d.flipped.empty());
}

TEST(ToolDiagnosis, SliverIsFoundAtItsCentroid) {
  // A unit square of four triangles around node e = (0.5, 0.004): triangle a-b-e is 0.004 high
  // on its 1 mm edge (area 0.002 mm^2, height 0.4 % of the longest edge).
  SurfaceBuilder b;
  const int a = b.add_node({0, 0, 0}), bb = b.add_node({1, 0, 0}), c = b.add_node({1, 1, 0}),
            dd = b.add_node({0, 1, 0}), e = b.add_node({0.5, 0.004, 0});
  b.add_triangle(a, bb, e);
  b.add_triangle(a, e, dd);
  b.add_triangle(e, bb, c);
  b.add_triangle(e, c, dd);
  const ToolDiagnosis d = diagnose_tool(b.build(), 1.0);
  ASSERT_EQ(d.slivers.size(), 1u);
  EXPECT_NEAR(d.slivers[0].value, 0.002, 1e-15);
  EXPECT_NEAR((d.slivers[0].position - Vec3(0.5, 0.004 / 3, 0)).norm(), 0.0, 1e-15);
  EXPECT_TRUE(d.folds.empty());
  EXPECT_TRUE(d.gaps.empty());
  EXPECT_TRUE(d.overlaps.empty());
}

TEST(ToolDiagnosis, TinyTriangleIsFoundBesideTheMedian) {
  // 32 triangles of 0.5 mm^2 and, apart, a well-shaped triangle of edge 0.005 mm (area
  // 1.08e-5 mm^2, below 1e-4 of the median).
  SurfaceBuilder b;
  b.add_patch(4, 4, rectangle(0, 4, 0, 4, 0));
  const double s = 0.005;
  const int p = b.add_node({10, 10, 0}), q = b.add_node({10 + s, 10, 0}),
            r = b.add_node({10 + s / 2, 10 + s * std::sqrt(3.0) / 2, 0});
  b.add_triangle(p, q, r);
  const ToolDiagnosis d = diagnose_tool(b.build(), 1.0);
  EXPECT_EQ(d.median_area, 0.5);
  ASSERT_EQ(d.slivers.size(), 1u);
  EXPECT_NEAR(d.slivers[0].value, std::sqrt(3.0) / 4 * s * s, 1e-12 * s * s);
  EXPECT_NEAR((d.slivers[0].position - Vec3(10 + s / 2, 10 + s * std::sqrt(3.0) / 6, 0)).norm(),
              0.0, 1e-12);
}

// Triangle (0,0,0)-(1,0,0)-(0,1,0) (normal +z) and a second triangle across its edge from (1,0,0)
// to (0,1,0), rotated about that edge by `degrees` from the flat continuation.
TriangleSurface hinge(double degrees) {
  const double phi = degrees * kPi / 180;
  const Vec3 m(0.5, 0.5, 0), w = Vec3(1, 1, 0).normalized();
  SurfaceBuilder b;
  const int a = b.add_node({0, 0, 0}), bb = b.add_node({1, 0, 0}), c = b.add_node({0, 1, 0});
  const int apex =
      b.add_node(m + std::sqrt(0.5) * (std::cos(phi) * w + std::sin(phi) * Vec3::UnitZ()));
  b.add_triangle(a, bb, c);
  b.add_triangle(c, bb, apex);
  return b.build();
}

TEST(ToolDiagnosis, FoldBackIsFoundOnItsEdge) {
  const ToolDiagnosis d = diagnose_tool(hinge(170.0), 1.0);
  ASSERT_EQ(d.folds.size(), 1u);
  EXPECT_NEAR(d.folds[0].value, 170.0, 1e-9);
  EXPECT_NEAR((d.folds[0].position - Vec3(0.5, 0.5, 0)).norm(), 0.0, 1e-15);
  EXPECT_TRUE(diagnose_tool(hinge(100.0), 1.0).folds.empty());  // a sharp edge, not a fold
  EXPECT_TRUE(diagnose_tool(hinge(-119.0), 1.0).folds.empty());
  EXPECT_EQ(diagnose_tool(hinge(-121.0), 1.0).folds.size(), 1u);
}

TEST(ToolDiagnosis, FaceFlippedAcrossAGapIsFound) {
  const ToolDiagnosis d = diagnose_tool(two_faces(0.05, 4, true).build(), 1.0);
  EXPECT_EQ(d.gaps.size(), 8u);
  ASSERT_EQ(d.flipped.size(), 8u);
  for (const ToolFinding& f : d.flipped) {
    EXPECT_NEAR(f.value, 180.0, 1e-9);
    EXPECT_NEAR(f.position.x(), 4.025, 1e-12);
  }
}

TEST(ToolDiagnosis, FaceFlippedAcrossACornerGapIsFound) {
  // A flange z = 0 (normal +z) whose edge x = 4 turns down into a wall x = 4 (normal +x), 0.05 mm
  // below it: consistent; then the wall reversed (normal -x): 90 degrees, but opposite ways.
  for (const bool reversed : {false, true}) {
    SurfaceBuilder b;
    b.add_patch(4, 4, rectangle(0, 4, 0, 4, 0));
    b.add_patch(
        4, 3, [](double u, double v) { return Vec3(4.0, 4 * u, -0.05 - 3 * v); }, !reversed);
    const ToolDiagnosis d = diagnose_tool(b.build(), 1.0);
    ASSERT_EQ(d.gaps.size(), 8u);
    EXPECT_NEAR(d.gaps.front().value, 0.05, 1e-12);
    EXPECT_EQ(d.flipped.size(), reversed ? 8u : 0u);
    for (const ToolFinding& f : d.flipped) {
      EXPECT_NEAR(f.value, 90.0, 1e-9);
    }
  }
}

TEST(ToolDiagnosis, WallThatOrientSurfaceTurnsTheWrongWayIsFound) {
  // A die's flange z = 0 (x in [-8, 0]) and, not joined to it, its wall x = 0 going down into the
  // cavity from 0.05 mm below. The blank lies over the flange and 2 mm of the cavity: no blank
  // node lies in front of the wall, and its votes (edge hits, most of them over the flange) turn
  // the wall to -x, away from the cavity the blank is drawn into.
  SurfaceBuilder b;
  b.add_patch(8, 4, rectangle(-8, 0, 0, 4, 0));
  b.add_patch(4, 4, [](double u, double v) { return Vec3(0.0, 4 * u, -0.05 - 4 * v); });
  TriangleSurface die = b.build("die");
  Matrix3X blank(3, 11 * 5);
  for (int j = 0; j <= 4; ++j) {
    for (int i = 0; i <= 10; ++i) {
      blank.col(11 * j + i) = Vec3(-8 + i, j, 0.5);
    }
  }
  orient_surface(die, blank);
  EXPECT_GT(die.triangle_normals()(2, 0), 0.99);    // the flange faces the blank
  EXPECT_LT(die.triangle_normals()(0, 64), -0.99);  // the wall faces -x
  const ToolDiagnosis d = diagnose_tool(die, 1.0);
  EXPECT_EQ(d.gaps.size(), 8u);
  ASSERT_EQ(d.flipped.size(), 8u);
  for (const ToolFinding& f : d.flipped) {
    EXPECT_NEAR(f.value, 90.0, 1e-9);
    EXPECT_NEAR(f.position.x(), 0.0, 1e-12);
    EXPECT_NEAR(f.position.z(), -0.025, 1e-12);
  }
}

TEST(ToolDiagnosis, CleanCurvedToolsReportNothing) {
  // A hemispherical punch (radius 20, poles fanned), a closed sphere, a revolved die (flange,
  // 5 mm profile radius, wall) and a die profile drawn straight (radius 8 mm), coarse and fine.
  for (const int n : {8, 32}) {
    SurfaceBuilder hemisphere;
    hemisphere.add_sphere({0, 0, 20}, 20.0, n / 2, 2 * n, kPi / 2);
    expect_clean(diagnose_tool(hemisphere.build(), 1.0));
    SurfaceBuilder sphere;
    sphere.add_sphere({0, 0, 0}, 5.0, n / 2, n, kPi);
    expect_clean(diagnose_tool(sphere.build(), 1.0));
    // The die's profile by arc length s: flange r 60 -> 35 at z = 0, quarter circle of radius 5
    // down to r = 30, z = -5, wall down to z = -35.
    const auto profile = [](double t) {
      const double flange = 25, arc = 5 * kPi / 2, wall = 30, s = t * (flange + arc + wall);
      if (s <= flange) {
        return Vec2(60 - s, 0);
      }
      if (s <= flange + arc) {
        const double a = (s - flange) / 5;
        return Vec2(30 + 5 * std::cos(a), -5 * std::sin(a));
      }
      return Vec2(30, -5 - (s - flange - arc));
    };
    SurfaceBuilder die;
    die.add_patch(2 * n, 2 * n, [&](double u, double v) {
      const Vec2 p = profile(v);
      return Vec3(p.x() * std::cos(u * kPi / 2), p.x() * std::sin(u * kPi / 2), p.y());
    });
    expect_clean(diagnose_tool(die.build(), 1.0));
    SurfaceBuilder full_die;  // the whole circle: a closed band
    full_die.add_patch(
        4 * n, 2 * n,
        [&](double u, double v) {
          const Vec2 p = profile(v);
          return Vec3(p.x() * std::cos(2 * kPi * u), p.x() * std::sin(2 * kPi * u), p.y());
        },
        false, true);
    expect_clean(diagnose_tool(full_die.build(), 1.0));
    SurfaceBuilder channel;
    channel.add_patch(n, 2 * n, [&](double u, double v) {
      const Vec2 p = profile(v);
      return Vec3(p.x(), 100 * u, p.y());
    });
    expect_clean(diagnose_tool(channel.build(), 1.0));
  }
}

TEST(ToolDiagnosis, LargeWavyToolIsCleanAndQuick) {
  // 224 x 224 cells: 100,352 triangles of a warped 400 x 400 mm sheet (amplitude 10 mm).
  SurfaceBuilder b;
  b.add_patch(224, 224, [](double u, double v) {
    return Vec3(400 * u, 400 * v, 10 * std::sin(6 * u) * std::cos(5 * v));
  });
  const TriangleSurface s = b.build();
  const auto start = std::chrono::steady_clock::now();
  const ToolDiagnosis d = diagnose_tool(s, 1.0);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  expect_clean(d);
  RecordProperty("triangles", s.num_triangles());
  RecordProperty("milliseconds", static_cast<int>(ms));
  std::printf("diagnose_tool: %d triangles in %.0f ms\n", s.num_triangles(), ms);
}

}  // namespace
}  // namespace sf
