// The rigid-body-mode check (src/implicit/rigid_body_modes.hpp): free modes left by symmetry
// planes, clamps and partial supports, their descriptions, and the holds that remove them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "implicit/rigid_body_modes.hpp"
#include "model/boundary_conditions.hpp"

namespace sf {
namespace {

constexpr unsigned char ux = 1, uy = 2, uz = 4, rx = 8, ry = 16, rz = 32;

/// A flat plate of nx x ny nodes over [0, 100] x [0, 50] mm at z = 0; node i + nx j.
Matrix3X plate(int nx, int ny) {
  Matrix3X x(3, nx * ny);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      x.col(j * nx + i) = Vec3(100.0 * i / (nx - 1), 50.0 * j / (ny - 1), 0.0);
    }
  }
  return x;
}

/// held with the added holds set.
std::vector<unsigned char> with_added(std::vector<unsigned char> held, const RigidBodyModes& m) {
  for (const auto& [node, dof] : m.added) {
    held[static_cast<std::size_t>(node)] |= static_cast<unsigned char>(1u << dof);
  }
  return held;
}

/// Checks that the added holds are new, as many as the free modes, and remove them all.
void expect_added_removes_all(const Matrix3X& x, const std::vector<unsigned char>& held,
                              const RigidBodyModes& m) {
  EXPECT_EQ(static_cast<int>(m.added.size()), m.free_count);
  for (const auto& [node, dof] : m.added) {
    EXPECT_EQ(held[static_cast<std::size_t>(node)] & (1u << dof), 0u) << node << " " << dof;
  }
  const RigidBodyModes after = find_free_rigid_body_modes(x, with_added(held, m));
  EXPECT_EQ(after.free_count, 0);
  EXPECT_TRUE(after.free_modes.empty());
  EXPECT_TRUE(after.added.empty());
}

int count_rotations(const RigidBodyModes& m) {
  return static_cast<int>(
      std::count_if(m.added.begin(), m.added.end(), [](const auto& a) { return a[1] >= 3; }));
}

TEST(RigidBodyModes, FreeBodyHasSixAndGetsAThreeTwoOneSupport) {
  const Matrix3X x = plate(11, 6);  // centroid (50, 25, 0)
  const std::vector<unsigned char> held(66, 0);
  const RigidBodyModes m = find_free_rigid_body_modes(x, held);
  EXPECT_EQ(m.free_count, 6);
  EXPECT_EQ(m.free_modes, (std::vector<std::string>{
                              "translation along x",
                              "translation along y",
                              "translation along z",
                              "rotation about an axis along x through (0, 25, 0) mm",
                              "rotation about an axis along y through (50, 0, 0) mm",
                              "rotation about an axis along z through (50, 25, 0) mm",
                          }));
  expect_added_removes_all(x, held, m);
  EXPECT_EQ(count_rotations(m), 0);  // a flat plate is held by translations alone
  // 3-2-1: three normal (z) holds at three of the four corners, then in-plane ones.
  const std::vector<int> corners = {0, 10, 55, 65};
  int z_at_corners = 0;
  for (const auto& [node, dof] : m.added) {
    if (dof == 2 && std::find(corners.begin(), corners.end(), node) != corners.end()) {
      ++z_at_corners;
    }
  }
  EXPECT_EQ(z_at_corners, 3);
  // In order: uz at the lowest-numbered of the four equally far corners, then at the opposite
  // corner; uy at two corners 100 mm apart; ux; the third uz.
  EXPECT_EQ(m.added,
            (std::vector<std::array<int, 2>>{{0, 2}, {65, 2}, {0, 1}, {10, 1}, {0, 0}, {10, 2}}));
}

TEST(RigidBodyModes, OneSymmetryPlaneLeavesThree) {
  const Matrix3X x = plate(11, 6);
  NodalConstraints constraints;
  constraints.mask.assign(66, 0);
  for (int j = 0; j < 6; ++j) {
    constraints.add_symmetry(j * 11, 0);  // x = 0: ux, ry, rz
  }
  ASSERT_EQ(constraints.mask[0], ux | ry | rz);
  const RigidBodyModes m = find_free_rigid_body_modes(x, constraints.mask);
  EXPECT_EQ(m.free_count, 3);
  EXPECT_EQ(m.free_modes, (std::vector<std::string>{
                              "translation along y",
                              "translation along z",
                              "rotation about an axis along x through (0, 25, 0) mm",
                          }));
  expect_added_removes_all(x, constraints.mask, m);
  EXPECT_EQ(count_rotations(m), 0);
}

