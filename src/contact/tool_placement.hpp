#pragma once
// Where a rigid tool stands: its mesh's point X (as meshed) at rotation X + translation.
#include "core/types.hpp"

namespace sf {

struct ToolPlacement {
  Mat3 rotation = Mat3::Identity();
  Vec3 translation = Vec3::Zero();  ///< mm

  Vec3 apply(const Vec3& mesh_point) const { return rotation * mesh_point + translation; }
  bool turned() const { return rotation != Mat3::Identity(); }
};

/// The rotation by `angle` (rad) about the unit vector `axis` (right-hand rule).
Mat3 rotation_about(const Vec3& axis, double angle);

/// The rotation vector (axis times angle, rad) of `rotation` (its angle in [0, pi]).
Vec3 rotation_vector(const Mat3& rotation);

}  // namespace sf
