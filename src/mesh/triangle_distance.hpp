#pragma once
// Closest points between segments and triangles (mm): the exact kernels of the tool diagnosis
// (mesh/tool_diagnosis.hpp) and of the tool-to-blank clearance (mesh/surface_approach.hpp).
// Ericson, Real-Time Collision Detection (2005): 5.1.5 (point-triangle), 5.1.9 (segment-segment).
#include <optional>

#include "core/types.hpp"

namespace sf {

/// A point of each of two sets and their distance (mm).
struct ClosestPair {
  Vec3 first = Vec3::Zero();
  Vec3 second = Vec3::Zero();
  double distance = 0.0;
};

/// The closest points of segments [p0, p1] and [q0, q1] (either may have zero length).
ClosestPair closest_segment_points(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1);

/// The point of triangle `t` (columns: its nodes) closest to p.
Vec3 closest_point_on_triangle(const Vec3& p, const Tri3& t);

/// Where segment [p0, p1] meets triangle `t` (inside or on its boundary), when its end points lie
/// on different sides of the triangle's plane or one lies in it; nothing for a segment lying in
/// the plane (its closest points to the triangle's edges tell).
std::optional<Vec3> segment_triangle_crossing(const Vec3& p0, const Vec3& p1, const Tri3& t);

/// The closest points of two triangles: the least of the vertex-triangle and edge-edge distances,
/// or a point where an edge of one crosses the other (distance 0).
ClosestPair closest_triangle_points(const Tri3& a, const Tri3& b);

/// Signed in-plane distance (mm) from p, a point in the triangle's plane, to the triangle's
/// boundary: positive inside (the least distance to its three edge lines), negative outside.
double inside_margin(const Vec3& p, const Tri3& t);

}  // namespace sf