TEST(RigidBodyModes, SymmetryPlaneInTurnedNodeAxesLeavesTheTurnedModes) {
  // The plate of OneSymmetryPlaneLeavesThree turned 30 degrees about z, its symmetry plane (the
  // turned x = 0 edge) held in node axes turned with it: ux, ry, rz of those axes. The free modes
  // are the unturned ones turned: the translations along the turned y and along z, the rotation
  // about the turned x; the added holds (in node axes where a node has them) remove them all.
  const double c = std::cos(std::numbers::pi / 6.0), s = std::sin(std::numbers::pi / 6.0);
  const Mat3 turn = (Mat3() << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0).finished();
  const Matrix3X x = turn * plate(11, 6);
  std::vector<unsigned char> held(66, 0);
  NodeFrames frames(66);
  for (int j = 0; j < 6; ++j) {
    held[static_cast<std::size_t>(j * 11)] = ux | ry | rz;
    frames.set(j * 11, NodeFrame{turn, turn});
  }
  const RigidBodyModes m = find_free_rigid_body_modes(x, held, frames);
  EXPECT_EQ(m.free_count, 3);
  ASSERT_EQ(m.free_modes.size(), 3u);
  EXPECT_EQ(m.free_modes[0], "translation along (-0.5, 0.866025, 0)");
  EXPECT_EQ(m.free_modes[1], "translation along z");
  EXPECT_EQ(m.free_modes[2].rfind("rotation about an axis along (0.866025, 0.5, 0) through", 0), 0u)
      << m.free_modes[2];
  // Without the frames the same masks would hold the global ux, ry, rz: other modes.
  EXPECT_NE(find_free_rigid_body_modes(x, held).free_modes, m.free_modes);
  EXPECT_EQ(static_cast<int>(m.added.size()), 3);
  const RigidBodyModes after = find_free_rigid_body_modes(x, with_added(held, m), frames);
  EXPECT_EQ(after.free_count, 0);
}

TEST(RigidBodyModes, TwoSymmetryPlanesLeaveTheNormalTranslation) {
  const Matrix3X x = plate(11, 6);
  NodalConstraints constraints;
  constraints.mask.assign(66, 0);
  for (int j = 0; j < 6; ++j) {
    constraints.add_symmetry(j * 11, 0);  // x = 0
  }
  for (int i = 0; i < 11; ++i) {
    constraints.add_symmetry(i, 1);  // y = 0: uy, rx, rz
  }
  const RigidBodyModes m = find_free_rigid_body_modes(x, constraints.mask);
  EXPECT_EQ(m.free_count, 1);
  EXPECT_EQ(m.free_modes, std::vector<std::string>{"translation along z"});
  // Every uz moves alike: the tie goes to the lowest node.
  EXPECT_EQ(m.added, (std::vector<std::array<int, 2>>{{0, 2}}));
  expect_added_removes_all(x, constraints.mask, m);
}

TEST(RigidBodyModes, ClampedEdgeLeavesNone) {
  const Matrix3X x = plate(11, 6);
  std::vector<unsigned char> held(66, 0);
  for (int j = 0; j < 6; ++j) {
    held[j * 11] = 0x3f;
  }
  const RigidBodyModes m = find_free_rigid_body_modes(x, held);
  EXPECT_EQ(m.free_count, 0);
  EXPECT_TRUE(m.free_modes.empty());
  EXPECT_TRUE(m.added.empty());
  // One clamped node is enough too (its rotations hold the body's).
  std::vector<unsigned char> one(66, 0);
  one[65] = 0x3f;
  EXPECT_EQ(find_free_rigid_body_modes(x, one).free_count, 0);
}

