#include "solver/start_gaps.hpp"

#include <limits>

#include "model/blank_parts.hpp"

namespace sf {

VectorX start_gaps(const Model& model, const ContactInterface& contact) {
  const Tool& tool = model.tools[static_cast<std::size_t>(contact.tool)];
  const ToolPlacement at_start = tool.motion.placement(0.0);
  const VectorX half = initial_half_thickness(model.blank, model.initial);  // mm per node
  const Matrix3X& x = model.blank.mesh.nodes;
  VectorX gaps(x.cols());
  ClosestPoint cp;
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    // The search works in the tool's frame: the node taken back through the tool's placement.
    contact.pair.search->find_closest(
        at_start.rotation.transpose() * (x.col(i) - at_start.translation), contact.pair.cutoff, cp);
    gaps[i] =
        cp.triangle >= 0 ? cp.signed_distance - half[i] : std::numeric_limits<double>::quiet_NaN();
  }
  return gaps;
}

}  // namespace sf
