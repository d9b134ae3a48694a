#include "contact/penalty_contact.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace sf {

ContactResult compute_penalty_contact(ContactPair& pair, const Matrix3X& x,
                                      const VectorX& half_thickness, const Vec3& tool_displacement,
                                      Matrix3X& f_contact) {
  ContactResult result;
  const int n = static_cast<int>(x.cols());
  ClosestPoint cp;
  for (int i = 0; i < n; ++i) {
    const double h = half_thickness[i];
    if (!(pair.cutoff > h)) {
      throw InputError(fmt::format(
          "contact with tool '{}': search radius {} mm does not exceed the half thickness {} mm "
          "of blank node {}",
          pair.surface ? pair.surface->name() : std::string("?"), pair.cutoff, h, i));
    }
    const Vec3 p = x.col(i) - tool_displacement;
    pair.search->find_closest_for_node(i, p, pair.cutoff, cp);
    if (cp.triangle < 0) {
      continue;
    }
    const double g = cp.signed_distance - h;
    if (g < 0 && cp.signed_distance > -h - pair.cutoff) {
      const double k = pair.stiffness[i];
      const Vec3 f = (k * (-g)) * cp.normal;
      f_contact.col(i) += f;
      result.force_on_tool -= f;
      result.energy += 0.5 * k * g * g;
      ++result.nodes_in_contact;
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
    if (dt_target > 0) {
      const double omega_max = 2.0 * dt_safety / dt_target;
      k[i] = std::min(k[i], nodal_mass[i] * omega_max * omega_max);
    }
  }
  return k;
}

}  // namespace sf
