// Penalty contact with a rotating tool (issue 32, item 7: flanging steels, cams): the tool's mesh
// point X stands at R X + d (ContactKinematics::tool_rotation, tool_displacement). What it must
// give is exact:
// - a node at R X0 + d meets the tool as X0 meets it unmoved: the same gap, the force turned by R;
//   the moment on the tool about the origin is the sum of x_i x (-f_i);
// - friction: a turning tool drags a node as a tool translating by the step of its own point under
//   the node does (the same increment, the same bits);
// - a disc turning under nodes pressed into it: once they slide, each friction force is mu F_n
//   along the disc's motion under it, and the torque on the disc is -n mu F_n r.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "contact/contact_search.hpp"
#include "contact/coulomb_friction.hpp"
#include "contact/penalty_contact.hpp"
#include "contact_pair_fixture.hpp"
#include "test_meshes.hpp"

namespace sf {
namespace {

using test::Contact;
using test::make_law;
using test::make_pair;

Mat3 turn(const Vec3& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

TEST(RotatingToolContact, ATurnedToolPushesAlongItsTurnedNormal) {
  const TriangleSurface flat =
      test::make_height_field("steel", 4, 4, 0, 4, 0, 4, [](double, double) { return 0.0; });
  Matrix3X reference(3, 3);  // as in the unmoved tool's frame: gaps -0.4, +0.1, -0.8
  reference.col(0) = Vec3(2.3, 1.7, 0.1);
  reference.col(1) = Vec3(1.1, 2.9, 0.6);
  reference.col(2) = Vec3(3.2, 0.4, -0.3);
  const VectorX h = VectorX::Constant(3, 0.5);
  const Mat3 r = turn(Vec3(1.0, 0.3, -0.2), 0.7);
  const Vec3 d(1.0, -2.0, 0.5);
  const Matrix3X x = (r * reference).colwise() + d;
  const Matrix3X v = Matrix3X::Zero(3, 3);
  Contact pair = make_pair(flat, 3, 100.0);
  Matrix3X f = Matrix3X::Zero(3, 3);
  ContactKinematics kinematics{x, v, h, d, Vec3::Zero(), 0.0};
  kinematics.tool_rotation = r;
  kinematics.tool_rotation_previous = r;
  const ContactResult result = compute_penalty_contact(pair.pair, pair.state, kinematics, f);
  EXPECT_LT((f.col(0) - r * Vec3(0, 0, 40)).norm(), 1e-12);
  EXPECT_EQ(f.col(1).norm(), 0.0);
  EXPECT_LT((f.col(2) - r * Vec3(0, 0, 80)).norm(), 1e-12);
  EXPECT_EQ(result.nodes_in_contact, 2);
  EXPECT_LT((result.force_on_tool + f.rowwise().sum()).norm(), 1e-12);
  const Vec3 moment = x.col(0).cross(-f.col(0)) + x.col(2).cross(-f.col(2));
  EXPECT_LT((result.moment_on_tool - moment).norm(), 1e-12 * moment.norm());
  EXPECT_NEAR(result.energy, 0.5 * 100 * (0.4 * 0.4 + 0.8 * 0.8), 1e-12);
}

TEST(RotatingToolContact, FrictionIsThatOfATranslatingToolStepOfItsPointUnderTheNode) {
  // A flat tool turning about z (its normal stays +z) by 0.01 rad over the step, under a node
  // pressed 0.1 mm into it; the same node under a translating tool whose step is the turning
  // tool's point's step under it.
  const TriangleSurface flat =
      test::make_height_field("steel", 4, 4, -10, 10, -10, 10, [](double, double) { return 0.0; });
  const FrictionParameters law = make_law(0.3, 0.2, 0.0);
  Matrix3X x(3, 1);
  x.col(0) = Vec3(3.0, 1.0, 0.4);
  const Matrix3X v = Vec3(2.0, -1.0, 0.0);
  const VectorX h = VectorX::Constant(1, 0.5);
  const double dt = 1e-3;
  const Mat3 before = turn(Vec3::UnitZ(), 0.20), now = turn(Vec3::UnitZ(), 0.21);
  const Vec3 d(0.5, 0.2, 0.0), d_before(0.49, 0.2, 0.0);
  Contact turning = make_pair(flat, 1, 1000.0, law);
  Matrix3X f_turning = Matrix3X::Zero(3, 1);
  ContactKinematics k_turning{x, v, h, d, Vec3(d - d_before), dt};
  k_turning.tool_rotation = now;
  k_turning.tool_rotation_previous = before;
  compute_penalty_contact(turning.pair, turning.state, k_turning, f_turning);
  const Vec3 p = now.transpose() * (x.col(0) - d);
  const Vec3 point_step = (now - before) * p + (d - d_before);
  Contact translating = make_pair(flat, 1, 1000.0, law);
  Matrix3X f_translating = Matrix3X::Zero(3, 1);
  compute_penalty_contact(translating.pair, translating.state, {x, v, h, d, point_step, dt},
                          f_translating);
  EXPECT_GT(f_turning.col(0).head<2>().norm(), 0.0);  // friction acts
  EXPECT_EQ(f_turning, f_translating);
  EXPECT_EQ(turning.state.stick_force, translating.state.stick_force);
}

TEST(RotatingToolContact, ADiscTurningUnderPressedNodesDragsThemWithTheSlidingForce) {
  // Four nodes at radius 3 mm pressed 0.1 mm (k = 1000 N/mm: F_n = 100 N) into a flat disc
  // turning about z at 20 rad/s; mu = mu_d = 0.2 once sliding (decay 1 s/mm: exp(-60) ~ 1e-26).
  const TriangleSurface flat =
      test::make_height_field("disc", 8, 8, -5, 5, -5, 5, [](double, double) { return 0.0; });
  const FrictionParameters law = make_law(0.3, 0.2, 1.0);
  const double k = 1000, radius = 3, omega = 20, dt = 1e-5, fn = 100;
  const int n = 4, steps = 2000;  // 0.4 rad: 1.2 mm of slip under each node
  Matrix3X x(3, n);
  x << radius, 0, -radius, 0,  //
      0, radius, 0, -radius,   //
      0.4, 0.4, 0.4, 0.4;
  const Matrix3X v = Matrix3X::Zero(3, n);
  const VectorX h = VectorX::Constant(n, 0.5);
  Contact pair = make_pair(flat, n, k, law);
  Matrix3X f(3, n);
  ContactResult result;
  for (int s = 1; s <= steps; ++s) {
    ContactKinematics kinematics{x, v, h, Vec3::Zero(), Vec3::Zero(), dt};
    kinematics.tool_rotation = turn(Vec3::UnitZ(), omega * dt * s);
    kinematics.tool_rotation_previous = turn(Vec3::UnitZ(), omega * dt * (s - 1));
    f.setZero();
    result = compute_penalty_contact(pair.pair, pair.state, kinematics, f);
    ASSERT_GE(result.friction_work, 0.0);
  }
  EXPECT_EQ(result.sliding_nodes, n);
  const double limit = 0.2 * fn;
  for (int i = 0; i < n; ++i) {
    const Vec3 along = Vec3::UnitZ().cross(x.col(i)).normalized();  // the disc's motion under it
    // The stored force lags the step's turn by half a step's angle (0.5 omega dt = 1e-4 rad).
    EXPECT_NEAR(f.col(i).dot(along), limit, 1e-6 * limit) << "node " << i;
    EXPECT_NEAR(f(2, i), fn, 1e-9);
  }
  EXPECT_NEAR(result.moment_on_tool.z(), -n * limit * radius, 1e-5 * n * limit * radius);
}

}  // namespace
}  // namespace sf
