#include "solver/reactions.hpp"

#include <fmt/core.h>

#include "core/dof_names.hpp"
#include "model/constraint_assembly.hpp"
#include "solver/operation_sequence.hpp"

namespace sf {

namespace {

/// The acceleration (mm/s^2, rad/s^2) of a prescribed motion at time t, by central differences
/// over the step h (s): of the velocity (t -/+ h/2) or of the displacement (t - h, t, t + h).
double prescribed_acceleration(const PrescribedMotion& p, double t, double h) {
  if (p.kind == PrescribedMotion::Kind::velocity) {
    return (p.target(t + 0.5 * h) - p.target(t - 0.5 * h)) / h;
  }
  return (p.target(t + h) - 2.0 * p.target(t) + p.target(std::max(0.0, t - h))) / (h * h);
}

Vec3 sum_over(const std::vector<int>& nodes, const Matrix3X& field) {
  Vec3 sum = Vec3::Zero();
  for (const int node : nodes) {
    sum += field.col(node);
  }
  return sum;
}

}  // namespace

void compute_reactions(const Model& model, const SolutionState& s, Matrix3X& force,
                       Matrix3X& moment) {
  const Eigen::Index n = s.x.cols();
  force.setZero(3, n);
  moment.setZero(3, n);
  const NodalConstraints& c = model.constraints;
  const double damping = s.dt > 0.0 ? damping_in_effect(model, s) : 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const unsigned bits = c.constrained_bits(static_cast<std::size_t>(i));
    if (bits == 0) {
      continue;
    }
    // What the support adds so that the node's acceleration is zero (held) in its components.
    Vec3 f =
        s.f_int.col(i) - s.f_ext.col(i) - s.f_contact.col(i) + damping * s.mass[i] * s.v.col(i);
    Vec3 m = s.m_int.col(i) - s.m_ext.col(i) + damping * s.rotational_inertia[i] * s.omega.col(i);
    c.zero_components(static_cast<int>(i), ~bits & 0x3fu, f, m);
    force.col(i) = f;
    moment.col(i) = m;
  }
  if (!(s.dt > 0.0)) {
    return;  // a static state: no inertia
  }
  for (const PrescribedMotion& p : model.prescribed_motions) {
    const double a = prescribed_acceleration(p, s.time, s.dt);
    const VectorX& mass = p.rotation ? s.rotational_inertia : s.mass;
    Matrix3X& field = p.rotation ? moment : force;
    for (std::size_t k = 0; k < p.nodes.size(); ++k) {
      const int node = p.nodes[k];
      field.col(node) += (mass[node] * p.sign[k] * a) * c.frames.axis(node, p.component[k]);
    }
  }
}

std::vector<ConstraintReaction> sum_reactions_by_entry(const Model& model, const Matrix3X& force,
                                                       const Matrix3X& moment) {
  std::vector<ConstraintReaction> out;
  for (const ReactionEntry& e : model.output.reactions) {
    const std::vector<int>& nodes = model.blank.group(e.group).nodes;
    ConstraintReaction r;
    r.entry = e.entry;
    r.group = e.group;
    r.force = sum_over(nodes, force);
    r.moment = sum_over(nodes, moment);
    r.axes = e.axes;
    if (e.dof >= 0) {
      const Mat3 frame = e.axes ? *e.axes : Mat3::Identity();
      r.along = frame.col(e.dof % 3).dot(e.dof < 3 ? r.force : r.moment);
      r.dof = kDofNames[static_cast<std::size_t>(e.dof)];
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace sf
