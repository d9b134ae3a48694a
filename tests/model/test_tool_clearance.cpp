// The clearance between two tool surfaces along a direction (model/tool_clearance.hpp), against
// exact values: two parallel squares, a tilted one, squares that never meet.
#include <gtest/gtest.h>

#include "model/tool_clearance.hpp"

namespace sf {
namespace {

// A square of side `side` (two triangles) centred at (cx, cy) in the plane z = z0 + slope * x.
TriangleSurface square(double cx, double cy, double z0, double side, double slope = 0.0) {
  Matrix3X x(3, 4);
  const double h = 0.5 * side;
  const double corners[4][2] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}};
  for (int k = 0; k < 4; ++k) {
    const double px = cx + corners[k][0];
    x.col(k) = Vec3(px, cy + corners[k][1], z0 + slope * px);
  }
  TriConn t(3, 2);
  t.col(0) << 0, 1, 2;
  t.col(1) << 0, 2, 3;
  return TriangleSurface("square", x, t);
}

TEST(ToolClearance, ParallelSquaresAreTheirDistanceApart) {
  // A holder 3 mm above a larger die, closing along -z: 3 mm, exactly.
  const auto holder = square(0.0, 0.0, 3.0, 10.0);
  const auto die = square(0.0, 0.0, 0.0, 40.0);
  EXPECT_DOUBLE_EQ(*clearance_along(holder, die, Vec3(0.0, 0.0, -1.0)), 3.0);
  // The die's nodes lie outside the holder: only the holder's rays meet. The other way round
  // (a small die under a large holder), only the die's rays back up meet.
  EXPECT_DOUBLE_EQ(*clearance_along(square(0.0, 0.0, 3.0, 40.0), square(0.0, 0.0, 0.0, 10.0),
                                    Vec3(0.0, 0.0, -1.0)),
                   3.0);
}

TEST(ToolClearance, TiltedDieIsMetFirstWhereItIsHighest) {
  // Die z = 0.1 x over x in [-20, 20]; a holder of side 10 at height 5 over x in [-5, 5]: its
  // corner at x = 5 meets the die at z = 0.5 after 4.5 mm.
  const auto holder = square(0.0, 0.0, 5.0, 10.0);
  const auto die = square(0.0, 0.0, 0.0, 40.0, 0.1);
  EXPECT_NEAR(*clearance_along(holder, die, Vec3(0.0, 0.0, -1.0)), 4.5, 1e-12);
}

TEST(ToolClearance, SurfacesThatNeverMeetHaveNone) {
  const auto holder = square(0.0, 0.0, 3.0, 10.0);
  const auto aside = square(50.0, 0.0, 0.0, 10.0);
  EXPECT_FALSE(clearance_along(holder, aside, Vec3(0.0, 0.0, -1.0)));
  // Moving away from the die: no meeting either.
  EXPECT_FALSE(clearance_along(holder, square(0.0, 0.0, 0.0, 40.0), Vec3(0.0, 0.0, 1.0)));
}

}  // namespace
}  // namespace sf
