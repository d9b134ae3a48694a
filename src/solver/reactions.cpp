#include "solver/reactions.hpp"

#include <algorithm>

namespace sf {

unsigned explicit_held_components(const Model& model, const SolutionState& s, int node) {
  const auto i = static_cast<std::size_t>(node);
  const unsigned prescribed = s.prescribed_mask.empty() ? 0u : s.prescribed_mask[i];
  return model.constraints.mask[i] | prescribed;
}

namespace {

// m a summed over the prescribed velocity components of `nodes`: the inertia force the
// prescribed motion needs, a from its target over the last step, centred on the state's time.
Vec3 prescribed_inertia(const Model& model, const SolutionState& s, std::span<const int> nodes) {
  Vec3 force = Vec3::Zero();
  if (!(s.dt > 0.0)) {
    return force;
  }
  for (const PrescribedVelocity& p : model.loads.prescribed_velocities) {
    const double rate =
        (p.scale.value(s.time + 0.5 * s.dt) - p.scale.value(s.time - 0.5 * s.dt)) / s.dt;
    for (int node : p.nodes) {
      if (!std::binary_search(nodes.begin(), nodes.end(), node)) {
        continue;
      }
      for (int c = 0; c < 3; ++c) {
        if (p.components[static_cast<std::size_t>(c)]) {
          force[c] += model.blank.mass[node] * rate * p.velocity[c];
        }
      }
    }
  }
  return force;
}

}  // namespace

Reaction sum_reactions(const Model& model, const SolutionState& s, std::span<const int> nodes,
                       const std::vector<unsigned char>* held) {
  Reaction r;
  const double c = model.loads.damping;
  for (int node : nodes) {
    const unsigned mask =
        held ? (*held)[static_cast<std::size_t>(node)] : explicit_held_components(model, s, node);
    if (mask == 0) {
      continue;
    }
    const double m = model.blank.mass[node];
    const double j = model.blank.rotational_inertia[node];
    for (int k = 0; k < 3; ++k) {
      if (mask & (1u << k)) {
        r.force[k] +=
            s.f_int(k, node) - s.f_ext(k, node) - s.f_contact(k, node) + c * m * s.v(k, node);
      }
      if (mask & (1u << (3 + k))) {
        r.moment[k] += s.m_int(k, node) - s.m_ext(k, node) + c * j * s.omega(k, node);
      }
    }
  }
  if (!held) {
    r.force += prescribed_inertia(model, s, nodes);
  }
  return r;
}

}  // namespace sf
