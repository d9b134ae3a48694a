#include "solver/nodal_reactions.hpp"

namespace sf {

unsigned explicit_held_components(const Model& model, const SolutionState& s, int node) {
  const auto i = static_cast<std::size_t>(node);
  const unsigned prescribed = s.prescribed_mask.empty() ? 0u : s.prescribed_mask[i];
  return model.constraints.mask[i] | prescribed;
}

void compute_nodal_reactions(const Model& model, const SolutionState& s,
                             const std::vector<unsigned char>* held, Matrix3X& force,
                             Matrix3X& moment) {
  const Eigen::Index n = s.x.cols();
  force.setZero(3, n);
  moment.setZero(3, n);
  const double c = model.loads.damping;
  for (Eigen::Index i = 0; i < n; ++i) {
    const int node = static_cast<int>(i);
    const unsigned mask =
        held ? (*held)[static_cast<std::size_t>(i)] : explicit_held_components(model, s, node);
    if (mask == 0) {
      continue;
    }
    const double m = model.blank.mass[i];
    const double j = model.blank.rotational_inertia[i];
    for (int k = 0; k < 3; ++k) {
      if (mask & (1u << k)) {
        force(k, i) = s.f_int(k, i) - s.f_ext(k, i) - s.f_contact(k, i) + c * m * s.v(k, i);
      }
      if (mask & (1u << (3 + k))) {
        moment(k, i) = s.m_int(k, i) - s.m_ext(k, i) + c * j * s.omega(k, i);
      }
    }
  }
  if (held || !(s.dt > 0.0)) {
    return;
  }
  // The inertia the prescribed velocities need: m a, a from the target over the last step.
  for (const PrescribedVelocity& p : model.loads.prescribed_velocities) {
    const double rate =
        (p.scale.value(s.time + 0.5 * s.dt) - p.scale.value(s.time - 0.5 * s.dt)) / s.dt;
    for (int node : p.nodes) {
      for (int k = 0; k < 3; ++k) {
        if (p.components[static_cast<std::size_t>(k)]) {
          force(k, node) += model.blank.mass[node] * rate * p.velocity[k];
        }
      }
    }
  }
}

}  // namespace sf
