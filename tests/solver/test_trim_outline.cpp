// Which side of a trim line a point projects on (solver/trim_outline.hpp). A tool's outline grown
// by d is the set of points within d of the tool's footprint: against the exact distance to a
// square, rounded at its corners (not mitred), for the square meshed flat, warped (heights do
// not matter seen along the direction) and with walls (triangles of no area seen along it).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "core/errors.hpp"
#include "solver/trim_outline.hpp"

namespace sf {
namespace {

// The unit square [0, 1]^2 as n x n cells of two triangles each, at heights z(x, y), and (walls)
// a vertical wall of two triangles standing on each side.
std::vector<Tri3> square_tool(int n, double (*z)(double, double), bool walls) {
  std::vector<Tri3> out;
  const auto p = [&](int i, int j) {
    const double x = static_cast<double>(i) / n, y = static_cast<double>(j) / n;
    return Vec3(x, y, z(x, y));
  };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      Tri3 a, b;
      a << p(i, j), p(i + 1, j), p(i + 1, j + 1);
      b << p(i, j), p(i + 1, j + 1), p(i, j + 1);
      out.push_back(a);
      out.push_back(b);
    }
  }
  if (walls) {
    const Vec3 corners[4] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    for (int k = 0; k < 4; ++k) {
      const Vec3 a = corners[k], b = corners[(k + 1) % 4], up(0, 0, 10);
      Tri3 t1, t2;
      t1 << a, b, b + up;
      t2 << a, b + up, a + up;
      out.push_back(t1);
      out.push_back(t2);
    }
  }
  return out;
}

double flat(double, double) {
  return 0.0;
}
double warped(double x, double y) {
  return 3.0 * x * y - 2.0 * x * x;  // a hyperbolic-parabolic warp
}

// Exact distance from (x, y) to the unit square (0 inside).
double square_distance(double x, double y) {
  const double dx = std::max({0.0, -x, x - 1.0}), dy = std::max({0.0, -y, y - 1.0});
  return std::hypot(dx, dy);
}

TrimOutline tool_outline(std::vector<Tri3> triangles, double offset, bool keep_inside = true) {
  return TrimOutline{.points = {},
                     .direction = Vec3(0.0, 0.0, -1.0),
                     .keep_inside = keep_inside,
                     .tool_triangles = std::move(triangles),
                     .offset = offset};
}

TEST(TrimOutline, AToolsOutlineGrownByTheOffsetIsTheSetWithinTheOffsetOfItsFootprint) {
  const double offset = 0.4;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 2.0);
  for (const auto& triangles :
       {square_tool(1, flat, false), square_tool(6, warped, false), square_tool(3, flat, true)}) {
    const TrimRegion region(tool_outline(triangles, offset), "part.h5");
    int inside = 0, checked = 0;
    for (int k = 0; k < 4000; ++k) {
      const double x = coordinate(random), y = coordinate(random);
      const double d = square_distance(x, y);
      if (std::abs(d - offset) < 1e-12) {
        continue;  // on the line itself
      }
      ++checked;
      inside += d < offset;
      ASSERT_EQ(region.keeps(Vec3(x, y, 5.0 * x)), d < offset) << x << ", " << y << ": " << d;
    }
    EXPECT_GT(inside, 1000);
    EXPECT_GT(checked - inside, 1000);
  }
  // Rounded at the corner: (1.3, 1.3) is 0.424 from it, (1.25, 1.35) 0.430, both beyond a
  // rounded 0.4 though inside the mitred square [-0.4, 1.4]^2.
  const TrimRegion region(tool_outline(square_tool(2, flat, false), offset), "part.h5");
  EXPECT_FALSE(region.keeps(Vec3(1.3, 1.3, 0.0)));
  EXPECT_FALSE(region.keeps(Vec3(1.25, 1.35, 0.0)));
  EXPECT_TRUE(region.keeps(Vec3(1.25, 1.25, 0.0)));  // 0.354
  // keep = outside: the other side.
  const TrimRegion hole(tool_outline(square_tool(2, flat, false), offset, false), "part.h5");
  EXPECT_TRUE(hole.keeps(Vec3(1.3, 1.3, 0.0)));
  EXPECT_FALSE(hole.keeps(Vec3(0.5, 0.5, 0.0)));
}

TEST(TrimOutline, AWallSeenEdgeOnIsItsEdgeAndTheOffsetMayBeZero) {
  Tri3 wall;  // in the plane y = 0, x in [0, 1]: no area seen along z
  wall << Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 1);
  const TrimRegion region(tool_outline({wall}, 0.3), "part.h5");
  EXPECT_TRUE(region.keeps(Vec3(0.5, 0.2, -4.0)));
  EXPECT_TRUE(region.keeps(Vec3(1.2, -0.2, 0.0)));  // 0.283 from the end (1, 0)
  EXPECT_FALSE(region.keeps(Vec3(0.5, 0.4, 0.0)));
  EXPECT_FALSE(region.keeps(Vec3(1.25, 0.25, 0.0)));  // 0.354
  // Offset 0: the footprint itself.
  const TrimRegion footprint(tool_outline(square_tool(2, flat, false), 0.0), "part.h5");
  EXPECT_TRUE(footprint.keeps(Vec3(0.99, 0.01, 3.0)));
  EXPECT_FALSE(footprint.keeps(Vec3(1.01, 0.5, 3.0)));
}

TEST(TrimOutline, TheDirectionOfProjectionNeedNotBeTheZAxis) {
  // The square seen along x: its triangles in the plane x = 2 (coordinates y, z).
  std::vector<Tri3> triangles = square_tool(2, flat, false);
  for (Tri3& t : triangles) {
    for (int a = 0; a < 3; ++a) {
      t.col(a) = Vec3(2.0, t(0, a), t(1, a));
    }
  }
  TrimOutline outline = tool_outline(triangles, 0.2);
  outline.direction = Vec3(-3.0, 0.0, 0.0);  // not of unit length
  const TrimRegion region(outline, "part.h5");
  EXPECT_TRUE(region.keeps(Vec3(-7.0, 1.1, 0.5)));
  EXPECT_FALSE(region.keeps(Vec3(-7.0, 1.1, 1.2)));  // 0.224 from the corner (1, 1)
  EXPECT_TRUE(region.keeps(Vec3(9.0, -0.19, 0.0)));
}

TEST(TrimOutline, AnOutlineItCannotUseIsAnErrorNamingThePart) {
  const auto message = [](const TrimOutline& outline) {
    try {
      TrimRegion region(outline, "part.h5");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(message(tool_outline({}, 1.0)).find("part.h5: a trim by a tool's outline"),
            std::string::npos);
  EXPECT_NE(message(tool_outline(square_tool(1, flat, false), -1.0)).find("offset >= 0"),
            std::string::npos);
  TrimOutline no_direction = tool_outline(square_tool(1, flat, false), 1.0);
  no_direction.direction = Vec3::Zero();
  EXPECT_NE(message(no_direction).find("nonzero length"), std::string::npos);
  TrimOutline two_points = tool_outline({}, 0.0);
  two_points.points = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
  EXPECT_NE(message(two_points).find("at least 3 points, got 2"), std::string::npos);
  TrimOutline flat_line = two_points;
  flat_line.points.push_back(Vec3(2, 0, 0));
  EXPECT_NE(message(flat_line).find("encloses no area"), std::string::npos);
}

}  // namespace
}  // namespace sf
