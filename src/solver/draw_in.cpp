#include "solver/draw_in.hpp"

#include <limits>

namespace sf {

double measure_draw_in(const Model& model, const DrawInConfig& draw_in, const Matrix3X& x) {
  const NodeGroup& group = model.blank.group(draw_in.group);
  if (group.nodes.empty()) {
    return std::numeric_limits<double>::quiet_NaN();  // a trim took its nodes away
  }
  const Vec3 direction(draw_in.direction[0], draw_in.direction[1], draw_in.direction[2]);
  double sum = 0.0;
  for (int node : group.nodes) {
    sum += (x.col(node) - model.blank.mesh.nodes.col(node)).dot(direction);
  }
  return sum / static_cast<double>(group.nodes.size());
}

}  // namespace sf
