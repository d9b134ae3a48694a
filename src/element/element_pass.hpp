#pragma once
// The inputs of an internal-force pass and what one share of it (a thread's range of elements)
// writes: the element loop (element_loop.hpp) takes a range of a block's elements and an
// ElementOutputs, writes only their own corner slots, per-element state and time steps, and sums
// the pass's works exactly (core/exact_sum.hpp), so that neither the nodal forces nor the works
// depend on how the elements were shared out.
#include "core/exact_sum.hpp"
#include "core/types.hpp"
#include "element/element_failure.hpp"
#include "element/node_turns.hpp"

namespace sf {

/// The kinematics a pass reads: x at the end of the step (mm), v (mm/s) and omega (rad/s) at
/// mid-step, the step dt (s).
struct ElementInputs {
  const Matrix3X& x;
  const Matrix3X& v;
  const Matrix3X& omega;
  double dt = 0.0;  ///< s
  /// true in the implicit static steps, whose dt is a pseudo-time: rate-dependent laws then take
  /// their rate-free flow stress.
  bool pseudo_time = false;
  /// Each node's director turn over the step (dt omega): run_element_pass finds them for a part
  /// whose elements turn directors (assumed strain); null otherwise.
  const NodeTurns* turns = nullptr;

  double rate_dt() const { return pseudo_time ? 0.0 : dt; }  ///< s, for rate-dependent laws
};

/// One share's outputs. Aligned apart so that threads do not share cache lines.
struct alignas(64) ElementOutputs {
  double* corners = nullptr;     ///< kCornerWidth per corner slot (element/corner_forces.hpp)
  double* element_dt = nullptr;  ///< s per element, the critical step at x; null: not wanted
  ExactSum internal_work;        ///< N mm, stress work increments (excludes hourglass)
  ExactSum plastic_work;         ///< N mm, their plastic part
  ExactSum hourglass_work;       ///< N mm, work of the hourglass (stabilisation) forces
  ElementFailure failure;        ///< the share's first failure; the loop stops there

  void reset(double* corner_buffer, double* time_steps) {
    corners = corner_buffer;
    element_dt = time_steps;
    internal_work.clear();
    plastic_work.clear();
    hourglass_work.clear();
    failure = ElementFailure();
  }

  /// Records the share's failure at element e (triangle: its index among the triangles).
  void fail(int e, ElementFailure::Kind kind, const char* when = "", int triangle = -1) {
    failure.element = e;
    failure.triangle = triangle;
    failure.kind = kind;
    failure.when = when;
  }
};

}  // namespace sf
