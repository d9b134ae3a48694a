#include "model/force_controlled_tool.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace sf {

ForceControlledTool::ForceControlledTool(const Vec3& direction, LoadCurve force, double mass,
                                         double damping, bool of_travel)
    : direction_(direction.normalized()),
      force_(std::move(force)),
      mass_(mass),
      damping_(damping),
      of_travel_(of_travel) {
  if (!(mass > 0.0) || !(damping >= 0.0) || force_.empty()) {
    throw std::invalid_argument(
        "ForceControlledTool: needs a mass > 0, a damping >= 0 and a force curve");
  }
}

void ForceControlledTool::step(double t, const Vec3& reaction, double weight, double dt,
                               double& velocity, double& travel) const {
  velocity += weight * rate(t, reaction, velocity, travel);
  travel += dt * velocity;
}

double ForceControlledTool::stiffness() const {
  if (!of_travel_) {
    return 0.0;
  }
  double steepest = 0.0;
  const std::vector<double>& s = force_.times();
  const std::vector<double>& f = force_.values();
  for (std::size_t i = 1; i < s.size(); ++i) {
    steepest = std::max(steepest, std::abs((f[i] - f[i - 1]) / (s[i] - s[i - 1])));
  }
  return steepest;
}

}  // namespace sf
