#include "model/force_controlled_tool.hpp"

#include <stdexcept>
#include <utility>

namespace sf {

ForceControlledTool::ForceControlledTool(const Vec3& direction, LoadCurve force, double mass,
                                         double damping)
    : direction_(direction.normalized()), force_(std::move(force)), mass_(mass), damping_(damping) {
  if (!(mass > 0.0) || !(damping >= 0.0) || force_.empty()) {
    throw std::invalid_argument(
        "ForceControlledTool: needs a mass > 0, a damping >= 0 and a force curve");
  }
}

void ForceControlledTool::step(double t, const Vec3& reaction, double weight, double dt,
                               double& velocity, double& travel) const {
  velocity += weight * rate(t, reaction, velocity);
  travel += dt * velocity;
}

}  // namespace sf
