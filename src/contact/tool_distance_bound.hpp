#pragma once
// A conservative lower bound of the distance from a point to a rigid tool surface, cheap where the
// point is far from the tool: what lets the penalty contact skip a blank node until its motion
// relative to the tool could have brought it within the search cutoff.
#include "contact/modified_search.hpp"
#include "core/types.hpp"
#include "mesh/triangle_surface.hpp"

namespace sf {

/// Lower bounds of the distance to one tool (reference frame), immutable once built.
class ToolDistanceBound {
 public:
  /// `surface` must outlive the bound.
  explicit ToolDistanceBound(const TriangleSurface& surface);

  /// A lower bound of the distance (mm) from p to the surface, looking no farther than `reach`
  /// (mm): the distance from p to the tool's bounding box when that is at least `reach` (a few
  /// flops); otherwise the least point-triangle distance when a triangle lies within `reach`
  /// (found with the modified search's grid and kernel), and `reach` when none does. Up to
  /// rounding (see `rounding_allowance`) it never exceeds the true distance.
  double lower_bound(const Vec3& p, double reach) const;

  /// What to subtract from a bound found at a point of size `point_size` (the largest coordinate,
  /// mm) whose value is `bound` (mm) to cover the rounding of the bound, of the distance the node
  /// moves, and of the search's own distances: 1e-9 of the largest length involved, some 10^6
  /// times their relative rounding (~1e-16) and far below any physical length.
  double rounding_allowance(double point_size, double bound) const {
    return 1e-9 * (size_ + point_size + bound);
  }

 private:
  ModifiedSearch exact_;
  Vec3 lo_ = Vec3::Zero();  ///< the tool's bounding box, mm
  Vec3 hi_ = Vec3::Zero();
  double size_ = 0;  ///< the larger of its diagonal and its largest coordinate, mm
};

}  // namespace sf
