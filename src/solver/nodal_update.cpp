#include "solver/nodal_update.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <climits>
#include <cmath>

#include "core/errors.hpp"
#include "core/exact_sums.hpp"  // kMinParallelIndices
#include "solver/operation_sequence.hpp"

namespace sf {
namespace {

// Accelerations from the nodal force balance, straight into the half-step velocity update.
// Returns false if any value is not finite (the caller then finds and names the node).
// Mass-proportional damping acts on the old half-step velocity (force -c m v), which keeps the
// update explicit; it is stable for c dt < 2.
bool add_force_kicks(const Model& model, SolutionState& s, double weight) {
  // The nodes this process keeps (all of them in a serial run).
  const std::span<const int> held = s.domain->held_nodes();
  const Eigen::Index n = held.empty() ? s.v.cols() : static_cast<Eigen::Index>(held.size());
  const double c = damping_in_effect(model, s);
  bool finite = true;
#pragma omp parallel for schedule(static) reduction(&& : finite) if (n >= kMinParallelIndices)
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index i = held.empty() ? k : held[static_cast<std::size_t>(k)];
    const double inv_m = s.inverse_mass[i];
    const double inv_i = s.inverse_inertia[i];
    s.v.col(i) += (weight * inv_m) * (s.f_ext.col(i) + s.f_contact.col(i) - s.f_int.col(i)) -
                  (weight * c) * s.v.col(i);
    s.omega.col(i) +=
        (weight * inv_i) * (s.m_ext.col(i) - s.m_int.col(i)) - (weight * c) * s.omega.col(i);
    finite = finite && std::isfinite(s.v.col(i).sum() + s.omega.col(i).sum());
  }
  model.constraints.apply(s.v, s.omega);
  return finite;
}

// The lowest node this process keeps (owned or ghost: every holder of a node has its bits) whose
// velocity is not finite, and its message; none if all are finite.
PhaseError find_non_finite(const Model& model, const SolutionState& s) {
  PhaseError found;
  auto check = [&](Eigen::Index i) {
    if (i < found.key && (!s.v.col(i).allFinite() || !s.omega.col(i).allFinite())) {
      found = {
          PhaseError::Kind::instability, static_cast<long>(i),
          fmt::format("non-finite velocity at blank node {} (gmsh node {}) at t = {:.6e} s, "
                      "cycle {}; forces there: internal ({}, {}, {}) N, contact ({}, {}, {}) N",
                      i, model.blank.mesh.gmsh_node_tags[static_cast<std::size_t>(i)], s.time,
                      s.cycle, s.f_int(0, i), s.f_int(1, i), s.f_int(2, i), s.f_contact(0, i),
                      s.f_contact(1, i), s.f_contact(2, i))};
    }
  };
  const std::span<const int> owned = s.domain->owned_nodes();
  if (owned.empty()) {
    for (Eigen::Index i = 0; i < s.v.cols() && !found.failed(); ++i) {
      check(i);
    }
    if (!found.failed()) {  // every component finite, their sum not: overflow
      found = {PhaseError::Kind::instability, LONG_MAX - 1,
               fmt::format("non-finite state at t = {:.6e} s, cycle {}", s.time, s.cycle)};
    }
    return found;
  }
  for (const std::span<const int> nodes : {owned, s.domain->ghost_nodes()}) {
    for (const int i : nodes) {
      check(i);
    }
  }
  return found;
}

}  // namespace

void update_velocities(const Model& model, SolutionState& s, double weight) {
  // Collective in a distributed run: every process learns whether one of them met a non-finite
  // velocity (at a node another process does not keep, it would not see it).
  PhaseError failure;
  if (!add_force_kicks(model, s, weight)) {
    failure = find_non_finite(model, s);
  }
  failure = s.domain->agree(std::move(failure));
  if (failure.failed()) {
    throw InstabilityError(failure.message);
  }
}

// Holds the prescribed components (in each node's axes) at their velocities over the step [t, t +
// dt]: a prescribed velocity at its value at mid-step, a prescribed displacement (or rotation) at
// the velocity that reaches its value at the step end, (d(t + dt) - d(t)) / dt (central
// difference). Returns the work (N mm) of the reactions that do so over the step: reaction = m
// (v_prescribed - v_free) / weight (the rotational inertia for a rotation), times v_prescribed dt.
double apply_velocity_conditions(const Model& model, SolutionState& s, double weight, double dt) {
  if (model.prescribed_motions.empty()) {
    return 0.0;  // the same on every process: no reduction needed
  }
  // Summed exactly over the nodes this process counts, then over the processes.
  const std::span<const int> owned = s.domain->owned_nodes();
  ExactSum work;
  const double t0 = s.time;
  const NodeFrames& frames = model.constraints.frames;
  for (const PrescribedMotion& p : model.prescribed_motions) {
    const double target = p.kind == PrescribedMotion::Kind::velocity
                              ? p.target(t0 + 0.5 * dt)
                              : (p.target(t0 + dt) - p.target(t0)) / dt;
    const VectorX& mass = p.rotation ? s.rotational_inertia : s.mass;
    Matrix3X& field = p.rotation ? s.omega : s.v;
    for (std::size_t k = 0; k < p.nodes.size(); ++k) {
      const int node = p.nodes[k];
      const int component = p.component[k];
      const double value = p.sign[k] * target;
      double free = 0.0;
      if (!frames.has(node)) {
        double& held = field(component % 3, node);
        free = held;
        held = value;
      } else {
        const Vec3 axis = frames.axis(node, component);
        free = axis.dot(field.col(node));
        field.col(node) += (value - free) * axis;
      }
      if (owned.empty() || std::binary_search(owned.begin(), owned.end(), node)) {
        const double reaction = mass[node] * (value - free) / weight;
        work.add(reaction * value * dt);
      }
    }
  }
  s.domain->reduce(std::span<ExactSum>(&work, 1));
  return work.round();
}

void update_positions(SolutionState& s, double dt) {
  const std::span<const int> held = s.domain->held_nodes();
  const Eigen::Index n = held.empty() ? s.x.cols() : static_cast<Eigen::Index>(held.size());
#pragma omp parallel for schedule(static) if (n >= kMinParallelIndices)
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index i = held.empty() ? k : held[static_cast<std::size_t>(k)];
    s.x.col(i) += dt * s.v.col(i);
    s.rotation.col(i) += dt * s.omega.col(i);
  }
  s.time += dt;
  s.cycle += 1;
  s.dt = dt;
}

}  // namespace sf
