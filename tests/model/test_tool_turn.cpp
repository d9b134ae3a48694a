// A tool that turns (tools.motion.angle, axis, pivot): where its motion places it, checked
// against placements worked out by hand (exact rotations by quarter turns, to round-off):
// - the case's motion turns the mesh about the axis through the pivot, and a translation moves
//   the pivot with it;
// - an operation's motion turns about its axis and pivot as the tool stands at the operation's
//   start (both given in the mesh's coordinates), after the turn and travel before it;
// - a case motion started afresh in a later operation turns on from where the tool stands.
#include <gtest/gtest.h>

#include <numbers>

#include "model/operation_plan.hpp"

namespace sf {
namespace {

constexpr double kRoundOff = 1e-12;  // mm, on coordinates of order 10 mm

MotionConfig turning(std::array<double, 3> axis, std::array<double, 3> pivot, double degrees,
                     double seconds) {
  MotionConfig m;
  m.angle = {{0.0, seconds}, {0.0, degrees}};
  m.axis = axis;
  m.pivot = pivot;
  return m;
}

void expect_near(const Vec3& actual, const Vec3& expected) {
  EXPECT_NEAR((actual - expected).norm(), 0.0, kRoundOff)
      << "got (" << actual.transpose() << "), expected (" << expected.transpose() << ")";
}

TEST(ToolTurn, TheCaseMotionTurnsAboutTheAxisThroughThePivot) {
  // A quarter turn about +z through (10, 0, 0) over 1 s: (20, 0, 0) -> (10, 10, 0); half-way,
  // an eighth of a turn.
  const RigidToolMotion motion(turning({0.0, 0.0, 2.0}, {10.0, 0.0, 0.0}, 90.0, 1.0));
  ASSERT_TRUE(motion.turns());
  expect_near(motion.placement(1.0).apply(Vec3(20.0, 0.0, 0.0)), Vec3(10.0, 10.0, 0.0));
  expect_near(motion.placement(5.0).apply(Vec3(10.0, 0.0, 7.0)), Vec3(10.0, 0.0, 7.0));  // axis
  const double h = std::sqrt(0.5) * 10.0;
  expect_near(motion.placement(0.5).apply(Vec3(20.0, 0.0, 0.0)), Vec3(10.0 + h, h, 0.0));
  EXPECT_NEAR(motion.angle(0.5), std::numbers::pi / 4.0, 1e-15);
  EXPECT_NEAR(motion.angular_speed(0.5), std::numbers::pi / 2.0, 1e-6);
}

TEST(ToolTurn, ATranslationMovesThePivotWithTheTool) {
  // Down 5 mm (displacement curve along -z) while turning a quarter turn about +y through the
  // origin: (10, 0, 0) turns to (0, 0, -10), then moves to (0, 0, -15).
  MotionConfig config = turning({0.0, 1.0, 0.0}, {0.0, 0.0, 0.0}, 90.0, 1.0);
  config.type = MotionConfig::Type::displacement;
  config.curve = {{0.0, 1.0}, {0.0, 5.0}};
  const RigidToolMotion motion(config);
  expect_near(motion.placement(1.0).apply(Vec3(10.0, 0.0, 0.0)), Vec3(0.0, 0.0, -15.0));
}

TEST(ToolTurn, AnOperationsMotionTurnsAboutItsAxisWhereTheToolStands) {
  // The case turns the tool a quarter turn about +z through (10, 0, 0) in [0, 1] s. Operation 1
  // (from t = 1 s) gives it a quarter turn about the mesh's +x axis through the mesh's point
  // (20, 0, 0), which the first turn carried to (10, 10, 0), with the mesh's +x axis turned to
  // +y. So the mesh point (20, 0, 5), at (10, 10, 5) after the first turn, turns about the
  // line through (10, 10, 0) along +y: (dx, dz) = (0, 5) -> (5, 0) -> (15, 10, 0).
  Model model;
  model.tools.resize(1);
  model.tools[0].motion = RigidToolMotion(turning({0.0, 0.0, 1.0}, {10.0, 0.0, 0.0}, 90.0, 1.0));
  Operation first, second;
  first.motions.resize(1);
  second.motions.resize(1);
  second.motions[0] = RigidToolMotion(turning({1.0, 0.0, 0.0}, {20.0, 0.0, 0.0}, 90.0, 1.0));
  model.operations = {first, second};

  const ToolMotionOrigin case_origin;
  const ToolStanding at_one = standing_in_effect(model, 0, case_origin, 1.0);
  expect_near(at_one.placement.apply(Vec3(20.0, 0.0, 5.0)), Vec3(10.0, 10.0, 5.0));
  const ToolMotionOrigin origin = origin_at_start(model, 1, 0, case_origin, true, 1.0, at_one);
  EXPECT_EQ(origin.operation, 1);
  const ToolStanding at_two = standing_in_effect(model, 0, origin, 2.0);
  expect_near(at_two.placement.apply(Vec3(20.0, 0.0, 5.0)), Vec3(15.0, 10.0, 0.0));
  expect_near(at_two.placement.apply(Vec3(20.0, 0.0, 0.0)), Vec3(10.0, 10.0, 0.0));  // pivot
  EXPECT_NEAR(at_two.angle, std::numbers::pi, 1e-15);  // the turns' angles add
}

TEST(ToolTurn, TheCaseMotionStartedAfreshTurnsOnFromWhereTheToolStands) {
  // Operation 1 does not give the tool a motion and it stood still in operation 0 (not moved):
  // its case motion starts again at t0 = 3 s, from the quarter turn it stands at (origin with
  // the placement of the first turn): a second quarter turn about the same axis and pivot.
  Model model;
  model.tools.resize(1);
  model.tools[0].motion = RigidToolMotion(turning({0.0, 0.0, 1.0}, {10.0, 0.0, 0.0}, 90.0, 1.0));
  Operation first, second;
  first.motions.resize(1);
  second.motions.resize(1);
  model.operations = {first, second};
  const ToolStanding standing = standing_in_effect(model, 0, ToolMotionOrigin{}, 1.0);
  const ToolMotionOrigin origin = origin_at_start(model, 1, 0, {}, false, 3.0, standing);
  EXPECT_EQ(origin.operation, -1);
  expect_near(placement_in_effect(model, 0, origin, 3.0).apply(Vec3(20.0, 0.0, 0.0)),
              Vec3(10.0, 10.0, 0.0));
  expect_near(placement_in_effect(model, 0, origin, 4.0).apply(Vec3(20.0, 0.0, 0.0)),
              Vec3(0.0, 0.0, 0.0));
}

}  // namespace
}  // namespace sf
