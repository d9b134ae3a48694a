#pragma once
// Surfaces for the contact tests.
#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

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

/// n points uniformly distributed in the box [lo, hi].
inline std::vector<Vec3> random_points(int n, const Vec3& lo, const Vec3& hi, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> pts(n);
  for (Vec3& p : pts) {
    p = lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(hi - lo);
  }
  return pts;
}

/// A smooth warp of a height field, z = f(x, y) over about [-1, 1]^2.
inline double warp(double x, double y) {
  return 0.3 * std::sin(2.0 * x) * std::cos(3.0 * y) + 0.1 * x * y;
}

/// The paper's trap (its figure 1): a long thin triangle N_min holds the projection of P, while
/// the surface node K closest to P belongs only to small triangles beside it.
inline TriangleSurface make_trap() {
  Matrix3X x(3, 8);
  x.col(0) = Vec3(-10, -1, 0);  // N_min = (0, 1, 2): long and thin, far vertices
  x.col(1) = Vec3(10, -1, 0);
  x.col(2) = Vec3(0, 3, 0.2);
  x.col(3) = Vec3(0, -1.1, -0.05);  // K: small triangles below y = -1
  x.col(4) = Vec3(-0.5, -1.2, 0);
  x.col(5) = Vec3(0.5, -1.2, 0);
  x.col(6) = Vec3(-0.5, -2.0, 0);
  x.col(7) = Vec3(0.5, -2.0, 0);
  TriConn t(3, 4);
  t << 0, 3, 3, 3,  //
      1, 5, 4, 6,   //
      2, 4, 6, 7;
  t.col(3) << 3, 7, 5;
  return TriangleSurface("trap", x, t);
}

/// Adversarial: a strip of small triangles (a dense row of nodes near y = 0 with random heights)
/// and two long thin triangles spanning the whole strip, above and below it (the traps).
inline TriangleSurface make_thin_trap() {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1, 1);
  const int n = 30;
  Matrix3X x(3, 2 * n + 2);
  for (int i = 0; i <= n; ++i) {
    const double xi = -1 + 2.0 * i / n;
    x.col(i) = Vec3(xi, -0.05 + 0.02 * u(rng), 0.05 * u(rng));  // dense row near y = 0
    x.col(n + 1 + i) = Vec3(xi, 0.05, 0.05 * u(rng));
  }
  std::vector<std::array<int, 3>> tris;
  for (int i = 0; i < n; ++i) {
    tris.push_back({i, i + 1, n + 2 + i});
    tris.push_back({i, n + 2 + i, n + 1 + i});
  }
  // Two long thin triangles spanning the whole strip, above and below (the traps).
  Matrix3X y(3, x.cols() + 4);
  y << x, Vec3(-1, 0.06, 0.02), Vec3(1, 0.06, -0.02), Vec3(0, 2.0, 0.3), Vec3(0, -2.0, -0.3);
  tris.push_back({2 * n + 2, 2 * n + 3, 2 * n + 4});
  tris.push_back({0, n, 2 * n + 5});
  TriConn t(3, tris.size());
  for (std::size_t k = 0; k < tris.size(); ++k) {
    t.col(k) << tris[k][0], tris[k][1], tris[k][2];
  }
  return TriangleSurface("thin", y, t);
}

/// Two faces meeting along the x axis: (x, y, z) = (x, s, slope * |s|) for s in [-1, 1].
/// slope > 0: a valley (concave seen from +z); slope < 0: a ridge (convex seen from +z).
inline TriangleSurface make_fold(double slope) {
  Matrix3X x(3, 6);
  x.col(0) = Vec3(-1, -1, slope);
  x.col(1) = Vec3(1, -1, slope);
  x.col(2) = Vec3(-1, 0, 0);
  x.col(3) = Vec3(1, 0, 0);
  x.col(4) = Vec3(-1, 1, slope);
  x.col(5) = Vec3(1, 1, slope);
  TriConn t(3, 4);
  t.col(0) << 0, 1, 3;
  t.col(1) << 0, 3, 2;
  t.col(2) << 2, 3, 5;
  t.col(3) << 2, 5, 4;
  return TriangleSurface("fold", x, t);
}

}  // namespace sf::test
