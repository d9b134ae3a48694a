#pragma once
// Material (rolling-direction) axes of shell elements, fixed once at the start of a run.
#include <cmath>
#include <vector>

#include "core/types.hpp"
#include "material/plane_stress.hpp"

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

/// The same for a part of quads then triangles (element numbering of ShellPart): a triangle's e1
/// is its side x21 projected on its plane (compute_triangle_geometry).
std::vector<double> compute_material_angles(const Matrix3X& x, const QuadConn& quads,
                                            const TriConn& triangles,
                                            const Vec3& rolling_direction);

// Material axes of one element for a law that has them: cos and sin of the material angle and
// the membrane and curvature strain increments (times dt) in those axes.
struct MaterialFrame {
  double c = 1.0;
  double s = 0.0;
  Vec3 d_m;
  Vec3 d_k;
};
struct NoMaterialFrame {};

/// The material frame of element e for a law with material axes: dt d_m and dt d_k turned by the
/// element's material angle (none stored: angle 0). Strains are linear in z, so they are turned
/// once per element.
inline MaterialFrame make_material_frame(const Vec3& dt_d_m, const Vec3& dt_d_k,
                                         const double* material_angle, int e) {
  MaterialFrame axes;
  axes.d_m = dt_d_m;
  axes.d_k = dt_d_k;
  if (material_angle) {
    axes.c = std::cos(material_angle[e]);
    axes.s = std::sin(material_angle[e]);
    axes.d_m = rotate_strain(dt_d_m, axes.c, axes.s);
    axes.d_k = rotate_strain(dt_d_k, axes.c, axes.s);
  }
  return axes;
}

}  // namespace sf
