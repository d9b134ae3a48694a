// The directors' turn found once per node (element/node_turns.hpp) against each element turning
// its own directors (rotate_director, Rodrigues' formula): the same bits, for still nodes, tiny,
// ordinary and large angles; and the turn itself against the exact rotation of a vector.
#include "element/node_turns.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <random>

#include "element/shell_directors.hpp"

namespace sf {
namespace {

bool same_bits(const Vec3& a, const Vec3& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0;
}

// omega (rad/s) of 4 nodes per element over 50 elements: still nodes, angles from 1e-300 to
// 3 rad per step, random axes; the elements' directors unit vectors near +z.
TEST(NodeTurns, TurningByTheNodesTurnGivesTheBitsOfTheElementsOwnTurn) {
  constexpr int kElements = 50;
  constexpr int kNodes = 4 * kElements;
  constexpr double dt = 1.3e-7;  // s
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Matrix3X omega(3, kNodes);
  const double angles[] = {0.0, 1e-300, 1e-12, 1e-4, 0.3, 3.0};  // rad per step
  for (int i = 0; i < kNodes; ++i) {
    const Vec3 axis = Vec3(unit(random), unit(random), unit(random)).normalized();
    omega.col(i) = angles[i % 6] / dt * axis;
  }
  NodeTurns turns;
  compute_node_turns(omega, dt, turns);
  int compared = 0;
  for (int e = 0; e < kElements; ++e) {
    const int nodes[4] = {4 * e, 4 * e + 1, 4 * e + 2, 4 * e + 3};
    Quad3 w;
    double directors[12], again[12];
    for (int a = 0; a < 4; ++a) {
      w.col(a) = omega.col(nodes[a]);
      const Vec3 d = Vec3(0.2 * unit(random), 0.2 * unit(random), 1.0).normalized();
      for (int k = 0; k < 3; ++k) {
        directors[3 * a + k] = again[3 * a + k] = d(k);
      }
    }
    Quad3 start, end, start_by_node, end_by_node;
    ASSERT_TRUE(advance_element_directors<4>(directors, w, dt, start, end));
    ASSERT_TRUE(advance_element_directors<4>(again, nodes, turns, start_by_node, end_by_node));
    for (int a = 0; a < 4; ++a) {
      EXPECT_TRUE(same_bits(end.col(a), end_by_node.col(a))) << "element " << e << " node " << a;
      EXPECT_EQ(std::memcmp(directors + 3 * a, again + 3 * a, sizeof(double) * 3), 0);
      ++compared;
    }
  }
  EXPECT_EQ(compared, kNodes);
}

// A node at rest leaves the director's bits as they are; a turn by phi agrees with the rotation
// matrix exp([phi]x) (Eigen's AngleAxis) to round-off (1e-15) and keeps the length 1 to 1e-15.
TEST(NodeTurns, ATurnIsTheRotationByTheRotationVector) {
  const Vec3 d = Vec3(0.1, -0.2, 1.0).normalized();
  EXPECT_TRUE(same_bits(turn_director(director_turn(Vec3::Zero()), d), d));
  for (const double angle : {1e-9, 0.01, 1.0, 3.0}) {
    const Vec3 axis = Vec3(1.0, 2.0, -0.5).normalized();
    const Vec3 turned = turn_director(director_turn(angle * axis), d);
    const Vec3 exact = Eigen::AngleAxisd(angle, axis) * d;
    EXPECT_LT((turned - exact).norm(), 1e-15) << angle;
    EXPECT_NEAR(turned.norm(), 1.0, 1e-15) << angle;
  }
}

}  // namespace
}  // namespace sf
