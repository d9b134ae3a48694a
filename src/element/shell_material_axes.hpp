#pragma once
// Material (rolling-direction) axes of shell elements, fixed once at the start of a run.
#include <vector>

#include "core/types.hpp"

namespace sf {

/// The rolling direction's in-plane part must be at least this long (unit direction), i.e. the
/// direction must be more than about 5.7 deg away from an element's normal.
inline constexpr double kMinRollingDirectionInPlane = 0.1;

/// Per element of `quads` on the configuration `x` (mm), the angle (rad, in (-pi, pi]) from the
/// element's corotational e1 axis (compute_shell_geometry: side x21 projected on the element
/// plane) to the rolling direction projected on the element plane, counter-clockwise about e3:
/// angle = atan2(d . e2, d . e1). `rolling_direction` need not be unit. Throws InputError naming
/// the element (0-based index and centroid, mm) when the direction's in-plane part is shorter
/// than kMinRollingDirectionInPlane (near the element's normal) or the element is degenerate.
std::vector<double> compute_material_angles(const Matrix3X& x, const QuadConn& quads,
                                            const Vec3& rolling_direction);

}  // namespace sf
