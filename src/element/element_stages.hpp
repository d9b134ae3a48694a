#pragma once
// Stages of the element loop (element_loop.hpp) that formulations of one shape share: the quads'
// corotational geometries, kBlockLanes elements at a time, and the triangles' end-of-step
// geometry.
#include <algorithm>

#include "element/element_loop.hpp"
#include "element/shell_geometry_batch.hpp"
#include "element/shell_triangle_geometry.hpp"

namespace sf {

/// The geometries of the quad being computed, at mid-step and at the end of the step, from
/// blocks of kBlockLanes consecutive elements computed together in SIMD lanes.
class QuadGeometryStage {
 public:
  QuadGeometryStage(const ElementInputs& in, const int* conn) : in_(in), conn_(conn) {}

  /// Before element e of the loop over [begin, end): a new block at every kBlockLanes-th one.
  SF_ELEMENT_STAGE void prepare(int e, int begin, int end) {
    lane_ = (e - begin) % kBlockLanes;
    if (lane_ == 0) {
      compute_quad_geometry_block(in_.x.data(), in_.v.data(), conn_, e,
                                  std::min(kBlockLanes, end - e), in_.dt, block_);
    }
  }

  /// The element's geometry at x - dt/2 v (the strains') into `g`; fails where it is inverted,
  /// collapsed or not finite.
  SF_ELEMENT_STAGE StageResult mid(const ShellGeometry*& g) const {
    g = &block_.mid[lane_];
    return block_.mid_ok[lane_] ? StageResult{}
                                : StageResult{ElementFailure::Kind::invalid_geometry, "mid-step"};
  }
  /// The same at x (the forces').
  SF_ELEMENT_STAGE StageResult end(const ShellGeometry*& g) const {
    g = &block_.end[lane_];
    return block_.end_ok[lane_]
               ? StageResult{}
               : StageResult{ElementFailure::Kind::invalid_geometry, "end of step"};
  }

 private:
  const ElementInputs& in_;
  const int* conn_;
  QuadGeometryBlock block_;  // of the kBlockLanes elements holding the current one
  int lane_ = 0;
};

/// A triangle's geometry at x (end), given the one at mid-step: fails on a collapsed triangle and
/// on one whose normal flipped within the step.
SF_ELEMENT_STAGE StageResult triangle_end_geometry(const Tri3& xe, const TriangleGeometry& mid,
                                                   TriangleGeometry& end) {
  if (!compute_triangle_geometry(xe, end)) {
    return {ElementFailure::Kind::invalid_geometry, "end of step"};
  }
  if (!(end.frame.col(2).dot(mid.frame.col(2)) > 0.0)) {
    return {ElementFailure::Kind::inverted};
  }
  return {};
}

}  // namespace sf