TEST(RigidBodyModes, HingeLeavesARotationAboutItsLine) {
  // Translations held at two nodes: the body can turn about the line through them.
  const Matrix3X x = plate(11, 6);
  std::vector<unsigned char> held(66, 0);
  held[0] = held[10] = ux | uy | uz;  // (0, 0, 0) and (100, 0, 0)
  const RigidBodyModes m = find_free_rigid_body_modes(x, held);
  EXPECT_EQ(m.free_count, 1);
  EXPECT_EQ(m.free_modes,
            std::vector<std::string>{"rotation about an axis along x through (0, 0, 0) mm"});
  // uz farthest from the hinge, lowest node: (0, 50, 0) is node 55.
  EXPECT_EQ(m.added, (std::vector<std::array<int, 2>>{{55, 2}}));
  expect_added_removes_all(x, held, m);

  // A diagonal hinge from (0, 0, 0) to (100, 50, 0).
  std::vector<unsigned char> diagonal(66, 0);
  diagonal[0] = diagonal[65] = ux | uy | uz;
  const RigidBodyModes d = find_free_rigid_body_modes(x, diagonal);
  EXPECT_EQ(d.free_count, 1);
  EXPECT_EQ(d.free_modes, std::vector<std::string>{"rotation about an axis along (0.894427, "
                                                   "0.447214, 0) through (0, 0, 0) mm"});
  expect_added_removes_all(x, diagonal, d);
}

TEST(RigidBodyModes, PinnedNodeLeavesRotationsAboutIt) {
  const Matrix3X x = plate(11, 6);
  std::vector<unsigned char> held(66, 0);
  held[13] = ux | uy | uz;  // (20, 10, 0)
  const RigidBodyModes m = find_free_rigid_body_modes(x, held);
  EXPECT_EQ(m.free_count, 3);
  EXPECT_EQ(m.free_modes, (std::vector<std::string>{
                              "rotation about an axis along x through (0, 10, 0) mm",
                              "rotation about an axis along y through (20, 0, 0) mm",
                              "rotation about an axis along z through (20, 10, 0) mm",
                          }));
  expect_added_removes_all(x, held, m);
  EXPECT_EQ(count_rotations(m), 0);
}

TEST(RigidBodyModes, SingleNodeNeedsRotationHolds) {
  Matrix3X x(3, 1);
  x.col(0) = Vec3(5.0, -2.0, 7.0);
  const std::vector<unsigned char> held(1, 0);
  const RigidBodyModes m = find_free_rigid_body_modes(x, held);
  EXPECT_EQ(m.free_count, 6);
  EXPECT_EQ(m.free_modes[3], "rotation about an axis along x through (0, -2, 7) mm");
  EXPECT_EQ(m.added,
            (std::vector<std::array<int, 2>>{{0, 0}, {0, 1}, {0, 2}, {0, 3}, {0, 4}, {0, 5}}));
  expect_added_removes_all(x, held, m);
  // Translations held: the three rotations about the node remain.
  const RigidBodyModes t = find_free_rigid_body_modes(x, {ux | uy | uz});
  EXPECT_EQ(t.free_count, 3);
  EXPECT_EQ(t.free_modes[2], "rotation about an axis along z through (5, -2, 0) mm");
  EXPECT_EQ(t.added, (std::vector<std::array<int, 2>>{{0, 3}, {0, 4}, {0, 5}}));
}

TEST(RigidBodyModes, CollinearNodesNeedOneRotationHold) {
  Matrix3X x(3, 5);
  for (int i = 0; i < 5; ++i) {
    x.col(i) = Vec3(10.0 * i, 0.0, 0.0);
  }
  const std::vector<unsigned char> held(5, 0);
  const RigidBodyModes m = find_free_rigid_body_modes(x, held);
  EXPECT_EQ(m.free_count, 6);
  expect_added_removes_all(x, held, m);
  // Translations cannot hold the turn about the line itself: exactly one rotation hold, about x.
  EXPECT_EQ(count_rotations(m), 1);
  EXPECT_EQ(m.added.back(), (std::array<int, 2>{0, 3}));
  // The rest: ux once, uy and uz at the two ends.
  std::vector<std::array<int, 2>> translations(m.added.begin(), m.added.end() - 1);
  std::sort(translations.begin(), translations.end());
  EXPECT_EQ(translations,
            (std::vector<std::array<int, 2>>{{0, 0}, {0, 1}, {0, 2}, {4, 1}, {4, 2}}));
}

TEST(RigidBodyModes, RejectsBadInput) {
  EXPECT_THROW(find_free_rigid_body_modes(Matrix3X(3, 0), {}), std::invalid_argument);
  EXPECT_THROW(find_free_rigid_body_modes(plate(3, 3), std::vector<unsigned char>(8, 0)),
               std::invalid_argument);
  Matrix3X x = plate(3, 3);
  x(1, 4) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(find_free_rigid_body_modes(x, std::vector<unsigned char>(9, 0)),
               std::invalid_argument);
}

}  // namespace
}  // namespace sf
