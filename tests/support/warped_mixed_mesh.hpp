#pragma once
// A warped, distorted mixed mesh and a yielding shell part on it, shared by the parallel tests
// (threads and ranks must give a serial pass's bits on the geometry users have).
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "element/element_block.hpp"
#include "element/shell_part.hpp"

namespace sf::test {

// An nx x ny grid of 1 mm cells on a cylinder of radius 20 mm (warped), nodes jittered by up to
// 0.2 mm (distorted); the last `tri_rows` rows of cells split into two triangles each.
struct Mesh {
  Matrix3X x;
  QuadConn quads;
  TriConn triangles;
};

inline Mesh make_mesh(int nx, int ny, int tri_rows) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  Mesh m;
  m.x.resize(3, (nx + 1) * (ny + 1));
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      const double s = i + jitter(random);
      const double y = j + jitter(random);
      m.x.col(j * (nx + 1) + i) = Vec3(20.0 * std::sin(s / 20.0), y, 20.0 * std::cos(s / 20.0));
    }
  }
  const int quad_rows = ny - tri_rows;
  m.quads.resize(4, nx * quad_rows);
  m.triangles.resize(3, 2 * nx * tri_rows);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i;
      const int b = a + 1;
      const int c = b + nx + 1;
      const int d = a + nx + 1;
      if (j < quad_rows) {
        m.quads.col(j * nx + i) << a, b, c, d;
      } else {
        const int t = 2 * ((j - quad_rows) * nx + i);
        m.triangles.col(t) << a, b, c;
        m.triangles.col(t + 1) << a, c, d;
      }
    }
  }
  return m;
}

inline ShellPart make_part(const Mesh& mesh, ShellFormulation formulation) {
  ShellPart p;
  p.formulation = formulation;
  p.quads = mesh.quads;
  p.triangles = mesh.triangles;
  p.section = make_gauss_section(5);
  p.materials[0].law = J2PlaneStress{210000.0, 0.3, LinearHardening{200.0, 1000.0}};
  p.materials[0].density = 7.85e-9;
  p.hourglass_coefficient = 0.1;
  return p;
}

/// The second material of two_material_part: an aluminium that yields earlier.
inline ShellMaterial second_material() {
  return {J2PlaneStress{70000.0, 0.33, LinearHardening{120.0, 500.0}}, 2.7e-9};
}

/// The part of make_part with a second material (a tailor-welded blank's) in runs of 37 quads and
/// 13 triangles alternating with the first: cut at places that are not the SIMD blocks' edges.
/// `which` receives each element's material index.
inline ShellPart two_material_part(const Mesh& mesh, ShellFormulation formulation,
                                   std::vector<int>* which = nullptr) {
  ShellPart p = make_part(mesh, formulation);
  std::vector<int> m(static_cast<std::size_t>(element_count(p)));
  for (const ElementBlock& block : element_blocks(p)) {
    const int run = block.shape == ElementShape::quad ? 37 : 13;
    for (int e = block.first; e < block.end(); ++e) {
      m[static_cast<std::size_t>(e)] = (block.local(e) / run) % 2;
    }
  }
  if (which) {
    *which = m;
  }
  set_element_materials(p, {p.materials[0], second_material()}, std::move(m));
  return p;
}

/// A stretching, bending and twisting motion of the mesh at x0, large enough to yield the steel of
/// make_part within a few 1e-6 s steps: velocities v (mm/s) and angular velocities w (rad/s).
inline void yielding_motion(const Matrix3X& x0, Matrix3X& v, Matrix3X& w) {
  v.resize(3, x0.cols());
  w.resize(3, x0.cols());
  for (Eigen::Index i = 0; i < x0.cols(); ++i) {
    const Vec3 p = x0.col(i);
    v.col(i) = Vec3(2e3 * p.y() * 0.05, 1e3 * std::sin(p.x()), 5e2 * p.x() * p.y() * 0.01);
    w.col(i) = Vec3(10.0 * p.y(), -20.0 * p.x(), 5.0);
  }
}

}  // namespace sf::test
