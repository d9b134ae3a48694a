#pragma once
// Surfaces for the contact tests.
#include <cmath>
#include <functional>
#include <random>

#include "core/types.hpp"
#include "mesh/triangle_surface.hpp"

namespace sf::test {

/// Height field z = f(x, y) over [x0, x1] x [y0, y1], nx x ny cells, two triangles per cell
/// (diagonal alternating), normals toward +z.
inline TriangleSurface make_height_field(const std::string& name, int nx, int ny, double x0,
                                         double x1, double y0, double y1,
                                         const std::function<double(double, double)>& f) {
  Matrix3X nodes(3, (nx + 1) * (ny + 1));
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      const double x = x0 + (x1 - x0) * i / nx, y = y0 + (y1 - y0) * j / ny;
      nodes.col(j * (nx + 1) + i) = Vec3(x, y, f(x, y));
    }
  }
  TriConn tri(3, 2 * nx * ny);
  int t = 0;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 2, d = a + nx + 1;
      if ((i + j) % 2 == 0) {
        tri.col(t++) << a, b, c;
        tri.col(t++) << a, c, d;
      } else {
        tri.col(t++) << a, b, d;
        tri.col(t++) << b, c, d;
      }
    }
  }
  return TriangleSurface(name, nodes, tri);
}

/// n random triangles with vertices in [0, 1]^3 (a soup: no shared nodes), none too thin.
inline TriangleSurface make_random_soup(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Matrix3X nodes(3, 3 * n);
  TriConn tri(3, n);
  for (int t = 0; t < n; ++t) {
    for (;;) {
      const Vec3 a(u(rng), u(rng), u(rng));
      const Vec3 b = a + 0.3 * Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
      const Vec3 c = a + 0.3 * Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
      if ((b - a).cross(c - a).norm() > 1e-3) {
        nodes.col(3 * t) = a;
        nodes.col(3 * t + 1) = b;
        nodes.col(3 * t + 2) = c;
        tri.col(t) << 3 * t, 3 * t + 1, 3 * t + 2;
        break;
      }
    }
  }
  return TriangleSurface("soup", nodes, tri);
}

}  // namespace sf::test
