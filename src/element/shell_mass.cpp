#include "element/shell_mass.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "element/shell_geometry.hpp"
#include "element/shell_geometry_batch.hpp"
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
    const double m_node = 0.25 * material_of(part, e).density * t * g.area;
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
    const double m_node = material_of(part, e).density * t * tg.area / 3.0;
    const double i_node = rotational_inertia_factor(tg.area, t) * m_node;
    for (int i = 0; i < 3; ++i) {
      mass(part.triangles(i, k)) += m_node;
      rotational_inertia(part.triangles(i, k)) += i_node;
    }
  }
}

namespace {

// The wave speed of element e's material, evaluated again only when the material changes.
class WaveSpeeds {
 public:
  explicit WaveSpeeds(const ShellPart& part) : part_(part) {}
  double of(int e) {
    const int m = material_index(part_, e);
    if (m != material_) {
      material_ = m;
      speed_ = material_wave_speed(part_.materials[static_cast<std::size_t>(m)]);
    }
    return speed_;
  }

 private:
  const ShellPart& part_;
  int material_ = -1;
  double speed_ = 0.0;
};

// L / c of triangle e (element index, quads first): L = 2 A / max side, the smallest altitude.
double triangle_time_step(const Matrix3X& x, const ShellPart& part, int e, double c,
                          TriangleGeometry& tg) {
  const int k = e - static_cast<int>(part.quads.cols());
  compute_triangle_geometry_or_throw(gather_triangle(x, part.triangles, k), e, k, "time step", tg);
  return triangle_characteristic_length(tg) / c;
}

// Calls step(e, dt) for every element in order, dt = L / c; the quads' areas come in blocks of
// kBlockLanes from the SIMD geometry kernel (the time loop evaluates this every cycle).
template <class Step>
void for_each_time_step(const ShellPart& part, const Matrix3X& x, Step step) {
  WaveSpeeds c(part);
  const int n_quads = static_cast<int>(part.quads.cols());
  for (int e0 = 0; e0 < n_quads; e0 += kBlockLanes) {
    const int count = std::min(kBlockLanes, n_quads - e0);
    double area[kBlockLanes];
    bool ok[kBlockLanes];
    compute_quad_area_block(x.data(), part.quads.data(), e0, count, area, ok);
    for (int j = 0; j < count; ++j) {
      const int e = e0 + j;
      if (!ok[j]) {
        throw_invalid_geometry(e, "time step");
      }
      step(e, quad_time_step(gather_quad(x, part.quads, e), area[j], c.of(e)));
    }
  }
  TriangleGeometry tg;
  for (int e = n_quads; e < element_count(part); ++e) {
    step(e, triangle_time_step(x, part, e, c.of(e), tg));
  }
}

}  // namespace

double material_wave_speed(const ShellMaterial& material) {
  return plane_stress_wave_speed(young_modulus(material.law), poisson_ratio(material.law),
                                 material.density);
}

double quad_time_step(const Quad3& xe, double area, double wave_speed) {
  double side2 = 0.0;
  for (int i = 0; i < 4; ++i) {
    side2 = std::max(side2, (xe.col((i + 1) % 4) - xe.col(i)).squaredNorm());
  }
  return area / (std::sqrt(side2) * wave_speed);
}

StableStep smallest_time_step(std::span<const double> element_dt) {
  StableStep best{std::numeric_limits<double>::infinity(), -1};
  for (std::size_t e = 0; e < element_dt.size(); ++e) {
    if (element_dt[e] < best.dt) {
      best = {element_dt[e], static_cast<int>(e)};
    }
  }
  return best;
}

StableStep compute_stable_time_step(const ShellPart& part, const Matrix3X& x,
                                    const ShellState& /*state*/) {
  StableStep best{std::numeric_limits<double>::infinity(), -1};
  for_each_time_step(part, x, [&best](int e, double dt) {
    if (dt < best.dt) {
      best = {dt, e};
    }
  });
  return best;
}

StableStep compute_element_time_steps(const ShellPart& part, const Matrix3X& x,
                                      std::span<double> element_dt) {
  if (element_dt.size() != static_cast<std::size_t>(element_count(part))) {
    throw std::invalid_argument("compute_element_time_steps: one value per element expected");
  }
  for_each_time_step(
      part, x, [element_dt](int e, double dt) { element_dt[static_cast<std::size_t>(e)] = dt; });
  return smallest_time_step(element_dt);
}

void compute_element_masses(const ShellPart& part, const Matrix3X& x, const ShellState& state,
                            std::vector<double>& mass, std::vector<double>& inertia_factor) {
  const auto n = static_cast<std::size_t>(element_count(part));
  const auto n_quads = static_cast<std::size_t>(part.quads.cols());
  mass.assign(n, 0.0);
  inertia_factor.assign(n, 0.0);
  ShellGeometry g;
  TriangleGeometry tg;
  for (std::size_t e = 0; e < n; ++e) {
    const int ei = static_cast<int>(e);
    double area = 0.0;
    if (e < n_quads) {
      compute_shell_geometry_or_throw(gather_quad(x, part.quads, ei), ei, "mass", g);
      area = g.area;
    } else {
      const int k = ei - static_cast<int>(n_quads);
      compute_triangle_geometry_or_throw(gather_triangle(x, part.triangles, k), ei, k, "mass", tg);
      area = tg.area;
    }
    const double t = state.thickness[e];
    mass[e] = material_of(part, ei).density * t * area;
    inertia_factor[e] = rotational_inertia_factor(area, t);
  }
}

}  // namespace sf
