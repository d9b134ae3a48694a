#pragma once
// The clearance between two rigid tool surfaces along a direction: how far `moving` can travel
// along `direction` before it touches `other` (both in their reference positions). Used by a
// gap end of an operation (a binder closing onto the die).
#include <optional>

#include "core/types.hpp"
#include "mesh/triangle_surface.hpp"

namespace sf {

/// mm, the least distance along `direction` (unit) from a node of `moving` to a triangle of
/// `other`, or from a node of `other` back along -direction to a triangle of `moving`; nullopt
/// when no such ray meets the other surface (they never touch moving that way). Negative when
/// they overlap along the direction already.
std::optional<double> clearance_along(const TriangleSurface& moving, const TriangleSurface& other,
                                      const Vec3& direction);

}  // namespace sf
