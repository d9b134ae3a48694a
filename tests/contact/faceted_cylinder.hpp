#pragma once
// A faceted circular cylinder for the contact tests: axis along y through (0, 0, z_axis), radius R,
// N facets around, `rows` rows of cells along y over [y0, y1], outward normals.
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/types.hpp"
#include "mesh/triangle_surface.hpp"

namespace sf::test {

/// Node (k, j) at angle theta_k = phase + 2 pi k / N in the xz plane: (R cos theta_k, y_j,
/// z_axis + R sin theta_k). Every cell (k, j) -> (k+1, j+1) is split along the same diagonal, so
/// each node away from the two end rows has three triangles on each of its two facets: its
/// averaged normal is then exactly radial (the bisector of two facet normals with equal weights).
inline TriangleSurface make_faceted_cylinder(double radius, int facets, double phase, double y0,
                                             double y1, int rows, double z_axis = 0.0) {
  const int ring = facets;
  Matrix3X nodes(3, ring * (rows + 1));
  for (int j = 0; j <= rows; ++j) {
    const double y = y0 + (y1 - y0) * j / rows;
    for (int k = 0; k < ring; ++k) {
      const double theta = phase + 2.0 * std::numbers::pi * k / facets;
      nodes.col(j * ring + k) =
          Vec3(radius * std::cos(theta), y, z_axis + radius * std::sin(theta));
    }
  }
  TriConn tri(3, 2 * ring * rows);
  int t = 0;
  for (int j = 0; j < rows; ++j) {
    for (int k = 0; k < ring; ++k) {
      const int a = j * ring + k, b = j * ring + (k + 1) % ring;
      const int c = b + ring, d = a + ring;
      // (a, c, b) and (a, d, c): outward normals (a -> b runs with increasing angle).
      tri.col(t++) << a, c, b;
      tri.col(t++) << a, d, c;
    }
  }
  TriangleSurface s("cylinder", nodes, tri);
  // Guard: the normals face away from the axis.
  const Vec3 centroid = (nodes.col(tri(0, 0)) + nodes.col(tri(1, 0)) + nodes.col(tri(2, 0))) / 3;
  const Vec3 outward(centroid.x(), 0, centroid.z() - z_axis);
  if (!(s.triangle_normals().col(0).dot(outward) > 0)) {
    throw std::logic_error("make_faceted_cylinder: inward normals");
  }
  return s;
}

}  // namespace sf::test
