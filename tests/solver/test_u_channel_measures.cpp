// The U-channel springback measures theta1, theta2, rho (src/solver/u_channel_measures.hpp) on
// synthetic sections with exact answers: a formed U, a U with its wall and flange turned by known
// angles, a wall bent into a circular arc, a rigid motion of the whole section, and the errors.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "solver/u_channel_measures.hpp"

namespace sf {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

/// A section along x in the x-z plane (x along the channel, z the punch axis), the nodes of each
/// part listed apart so that a test can move them; y is 0 on the section.
struct Section {
  std::vector<Vec2> bottom;   ///< mm, z = -70, x = 0 ... 30
  std::vector<Vec2> corner1;  ///< mm, on the punch radius: in no region
  std::vector<Vec2> wall;     ///< mm, x = 35, z = -65 ... -5, bottom end first
  std::vector<Vec2> corner2;  ///< mm, on the die radius: in no region
  std::vector<Vec2> flange;   ///< mm, z = 0, x = 40 ... 175
};

/// The formed U: bottom, 5 mm corner, vertical wall, 5 mm corner, flange (the NUMISHEET'93
/// channel's proportions, mid-surface).
Section formed_u() {
  Section s;
  for (int i = 0; i <= 6; ++i) {
    s.bottom.emplace_back(5.0 * i, -70.0);
  }
  for (const double a : {-60.0, -30.0}) {
    s.corner1.emplace_back(30.0 + 5.0 * std::cos(a * deg), -65.0 + 5.0 * std::sin(a * deg));
  }
  for (int i = 0; i <= 12; ++i) {
    s.wall.emplace_back(35.0, -65.0 + 5.0 * i);
  }
  for (const double a : {150.0, 120.0}) {
    s.corner2.emplace_back(40.0 + 5.0 * std::cos(a * deg), -5.0 + 5.0 * std::sin(a * deg));
  }
  for (int i = 0; i <= 27; ++i) {
    s.flange.emplace_back(40.0 + 5.0 * i, 0.0);
  }
  return s;
}

/// Ranges that pick the regions of formed_u() (each holds only its straight part).
UChannelMeasureConfig ranges() {
  UChannelMeasureConfig c;
  c.section = "section";
  c.bottom = {0.0, 29.0};    // x: every bottom node but the one at 30 mm, where the radius starts
  c.wall = {-64.0, -4.0};    // z: the wall nodes from -60 to -5 mm
  c.flange = {41.0, 176.0};  // x: from 45 mm to the end
  return c;
}

std::vector<Vec2> all_points(const Section& s) {
  std::vector<Vec2> p;
  for (const auto* part : {&s.bottom, &s.corner1, &s.wall, &s.corner2, &s.flange}) {
    p.insert(p.end(), part->begin(), part->end());
  }
  return p;
}

/// Blank coordinates: the section's nodes, shuffled (the measures must not depend on the order
/// of the node group), then as many nodes off the section (y = 17.5 mm) that the measures must
/// ignore.
struct Blank {
  Matrix3X formed;
  Matrix3X current;
  std::vector<int> section;
};

Blank make_blank(const Section& formed, const Section& current) {
  const std::vector<Vec2> f = all_points(formed);
  const std::vector<Vec2> c = all_points(current);
  const int n = static_cast<int>(f.size());
  Blank b;
  b.formed.resize(3, 2 * n);
  b.current.resize(3, 2 * n);
  // Node k of the blank holds section point (7 k) mod n: 7 and n are coprime here, a shuffle.
  for (int k = 0; k < n; ++k) {
    const int p = (7 * k) % n;
    b.formed.col(k) << f[p].x(), 0.0, f[p].y();
    b.current.col(k) << c[p].x(), 0.0, c[p].y();
    b.section.push_back(k);
  }
  for (int k = 0; k < n; ++k) {  // the strip's other edge: same x, z, far in y
    b.formed.col(n + k) = b.formed.col(k) + Vec3(0.0, 17.5, 0.0);
    b.current.col(n + k) = b.current.col(k) + Vec3(0.0, 17.5, 0.0);
  }
  std::reverse(b.section.begin(), b.section.end());
  return b;
}

/// Rotates `p` about `centre` by `angle` (rad, counter-clockwise in the x-z plane seen with x to
/// the right and z up).
Vec2 rotate(const Vec2& p, const Vec2& centre, double angle) {
  return centre + Eigen::Rotation2Dd(angle) * (p - centre);
}

/// formed_u() with the wall (and everything beyond it) turned outwards by `wall_angle` (rad)
/// about the bottom corner (35, -70), then the flange turned by a further `flange_angle` (rad,
/// counter-clockwise: its outer end up) about the wall's top (the wall-flange corner).
Section opened_u(double wall_angle, double flange_angle) {
  Section s = formed_u();
  const Vec2 corner1(35.0, -70.0);
  for (auto* part : {&s.wall, &s.corner2, &s.flange}) {
    for (Vec2& p : *part) {
      p = rotate(p, corner1, -wall_angle);  // clockwise: the wall's top moves to +x
    }
  }
  const Vec2 corner2 = rotate(Vec2(35.0, 0.0), corner1, -wall_angle);
  for (Vec2& p : s.flange) {
    p = rotate(p, corner2, flange_angle);
  }
  return s;
}

/// mm, radius of the algebraic (Kasa) least-squares circle through `points`: minimises
/// sum (x^2 + z^2 + D x + E z + F)^2, on coordinates centred at the points' mean.
double kasa_radius(const std::vector<Vec2>& points) {
  Vec2 mean = Vec2::Zero();
  for (const Vec2& p : points) {
    mean += p;
  }
  mean /= static_cast<double>(points.size());
  Eigen::MatrixX3d a(points.size(), 3);
  Eigen::VectorXd rhs(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec2 q = points[i] - mean;
    a.row(static_cast<Eigen::Index>(i)) << q.x(), q.y(), 1.0;
    rhs(static_cast<Eigen::Index>(i)) = -q.squaredNorm();
  }
  const Eigen::Vector3d def = a.colPivHouseholderQr().solve(rhs);
  return std::sqrt(0.25 * (def(0) * def(0) + def(1) * def(1)) - def(2));
}

std::string error_of(const UChannelMeasureConfig& config, const Blank& b) {
  try {
    measure_u_channel(config, b.section, b.formed, b.current);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

TEST(UChannelMeasures, FormedUIsNinetyNinetyAndStraight) {
  const Blank b = make_blank(formed_u(), formed_u());
  const UChannelMeasures m = measure_u_channel(ranges(), b.section, b.formed, b.current);
  EXPECT_NEAR(m.theta1, 90.0, 1e-12);
  EXPECT_NEAR(m.theta2, 90.0, 1e-12);
  EXPECT_EQ(m.rho, std::numeric_limits<double>::infinity());
  EXPECT_EQ(m.bottom_nodes, 6);   // x = 0 ... 25
  EXPECT_EQ(m.wall_nodes, 12);    // z = -60 ... -5
  EXPECT_EQ(m.flange_nodes, 27);  // x = 45 ... 175
}

TEST(UChannelMeasures, OpenedWallAndTurnedFlangeGiveTheirAngles) {
  // Wall opened by 12 deg: theta1 = 102. Flange turned up by 5 deg from the wall's direction
  // (so 7 deg below level): theta2 = 90 - 5 = 85.
  const Blank b = make_blank(formed_u(), opened_u(12.0 * deg, 5.0 * deg));
  const UChannelMeasures m = measure_u_channel(ranges(), b.section, b.formed, b.current);
  EXPECT_NEAR(m.theta1, 102.0, 1e-9);
  EXPECT_NEAR(m.theta2, 85.0, 1e-9);
  EXPECT_EQ(m.rho, std::numeric_limits<double>::infinity());
}

TEST(UChannelMeasures, OpenedWallWithLevelFlangeClosesTheta2) {
  // The usual springback: the wall opens by 8 deg, the flange stays level (parallel to the
  // bottom): theta1 opens to 98, theta2 closes to 82, and theta1 + theta2 = 180.
  const Blank b = make_blank(formed_u(), opened_u(8.0 * deg, 8.0 * deg));
  const UChannelMeasures m = measure_u_channel(ranges(), b.section, b.formed, b.current);
  EXPECT_NEAR(m.theta1, 98.0, 1e-9);
  EXPECT_NEAR(m.theta2, 82.0, 1e-9);
}

TEST(UChannelMeasures, ArcWallGivesItsRadius) {
  // The wall bent into an arc of radius 150 mm: it leaves the bottom corner vertically and
  // curls outwards (centre at x = 35 + 150, z = -65).
  const double radius = 150.0;
  Section current = formed_u();
  for (std::size_t i = 0; i < current.wall.size(); ++i) {
    const double s = 5.0 * static_cast<double>(i);  // arc length from the first wall point
    current.wall[i] =
        Vec2(35.0 + radius, -65.0) + radius * Vec2(-std::cos(s / radius), std::sin(s / radius));
  }
  const Blank b = make_blank(formed_u(), current);
  const UChannelMeasures m = measure_u_channel(ranges(), b.section, b.formed, b.current);
  EXPECT_NEAR(m.rho / radius, 1.0, 1e-9);

  // The measured wall nodes (formed z in [-64, -4]: all but the first) on a least-squares
  // circle: the same radius.
  const std::vector<Vec2> wall_nodes(current.wall.begin() + 1, current.wall.end());
  EXPECT_NEAR(kasa_radius(wall_nodes) / radius, 1.0, 1e-9);
  EXPECT_EQ(m.wall_nodes, 12);

  // The chord from the first to the last measured wall node, against the bottom.
  const Vec2 chord = (wall_nodes.back() - wall_nodes.front()).normalized();
  EXPECT_NEAR(m.theta1, std::atan2(chord.y(), -chord.x()) / deg, 1e-9);
}

TEST(UChannelMeasures, RigidMotionChangesNothing) {
  // An opened U with a wall bent into an arc of radius 200 mm, then the whole section turned by
  // 30 deg about y and moved by (-20, 3, -25) mm: far enough that the regions' ranges on the
  // current shape would pick other nodes; they are picked on the formed shape, so every measure
  // is unchanged.
  Section current = opened_u(9.0 * deg, 3.0 * deg);
  const Vec2 centre(35.0 + 200.0, -65.0);
  for (std::size_t i = 0; i < current.wall.size(); ++i) {
    const double s = 5.0 * static_cast<double>(i);
    current.wall[i] = rotate(centre + 200.0 * Vec2(-std::cos(s / 200.0), std::sin(s / 200.0)),
                             Vec2(35.0, -70.0), -9.0 * deg);
  }
  const Blank b = make_blank(formed_u(), current);
  const UChannelMeasures before = measure_u_channel(ranges(), b.section, b.formed, b.current);

  Blank moved = b;
  const Mat3 turn = Eigen::AngleAxisd(30.0 * deg, Vec3::UnitY()).toRotationMatrix();
  for (Eigen::Index k = 0; k < moved.current.cols(); ++k) {
    moved.current.col(k) = turn * b.current.col(k) + Vec3(-20.0, 3.0, -25.0);
  }
  const UChannelMeasures after =
      measure_u_channel(ranges(), moved.section, moved.formed, moved.current);
  EXPECT_NEAR(after.theta1, before.theta1, 1e-9);
  EXPECT_NEAR(after.theta2, before.theta2, 1e-9);
  EXPECT_NEAR(after.rho / before.rho, 1.0, 1e-9);
  EXPECT_EQ(after.bottom_nodes, before.bottom_nodes);
  EXPECT_EQ(after.wall_nodes, before.wall_nodes);
  EXPECT_EQ(after.flange_nodes, before.flange_nodes);
  // The section really moved out of its ranges: picked on the current shape, the bottom (x in
  // [0, 29]) would hold other nodes.
  int bottom_by_current = 0;
  for (const int k : moved.section) {
    const double x = moved.current(0, k);
    bottom_by_current += (x >= 0.0 && x <= 29.0) ? 1 : 0;
  }
  EXPECT_NE(bottom_by_current, before.bottom_nodes);
  // And the values are the opened U's: the wall chord of the arc against the level bottom.
  EXPECT_GT(before.theta1, 99.0);
  EXPECT_NEAR(before.rho / 200.0, 1.0, 1e-9);
}

TEST(UChannelMeasures, TooFewNodesNameTheRegionAndItsRange) {
  const Blank b = make_blank(formed_u(), formed_u());
  UChannelMeasureConfig c = ranges();
  c.bottom = {0.0, 2.0};  // one node (x = 0)
  std::string e = error_of(c, b);
  EXPECT_NE(e.find("the bottom (x in [0, 2] mm"), std::string::npos) << e;
  EXPECT_NE(e.find("holds 1 "), std::string::npos) << e;
  EXPECT_NE(e.find("section 'section'"), std::string::npos) << e;

  c = ranges();
  c.wall = {-12.0, -4.0};  // two nodes (z = -10, -5): a wall needs three
  e = error_of(c, b);
  EXPECT_NE(e.find("the wall (z in [-12, -4] mm"), std::string::npos) << e;
  EXPECT_NE(e.find("at least 3"), std::string::npos) << e;

  c = ranges();
  c.flange = {200.0, 300.0};  // beyond the strip: empty
  e = error_of(c, b);
  EXPECT_NE(e.find("the flange (x in [200, 300] mm"), std::string::npos) << e;
  EXPECT_NE(e.find("holds 0 "), std::string::npos) << e;
}

TEST(UChannelMeasures, OverlappingRangesAreAnError) {
  const Blank b = make_blank(formed_u(), formed_u());
  UChannelMeasureConfig c = ranges();
  c.bottom = {0.0, 36.0};  // reaches the wall nodes at x = 35
  std::string e = error_of(c, b);
  EXPECT_NE(e.find("the bottom (x in [0, 36] mm"), std::string::npos) << e;
  EXPECT_NE(e.find("the wall (z in [-64, -4] mm"), std::string::npos) << e;
  EXPECT_NE(e.find("overlap"), std::string::npos) << e;

  c = ranges();
  c.wall = {-64.0, 0.0};  // reaches the flange nodes at z = 0
  e = error_of(c, b);
  EXPECT_NE(e.find("the wall (z in [-64, 0] mm"), std::string::npos) << e;
  EXPECT_NE(e.find("the flange (x in [41, 176] mm"), std::string::npos) << e;
}

TEST(UChannelMeasures, BadNodeIndexIsAnError) {
  Blank b = make_blank(formed_u(), formed_u());
  b.section.push_back(static_cast<int>(b.formed.cols()));
  const std::string e = error_of(ranges(), b);
  EXPECT_NE(e.find("out of range"), std::string::npos) << e;
}

}  // namespace
}  // namespace sf
