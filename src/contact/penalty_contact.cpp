#include "contact/penalty_contact.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <string_view>

#include "core/errors.hpp"

namespace sf {

ContactResult compute_penalty_contact(ContactPair& pair, const ContactKinematics& kinematics,
                                      Matrix3X& f_contact) {
  ContactResult result;
  const Matrix3X& x = kinematics.x;
  const int n = static_cast<int>(x.cols());
  const std::string_view tool_name = pair.surface ? std::string_view(pair.surface->name()) : "?";
  const bool interpolated = pair.projection == ContactProjection::interpolated;
  const bool friction = pair.friction.active();
  if (friction) {
    pair.friction.validate(tool_name);
    if (pair.stick_force.cols() != n) {
      pair.stick_force.setZero(3, n);
    }
  }
  if (interpolated && !pair.projector) {
    pair.projector = std::make_unique<InterpolatedProjector>(*pair.surface);
  }
  ClosestPoint cp;
  InterpolatedProjection ip;
  for (int i = 0; i < n; ++i) {
    const double h = kinematics.half_thickness[i];
    if (!(pair.cutoff > h)) {
      throw InputError(fmt::format(
          "contact with tool '{}': search radius {} mm does not exceed the half thickness {} mm "
          "of blank node {}",
          tool_name, pair.cutoff, h, i));
    }
    const Vec3 p = x.col(i) - kinematics.tool_displacement;
    pair.search->find_closest_for_node(i, p, pair.cutoff, cp);
    bool in_contact = false;
    if (cp.triangle >= 0) {
      double distance = cp.signed_distance;
      Vec3 normal = cp.normal;
      if (interpolated) {
        pair.projector->project(p, cp, ip);
        result.projection_fallbacks += ip.fallback ? 1 : 0;
        distance = ip.distance;
        normal = ip.normal;
      }
      const double g = distance - h;
      in_contact = g < 0 && distance > -h - pair.cutoff;
      if (in_contact) {
        const double k = pair.stiffness[i];
        const double normal_force = k * (-g);
        Vec3 f = normal_force * normal;
        result.energy += 0.5 * k * g * g;
        ++result.nodes_in_contact;
        if (friction) {
          const Vec3 increment =
              kinematics.dt * kinematics.v.col(i) - kinematics.tool_displacement_increment;
          Vec3 stored = pair.stick_force.col(i);
          const FrictionStep step =
              coulomb_friction_update(pair.friction, stored, normal, increment, kinematics.dt,
                                      normal_force, pair.friction.tangential_stiffness_ratio * k);
          pair.stick_force.col(i) = stored;
          f += step.force;
          result.friction_work += step.work;
          ++(step.sliding ? result.sliding_nodes : result.sticking_nodes);
        }
        f_contact.col(i) += f;
        result.force_on_tool -= f;
      }
    }
    if (friction && !in_contact) {
      pair.stick_force.col(i).setZero();
    }
  }
  return result;
}

VectorX compute_penalty_stiffness(const Matrix3X& nodes, const QuadConn& quads,
                                  const TriConn& triangles, const VectorX& nodal_mass,
                                  double youngs_modulus, double poisson_ratio, double scale,
                                  double dt_target, double dt_safety) {
  if (!(youngs_modulus > 0) || !(poisson_ratio > -1 && poisson_ratio < 0.5)) {
    throw InputError(
        fmt::format("contact penalty: need E > 0 and -1 < nu < 0.5 (got E = {} MPa, nu = {})",
                    youngs_modulus, poisson_ratio));
  }
  if (!(scale > 0)) {
    throw InputError(fmt::format("contact penalty: scale must be > 0 (got {})", scale));
  }
  const int n = static_cast<int>(nodes.cols());
  const double bulk = youngs_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio));
  VectorX area = VectorX::Zero(n);
  VectorX diagonal = VectorX::Zero(n);
  for (int e = 0; e < quads.cols(); ++e) {
    const Vec3 d1 = nodes.col(quads(2, e)) - nodes.col(quads(0, e));
    const Vec3 d2 = nodes.col(quads(3, e)) - nodes.col(quads(1, e));
    const double a = 0.5 * d1.cross(d2).norm();  // exact for a flat quad
    const double d = std::max(d1.norm(), d2.norm());
    for (int k = 0; k < 4; ++k) {
      area[quads(k, e)] += 0.25 * a;
      diagonal[quads(k, e)] = std::max(diagonal[quads(k, e)], d);
    }
  }
  for (int e = 0; e < triangles.cols(); ++e) {
    const Vec3 x1 = nodes.col(triangles(0, e));
    const Vec3 e1 = nodes.col(triangles(1, e)) - x1;
    const Vec3 e2 = nodes.col(triangles(2, e)) - x1;
    const double a = 0.5 * e1.cross(e2).norm();
    const double d =
        std::sqrt(std::max({e1.squaredNorm(), e2.squaredNorm(), (e2 - e1).squaredNorm()}));
    for (int k = 0; k < 3; ++k) {
      area[triangles(k, e)] += a / 3.0;
      diagonal[triangles(k, e)] = std::max(diagonal[triangles(k, e)], d);
    }
  }
  VectorX k = VectorX::Zero(n);
  for (int i = 0; i < n; ++i) {
    if (diagonal[i] > 0) {
      k[i] = scale * bulk * area[i] / diagonal[i];
    }
  }
  cap_penalty_stiffness(k, nodal_mass, dt_target, dt_safety);
  return k;
}

int cap_penalty_stiffness(VectorX& stiffness, const VectorX& nodal_mass, double dt_target,
                          double dt_safety) {
  if (!(dt_target > 0)) {
    return 0;
  }
  const double omega_max = 2.0 * dt_safety / dt_target;
  int capped = 0;
  for (Eigen::Index i = 0; i < stiffness.size(); ++i) {
    const double limit = nodal_mass[i] * omega_max * omega_max;
    if (stiffness[i] > limit) {
      stiffness[i] = limit;
      ++capped;
    }
  }
  return capped;
}

}  // namespace sf
