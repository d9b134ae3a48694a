#include "meshing/chord_error_size.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace sf {

double chord_error_size(double curvature, double chord_error) {
  constexpr double kUnlimited = std::numeric_limits<double>::infinity();
  if (!(curvature > 0.0) || !std::isfinite(curvature)) {
    return kUnlimited;
  }
  const double radius = 1.0 / curvature;
  if (chord_error >= radius) {
    return kUnlimited;
  }
  return 2.0 * std::sqrt(chord_error * (2.0 * radius - chord_error));
}

namespace {

/// gmsh's (largest) curvature of entity (dim, tag) at the point x, 1/mm; 0 where gmsh has none.
double curvature_at(int dim, int tag, const std::vector<double>& x) {
  std::vector<double> parameters, curvatures;
  gmsh::model::getParametrization(dim, tag, x, parameters);
  gmsh::model::getCurvature(dim, tag, parameters, curvatures);
  return curvatures.empty() ? 0.0 : std::abs(curvatures[0]);
}

/// The curvature that sets the size at x on entity (dim, tag): a surface's own; on a curve the
/// largest of its own and its surfaces' (a straight seam or edge of a cylinder is meshed first, and
/// the triangles of the curved face beside it take its lengths).
double governing_curvature(int dim, int tag, const std::vector<double>& x) {
  double curvature = curvature_at(dim, tag, x);
  if (dim == 1) {
    std::vector<int> surfaces, points;
    gmsh::model::getAdjacencies(1, tag, surfaces, points);
    for (const int surface : surfaces) {
      curvature = std::max(curvature, curvature_at(2, surface, x));
    }
  }
  return curvature;
}

}  // namespace

void set_chord_error_size(double chord_error) {
  // gmsh asks for the size at points of curves (dim 1) while meshing them and of surfaces (dim 2)
  // while meshing those. A size of 1e22 is gmsh's own "no limit" (Mesh.MeshSizeMax's default).
  gmsh::model::mesh::setSizeCallback([chord_error](int dim, int tag, double x, double y, double z) {
    if (dim != 1 && dim != 2) {
      return 1e22;
    }
    const double size = chord_error_size(governing_curvature(dim, tag, {x, y, z}), chord_error);
    return std::isfinite(size) ? size : 1e22;
  });
}

}  // namespace sf
