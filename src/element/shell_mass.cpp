#include "element/shell_mass.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "element/element_block.hpp"
#include "element/shell_geometry.hpp"
#include "element/shell_geometry_batch.hpp"
#include "element/shell_triangle_geometry.hpp"

namespace sf {

void compute_lumped_mass(const ShellPart& part, const Matrix3X& x, const ShellState& state,
                         VectorX& mass, VectorX& rotational_inertia) {
  mass = VectorX::Zero(x.cols());
  rotational_inertia = VectorX::Zero(x.cols());
  ShellGeometry g;
  TriangleGeometry tg;
  for (const ElementBlock& block : element_blocks(part)) {
    for (int e = block.first; e < block.end(); ++e) {
      const int k = block.local(e);
      const double t = state.thickness[e];
      double m_node = 0.0;
      double area = 0.0;
      if (block.shape == ElementShape::quad) {
        compute_shell_geometry_or_throw(gather_quad(x, part.quads, k), e, "mass", g);
        area = g.area;
        m_node = 0.25 * material_of(part, e).density * t * area;
      } else {
        compute_triangle_geometry_or_throw(gather_triangle(x, part.triangles, k), e, k, "mass", tg);
        area = tg.area;
        m_node = material_of(part, e).density * t * area / 3.0;
      }
      const double i_node = rotational_inertia_factor(area, t) * m_node;
      const int* nodes = block.element_nodes(e);
      for (int i = 0; i < block.nodes_per_element(); ++i) {
        mass(nodes[i]) += m_node;
        rotational_inertia(nodes[i]) += i_node;
      }
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

// L / c of triangle e of the triangle block: L = 2 A / max side, the smallest altitude.
double triangle_time_step(const Matrix3X& x, const ShellPart& part, const ElementBlock& block,
                          int e, double c, TriangleGeometry& tg) {
  const int k = block.local(e);
  compute_triangle_geometry_or_throw(gather_triangle(x, part.triangles, k), e, k, "time step", tg);
  return triangle_characteristic_length(tg) / c;
}

// step(e, dt) for the quads of `block`, their areas kBlockLanes at a time.
template <class Step>
void for_each_quad_time_step(const ShellPart& part, const ElementBlock& block, const Matrix3X& x,
                             WaveSpeeds& c, Step& step) {
  for (int l0 = 0; l0 < block.count; l0 += kBlockLanes) {
    const int count = std::min(kBlockLanes, block.count - l0);
    double area[kBlockLanes];
    bool ok[kBlockLanes];
    compute_quad_area_block(x.data(), block.nodes, l0, count, area, ok);
    for (int j = 0; j < count; ++j) {
      const int e = block.first + l0 + j;
      if (!ok[j]) {
        throw_invalid_geometry(e, "time step");
      }
      step(e, quad_time_step(gather_quad(x, part.quads, l0 + j), area[j], c.of(e)));
    }
  }
}

// Calls step(e, dt) for every element in order, dt = L / c; the quads' areas come in blocks of
// kBlockLanes from the SIMD geometry kernel (the time loop evaluates this every cycle).
template <class Step>
void for_each_time_step(const ShellPart& part, const Matrix3X& x, Step step) {
  WaveSpeeds c(part);
  TriangleGeometry tg;
  for (const ElementBlock& block : element_blocks(part)) {
    if (block.shape == ElementShape::quad) {
      for_each_quad_time_step(part, block, x, c, step);
      continue;
    }
    for (int e = block.first; e < block.end(); ++e) {
      step(e, triangle_time_step(x, part, block, e, c.of(e), tg));
    }
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
  const ElementBlocks blocks = element_blocks(part);
  mass.assign(n, 0.0);
  inertia_factor.assign(n, 0.0);
  ShellGeometry g;
  TriangleGeometry tg;
  for (std::size_t e = 0; e < n; ++e) {
    const int ei = static_cast<int>(e);
    const ElementBlock& block = blocks.of(ei);
    const int k = block.local(ei);
    double area = 0.0;
    if (block.shape == ElementShape::quad) {
      compute_shell_geometry_or_throw(gather_quad(x, part.quads, k), ei, "mass", g);
      area = g.area;
    } else {
      compute_triangle_geometry_or_throw(gather_triangle(x, part.triangles, k), ei, k, "mass", tg);
      area = tg.area;
    }
    const double t = state.thickness[e];
    mass[e] = material_of(part, ei).density * t * area;
    inertia_factor[e] = rotational_inertia_factor(area, t);
  }
}

}  // namespace sf
