#pragma once
// The turn of the directors at each node over one step (issue 34, item 2): every element at a
// node turns its director there by the same rotation vector dt omega, so its axis, cosine and
// sine (a square root, a division and a sine-cosine pair) are found once per node and cycle
// instead of once per element corner. Applying a node's turn does exactly the operations of
// rotate_director, so the directors keep their bits.
#include <vector>

#include "core/types.hpp"

namespace sf {

/// Rodrigues' rotation by a rotation vector phi (rad) in parts: the unit axis, cos and sin of
/// the angle. still: phi = 0, which leaves a vector as it is (not even renormalised).
struct DirectorTurn {
  Vec3 axis;
  double c = 1.0;
  double s = 0.0;
  bool still = true;
};

/// The turn by phi (rad).
inline DirectorTurn director_turn(const Vec3& phi) {
  const double angle2 = phi.squaredNorm();
  if (angle2 == 0.0) {
    return {Vec3::Zero(), 1.0, 0.0, true};
  }
  const double angle = std::sqrt(angle2);
  return {phi / angle, std::cos(angle), std::sin(angle), false};
}

/// The unit vector d turned (exact for any angle), renormalised against round-off.
inline Vec3 turn_director(const DirectorTurn& t, const Vec3& d) {
  if (t.still) {
    return d;
  }
  const Vec3 r = t.c * d + t.s * t.axis.cross(d) + ((1.0 - t.c) * t.axis.dot(d)) * t.axis;
  return r / r.norm();
}

/// Every node's turn over one step, structure of arrays; sized on first use, then no allocation.
/// A node is still where s == 0 (a non-zero angle has a non-zero sine in double).
struct NodeTurns {
  std::vector<double> axis_x, axis_y, axis_z;  ///< -, the unit axis
  std::vector<double> c, s;                    ///< -, cos and sin of the angle

  DirectorTurn of(int node) const {
    const auto i = static_cast<std::size_t>(node);
    return {Vec3(axis_x[i], axis_y[i], axis_z[i]), c[i], s[i], s[i] == 0.0};
  }
};

/// turns = each node's turn by dt omega.col(i) (omega: rad/s, dt: s); threads share out the
/// nodes.
void compute_node_turns(const Matrix3X& omega, double dt, NodeTurns& turns);

}  // namespace sf
