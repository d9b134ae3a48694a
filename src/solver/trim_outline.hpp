#pragma once
// Where a trim line runs, seen along its direction of projection (solver/trim.hpp): a closed
// polyline (given in the case or read from a file's curves), or a tool's outline grown by an
// offset. A point is inside a polyline by the even-odd rule; inside a tool's outline when its
// projection lies within the offset of the projection of one of the tool's triangles (so the
// outline grown by d is the set at distance d from the tool's footprint: rounded at its convex
// corners, as a trim at a distance from a punch is).
#include <memory>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace sf {

class BoxTree;

struct TrimOutline {
  std::vector<Vec3> points;               ///< mm, closed: the last point joins the first
  Vec3 direction = Vec3(0.0, 0.0, -1.0);  ///< projected along it onto the part
  bool keep_inside = true;                ///< keep what projects inside (else outside)
  /// Or (points empty) a tool's outline: its triangles where it stands (mm, a column per node)
  std::vector<Tri3> tool_triangles;
  double offset = 0.0;  ///< mm, >= 0: the tool's outline grown by it

  /// A closed polyline's outline.
  static TrimOutline polyline(std::vector<Vec3> points, const Vec3& direction, bool keep_inside) {
    return {std::move(points), direction, keep_inside, {}, 0.0};
  }
};

/// The outline across its direction, ready to tell which side a point lies on.
class TrimRegion {
 public:
  /// InputError naming `source` (the part's file) for a polyline of fewer than 3 points or of no
  /// area across the direction, a tool without triangles, a direction of zero length or a negative
  /// offset.
  TrimRegion(const TrimOutline& outline, const std::string& source);
  ~TrimRegion();
  TrimRegion(const TrimRegion&) = delete;
  TrimRegion& operator=(const TrimRegion&) = delete;

  /// Whether a point (mm) projects on the kept side.
  bool keeps(const Vec3& point) const { return inside(project(point)) == keep_inside_; }

 private:
  Vec2 project(const Vec3& p) const { return {p.dot(e1_), p.dot(e2_)}; }
  bool inside(const Vec2& p) const;
  bool inside_polyline(const Vec2& p) const;
  bool near_tool(const Vec2& p) const;

  Vec3 e1_, e2_;  ///< the plane across the direction
  bool keep_inside_ = true;
  std::vector<Vec2> polyline_;
  std::vector<std::array<Vec2, 3>> triangles_;  ///< the tool's, projected
  std::unique_ptr<BoxTree> tree_;               ///< over the projected triangles' boxes
  double offset_ = 0.0;
};

}  // namespace sf
