#pragma once
// A conservative lower bound of the distance from a point to a rigid tool surface, cheap where the
// point is far from the tool: what lets the penalty contact skip a blank node until its motion
// relative to the tool could have brought it within the search cutoff.
#include <vector>

#include "contact/modified_search.hpp"
#include "core/types.hpp"
#include "mesh/triangle_surface.hpp"

namespace sf {

/// What the tool looks like from a point near it, within a reach (ToolDistanceBound::
/// front_clearance): enough to prove a node within the search cutoff out of contact
/// (docs/contact.md, "Nodes near a tool but out of contact").
struct FrontClearance {
  /// A lower bound of the distance (mm) from the point to the surface, as lower_bound(p, reach).
  double distance = 0;
  /// The least point-triangle distance found (mm), an upper bound of the distance; infinite when
  /// no triangle lies within reach.
  double nearest = 0;
  /// The least signed distance (mm) of the point from the plane of a triangle within reach, on the
  /// side of the triangle's normal; infinite when no triangle lies within reach.
  double least_side = 0;
  /// An upper bound of the sine of the angle between any two face normals within reach.
  double cone_sine = 0;
  /// Every triangle within reach has its nodal normals on its face normal's side (N . n >
  /// normal_agreement) and the face normals within a cone narrower than 90 degrees: without
  /// this, the point's side of the surface along an interpolated normal is not known.
  bool sided = false;
};

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

  /// The clearance of p against every triangle within `reach` (mm): the bound and the sides as
  /// FrontClearance describes them. Costs about one modified search of radius `reach`.
  FrontClearance front_clearance(const Vec3& p, double reach) const;

  /// A triangle's nodal normals agree with its face normal when each has N . n above this: then
  /// the interpolated normal n(T) has n(T) . n > 0 over the triangle (and 1e-9 beyond its edges).
  static constexpr double normal_agreement = 1e-3;

 private:
  ModifiedSearch exact_;
  std::vector<char> agrees_;  ///< per triangle: its nodal normals agree with its face normal
  Vec3 lo_ = Vec3::Zero();    ///< the tool's bounding box, mm
  Vec3 hi_ = Vec3::Zero();
  double size_ = 0;  ///< the larger of its diagonal and its largest coordinate, mm
};

}  // namespace sf
