#pragma once
// Triangle surfaces of known geometry for the tool-diagnosis and clearance tests: structured
// patches of a parametric map (planes, annuli, die profiles, height fields), latitude-longitude
// spheres with their poles, each piece with its own nodes unless it is built in one call.
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "mesh/triangle_surface.hpp"

namespace sf::test {

class SurfaceBuilder {
 public:
  int add_node(const Vec3& x) {
    nodes_.push_back(x);
    return static_cast<int>(nodes_.size()) - 1;
  }
  void add_triangle(int a, int b, int c) { triangles_.push_back({a, b, c}); }

  /// A structured patch of nodes f(u, v), u = i / nu, v = j / nv, two triangles per cell split
  /// along the (i, j)-(i+1, j+1) diagonal, normals along df/du x df/dv (reversed when `flip`).
  /// `wrap_u`: the nodes of u = 1 are those of u = 0 (a closed band).
  template <class F>
  void add_patch(int nu, int nv, F&& f, bool flip = false, bool wrap_u = false) {
    const int columns = wrap_u ? nu : nu + 1;
    const int first = static_cast<int>(nodes_.size());
    for (int j = 0; j <= nv; ++j) {
      for (int i = 0; i < columns; ++i) {
        add_node(f(static_cast<double>(i) / nu, static_cast<double>(j) / nv));
      }
    }
    const auto node = [&](int i, int j) { return first + j * columns + i % columns; };
    for (int j = 0; j < nv; ++j) {
      for (int i = 0; i < nu; ++i) {
        const int a = node(i, j), b = node(i + 1, j), c = node(i + 1, j + 1), d = node(i, j + 1);
        add_oriented(a, b, c, flip);
        add_oriented(a, c, d, flip);
      }
    }
  }

  /// Sphere (or its lower part down from the south pole to polar angle `theta_max`) of radius r
  /// about `centre`, poles on the z axis, `rings` rings and `segments` segments, outward normals
  /// (inward when `flip`).
  void add_sphere(const Vec3& centre, double r, int rings, int segments, double theta_max,
                  bool flip = false) {
    const double pi = std::acos(-1.0);
    const int pole = add_node(centre - r * Vec3::UnitZ());
    const auto point = [&](int ring, int s) {  // ring 1 .. rings, polar angle from -z
      const double theta = theta_max * ring / rings, phi = 2.0 * pi * s / segments;
      return Vec3(centre + r * Vec3(std::sin(theta) * std::cos(phi),
                                    std::sin(theta) * std::sin(phi), -std::cos(theta)));
    };
    const bool closed = std::abs(theta_max - pi) < 1e-12;
    const int last_ring = closed ? rings - 1 : rings;
    const int first = static_cast<int>(nodes_.size());
    for (int ring = 1; ring <= last_ring; ++ring) {
      for (int s = 0; s < segments; ++s) {
        add_node(point(ring, s));
      }
    }
    const auto node = [&](int ring, int s) { return first + (ring - 1) * segments + s % segments; };
    for (int s = 0; s < segments; ++s) {  // outward from the south pole: counter-clockwise from -z
      add_oriented(pole, node(1, s + 1), node(1, s), flip);
    }
    for (int ring = 1; ring < last_ring; ++ring) {
      for (int s = 0; s < segments; ++s) {
        add_oriented(node(ring, s), node(ring, s + 1), node(ring + 1, s + 1), flip);
        add_oriented(node(ring, s), node(ring + 1, s + 1), node(ring + 1, s), flip);
      }
    }
    if (closed) {
      const int north = add_node(centre + r * Vec3::UnitZ());
      for (int s = 0; s < segments; ++s) {
        add_oriented(north, node(last_ring, s), node(last_ring, s + 1), flip);
      }
    }
  }

  /// The same triangles with the nodes closer than `tolerance` joined (pieces built apart made
  /// one surface; O(n^2), for small meshes).
  SurfaceBuilder joined(double tolerance) const {
    SurfaceBuilder out;
    std::vector<int> id;
    for (const Vec3& x : nodes_) {
      int found = -1;
      for (std::size_t k = 0; k < out.nodes_.size() && found < 0; ++k) {
        found = (out.nodes_[k] - x).norm() < tolerance ? static_cast<int>(k) : -1;
      }
      id.push_back(found >= 0 ? found : out.add_node(x));
    }
    for (const auto& t : triangles_) {
      out.add_triangle(id[t[0]], id[t[1]], id[t[2]]);
    }
    return out;
  }

  TriangleSurface build(const std::string& name = "tool") const {
    return TriangleSurface(name, nodes(), triangles());
  }
  Matrix3X nodes() const {
    Matrix3X x(3, static_cast<Eigen::Index>(nodes_.size()));
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      x.col(static_cast<Eigen::Index>(i)) = nodes_[i];
    }
    return x;
  }
  TriConn triangles() const {
    TriConn t(3, static_cast<Eigen::Index>(triangles_.size()));
    for (std::size_t i = 0; i < triangles_.size(); ++i) {
      t.col(static_cast<Eigen::Index>(i)) << triangles_[i][0], triangles_[i][1], triangles_[i][2];
    }
    return t;
  }

 private:
  void add_oriented(int a, int b, int c, bool flip) {
    flip ? add_triangle(a, c, b) : add_triangle(a, b, c);
  }

  std::vector<Vec3> nodes_;
  std::vector<std::array<int, 3>> triangles_;
};

/// A flat rectangle [x0, x1] x [y0, y1] at height z: a parametric map for add_patch.
inline auto rectangle(double x0, double x1, double y0, double y1, double z) {
  return [=](double u, double v) { return Vec3(x0 + u * (x1 - x0), y0 + v * (y1 - y0), z); };
}

}  // namespace sf::test
