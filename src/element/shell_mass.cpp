#include "element/shell_mass.hpp"

#include <algorithm>
#include <limits>

#include "element/shell_geometry.hpp"
#include "element/shell_triangle_geometry.hpp"

namespace sf {

void compute_lumped_mass(const ShellPart& part, const Matrix3X& x, const ShellState& state,
                         VectorX& mass, VectorX& rotational_inertia) {
  mass = VectorX::Zero(x.cols());
  rotational_inertia = VectorX::Zero(x.cols());
  ShellGeometry g;
  for (int e = 0; e < part.quads.cols(); ++e) {
    compute_shell_geometry_or_throw(gather_quad(x, part.quads, e), e, "mass", g);
    const double t = state.thickness[e];
    const double m_node = 0.25 * part.density * t * g.area;
    const double i_node = rotational_inertia_factor(g.area, t) * m_node;
    for (int i = 0; i < 4; ++i) {
      mass(part.quads(i, e)) += m_node;
      rotational_inertia(part.quads(i, e)) += i_node;
    }
  }
  const int n_quads = static_cast<int>(part.quads.cols());
  TriangleGeometry tg;
  for (int k = 0; k < part.triangles.cols(); ++k) {
    const int e = n_quads + k;
    compute_triangle_geometry_or_throw(gather_triangle(x, part.triangles, k), e, k, "mass", tg);
    const double t = state.thickness[e];
    const double m_node = part.density * t * tg.area / 3.0;
    const double i_node = rotational_inertia_factor(tg.area, t) * m_node;
    for (int i = 0; i < 3; ++i) {
      mass(part.triangles(i, k)) += m_node;
      rotational_inertia(part.triangles(i, k)) += i_node;
    }
  }
}

StableStep compute_stable_time_step(const ShellPart& part, const Matrix3X& x,
                                    const ShellState& state) {
  const double c = plane_stress_wave_speed(young_modulus(part.material),
                                           poisson_ratio(part.material), part.density);
  StableStep best{std::numeric_limits<double>::infinity(), -1};
  ShellGeometry g;
  for (int e = 0; e < part.quads.cols(); ++e) {
    const Quad3 xe = gather_quad(x, part.quads, e);
    compute_shell_geometry_or_throw(xe, e, "time step", g);
    double side2 = 0.0;
    for (int i = 0; i < 4; ++i) {
      side2 = std::max(side2, (xe.col((i + 1) % 4) - xe.col(i)).squaredNorm());
    }
    const double dt = g.area / (std::sqrt(side2) * c);
    if (dt < best.dt) {
      best = {dt, e};
    }
  }
  const int n_quads = static_cast<int>(part.quads.cols());
  TriangleGeometry tg;
  for (int k = 0; k < part.triangles.cols(); ++k) {
    const int e = n_quads + k;
    compute_triangle_geometry_or_throw(gather_triangle(x, part.triangles, k), e, k, "time step",
                                       tg);
    const double dt = triangle_characteristic_length(tg) / c;
    if (dt < best.dt) {
      best = {dt, e};
    }
  }
  return best;
}

}  // namespace sf
