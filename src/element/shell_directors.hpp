#pragma once
// Directors of the shell: the unit fibre at each node of each element, rotated with the node. The
// assumed-strain quads take their curvature and transverse shear from the nodes' positions and
// directors (shell_quad_directors.hpp), so a node's rotation about its own director, the drilling
// rotation that no shell element resists, moves nothing: flat elements on a curved mesh are then
// not hinged to each other through it, as they are when each element takes the nodal rotation
// about its own normal (docs/element-and-material.md, "Directors").
#include <cmath>
#include <numbers>
#include <vector>

#include "core/types.hpp"
#include "element/node_turns.hpp"
#include "element/shell_part.hpp"

namespace sf {

/// rad: at a fold of the initial mesh each element keeps its own normal as the node's director; a
/// node is at a fold when some element's normal is more than this from the node's averaged
/// normal (30 deg: elements up to about 60 deg apart are facets of one smooth surface).
inline constexpr double kFoldAngle = std::numbers::pi / 6.0;

/// Per node of x (mm): the unit area-weighted mean of the normals of the elements around it, or
/// zero for a node without elements or whose elements' normals cancel.
Matrix3X compute_nodal_normals(const ShellPart& part, const Matrix3X& x);

/// Sets every element-node director of `state` (sized by make_shell_state) at the initial
/// coordinates x (mm): the node's averaged normal where the surface is smooth, the element's own
/// normal at a fold (kFoldAngle). Throws InputError naming the element on a degenerate one.
void initialize_directors(const ShellPart& part, const Matrix3X& x, ShellState& state);

/// The unit vector d turned by the rotation vector phi (rad; Rodrigues' formula, exact for any
/// angle), renormalised against round-off.
inline Vec3 rotate_director(const Vec3& d, const Vec3& phi) {
  return turn_director(director_turn(phi), d);
}

/// An element's directors over a step: `start` read from the state at `director` (3 per node),
/// `end` = start turned by turn_of(i) (a DirectorTurn for node i of the element) and written
/// back. Returns false, leaving the state as it is, if they were never set
/// (initialize_directors): a program error the element loop reports.
template <int N, class TurnOf>
[[nodiscard]] inline bool turn_element_directors(double* director, TurnOf turn_of,
                                                 Eigen::Matrix<double, 3, N>& start,
                                                 Eigen::Matrix<double, 3, N>& end) {
  for (int i = 0; i < N; ++i) {
    start.col(i) = Vec3(director[3 * i], director[3 * i + 1], director[3 * i + 2]);
    if (!(start.col(i).squaredNorm() > 0.5)) {
      return false;
    }
  }
  for (int i = 0; i < N; ++i) {
    double* c = director + 3 * i;
    end.col(i) = turn_director(turn_of(i), start.col(i));
    c[0] = end(0, i);
    c[1] = end(1, i);
    c[2] = end(2, i);
  }
  return true;
}

/// The directors turned by dt w_I (w: the element's nodal angular velocities, rad/s; dt: s): the
/// reference the node turns below must reproduce bit for bit (tests/element/test_node_turns.cpp).
template <int N>
[[nodiscard]] inline bool advance_element_directors(double* director,
                                                    const Eigen::Matrix<double, 3, N>& w, double dt,
                                                    Eigen::Matrix<double, 3, N>& start,
                                                    Eigen::Matrix<double, 3, N>& end) {
  return turn_element_directors<N>(
      director, [&](int i) { return director_turn(dt * w.col(i)); }, start, end);
}

/// The same with each node's turn found beforehand (compute_node_turns over the step's dt omega):
/// the same bits. nodes: the element's N node ids.
template <int N>
[[nodiscard]] inline bool advance_element_directors(double* director, const int* nodes,
                                                    const NodeTurns& turns,
                                                    Eigen::Matrix<double, 3, N>& start,
                                                    Eigen::Matrix<double, 3, N>& end) {
  return turn_element_directors<N>(
      director, [&](int i) { return turns.of(nodes[i]); }, start, end);
}

}  // namespace sf
