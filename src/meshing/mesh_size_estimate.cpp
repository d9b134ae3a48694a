#include "meshing/mesh_size_estimate.hpp"

#include <gmsh.h>
#include <algorithm>

namespace sf {

double estimated_surface_area() {
  double area = 0.0;
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  for (const auto& [dim, tag] : surfaces) {
    double lo[3], hi[3];
    gmsh::model::getBoundingBox(dim, tag, lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    double sides[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
    std::sort(sides, sides + 3);
    area += sides[1] * sides[2];
  }
  return area;
}

double estimate_element_count(double element_size, bool recombine) {
  return estimated_surface_area() / (element_size * element_size) * (recombine ? 1.0 : 2.3);
}

}  // namespace sf
