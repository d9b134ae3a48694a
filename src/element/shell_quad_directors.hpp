#pragma once
// Curvature and transverse shear of the assumed-strain quad as functions of its nodes' positions
// x_I and directors d_I (3-D, global components): covariant measures at the element's centre,
// dot products of natural-coordinate derivatives, hence objective for any rigid rotation,
// unchanged by a node's rotation about its own director (the drilling rotation), and total
// (their increments over a step are exact differences, so the elastic bending and shear energy is
// a function of the state). Pure inline kernels. See docs/element-and-material.md.
//
// Node I sits at (xi_I, eta_I) = (-1,-1), (1,-1), (1,1), (-1,1); h_I = xi_I eta_I.
#include <algorithm>
#include <cmath>

#include "core/types.hpp"

namespace sf {

inline constexpr double kXi[4] = {-1.0, 1.0, 1.0, -1.0};
inline constexpr double kEta[4] = {-1.0, -1.0, 1.0, 1.0};
inline constexpr double kH[4] = {1.0, -1.0, 1.0, -1.0};

/// The natural basis of a quad at its centre (global components): covariant g_xi = dx/dxi,
/// g_eta (mm; tangent to the element, also when it is warped), the twist vector g_xieta =
/// sum h_I x_I / 4 (mm), the contravariant grad_xi, grad_eta (tangent, 1/mm) and the hourglass
/// vector gamma_I = h_I - c_xi xi_I - c_eta eta_I (Flanagan-Belytschko's, written without a
/// frame: c = the in-plane components of g_xieta on grad_xi, grad_eta).
struct QuadBasis {
  Vec3 g_xi;
  Vec3 g_eta;
  Vec3 grad_xi;
  Vec3 grad_eta;
  double gamma[4];
  double area;  ///< mm^2, 4 |g_xi x g_eta| (= |x31 x x42| / 2)
};

inline QuadBasis compute_quad_basis(const Quad3& x) {
  QuadBasis b;
  b.g_xi = 0.25 * (-x.col(0) + x.col(1) + x.col(2) - x.col(3));
  b.g_eta = 0.25 * (-x.col(0) - x.col(1) + x.col(2) + x.col(3));
  const Vec3 g_xieta = 0.25 * (x.col(0) - x.col(1) + x.col(2) - x.col(3));
  const double a11 = b.g_xi.squaredNorm();
  const double a22 = b.g_eta.squaredNorm();
  const double a12 = b.g_xi.dot(b.g_eta);
  const double det = a11 * a22 - a12 * a12;
  b.grad_xi = (a22 * b.g_xi - a12 * b.g_eta) / det;
  b.grad_eta = (a11 * b.g_eta - a12 * b.g_xi) / det;
  const double c_xi = g_xieta.dot(b.grad_xi);
  const double c_eta = g_xieta.dot(b.grad_eta);
  for (int i = 0; i < 4; ++i) {
    b.gamma[i] = kH[i] - c_xi * kXi[i] - c_eta * kEta[i];
  }
  b.area = 4.0 * std::sqrt(det);
  return b;
}

/// The difference of two unit directors d_b - d_a taken along the arc between them: the chord
/// scaled by theta / (2 sin(theta / 2)) = asin(s) / s, s = |d_b - d_a| / 2, theta the angle
/// between them. A curvature built from chords would be 2 sin(phi / 2) / L for an element bent
/// through phi and its moment EI sin(phi) / L (1.6 % low at 18 degrees per element); with arcs
/// both are exact for uniform bending, as with rotation differences.
struct ArcDifference {
  Vec3 value;  ///< (d_b - d_a) asin(s) / s
  Vec3 chord;  ///< d_b - d_a
  double g;    ///< asin(s) / s
  double h;    ///< (dg/ds) / (4 s): the scale of the chord's part of the gradient
};

inline ArcDifference make_arc_difference(const Vec3& d_a, const Vec3& d_b) {
  ArcDifference a;
  a.chord = d_b - d_a;
  const double s = std::min(0.5 * a.chord.norm(), 0.999);  // directors never opposite
  const double s2 = s * s;
  if (s < 1e-3) {
    // Series: g = 1 + s^2/6 + 3 s^4/40, dg/ds = s/3 + 3 s^3/10.
    a.g = 1.0 + s2 / 6.0 + 0.075 * s2 * s2;
    a.h = 1.0 / 12.0 + 0.075 * s2;
  } else {
    const double asin_s = std::asin(s);
    a.g = asin_s / s;
    a.h = (s / std::sqrt(1.0 - s2) - asin_s) / (4.0 * s2 * s);
  }
  a.value = a.g * a.chord;
  return a;
}

/// Adds the gradient of r . (arc difference) with respect to d_a and d_b into grad_a, grad_b.
inline void add_arc_difference_gradient(const ArcDifference& a, const Vec3& r, Vec3& grad_a,
                                        Vec3& grad_b) {
  const Vec3 g = a.g * r + (a.h * r.dot(a.chord)) * a.chord;
  grad_b += g;
  grad_a -= g;
}

/// The edges of the MITC4 transverse shear: 0 = C (nodes 0 -> 1, eta = -1), 1 = A (3 -> 2,
/// eta = +1), 2 = D (0 -> 3, xi = -1), 3 = B (1 -> 2, xi = +1).
inline constexpr int kEdgeNodes[4][2] = {{0, 1}, {3, 2}, {0, 3}, {1, 2}};

/// The natural derivatives of the director field at the centre, each the mean of the arc
/// differences along the two edges in its direction: d_xi = (arc(0 -> 1) + arc(3 -> 2)) / 4,
/// d_eta = (arc(0 -> 3) + arc(1 -> 2)) / 4 (the edges of kEdgeNodes, in that order).
struct QuadDirectorGradients {
  ArcDifference edge[4];
  Vec3 d_xi;
  Vec3 d_eta;
};

inline QuadDirectorGradients compute_director_gradients(const Quad3& d) {
  QuadDirectorGradients g;
  for (int k = 0; k < 4; ++k) {
    g.edge[k] = make_arc_difference(d.col(kEdgeNodes[k][0]), d.col(kEdgeNodes[k][1]));
  }
  g.d_xi = 0.25 * (g.edge[0].value + g.edge[1].value);
  g.d_eta = 0.25 * (g.edge[2].value + g.edge[3].value);
  return g;
}

/// The covariant measures of one configuration (mm).
struct DirectorMeasures {
  /// K = (g_xi . d_xi, g_eta . d_eta, g_xi . d_eta + g_eta . d_xi), d_xi = sum xi_I d_I / 4: the
  /// covariant components of grad beta (beta the director's tilt), minus the curvature.
  Vec3 curvature;
  /// MITC4 covariant transverse shear of each edge a -> b: (x_b - x_a) / 2 . (d_a + d_b) / 2.
  double edge[4];
  /// (Q . g_xi, Q . g_eta), Q = sum gamma_I d_I: the hourglass part of the director field.
  Vec2 hourglass;
};

/// The measures of coordinates x and directors d (unit, global components, their gradients dg =
/// compute_director_gradients(d)) with the hourglass vector gamma of `basis` (taken fixed over a
/// step).
inline DirectorMeasures compute_director_measures(const Quad3& x, const Quad3& d,
                                                  const QuadDirectorGradients& dg,
                                                  const QuadBasis& basis) {
  DirectorMeasures m;
  const Vec3 g_xi = 0.25 * (-x.col(0) + x.col(1) + x.col(2) - x.col(3));
  const Vec3 g_eta = 0.25 * (-x.col(0) - x.col(1) + x.col(2) + x.col(3));
  const Vec3& d_xi = dg.d_xi;
  const Vec3& d_eta = dg.d_eta;
  m.curvature = Vec3(g_xi.dot(d_xi), g_eta.dot(d_eta), g_xi.dot(d_eta) + g_eta.dot(d_xi));
  for (int k = 0; k < 4; ++k) {
    const int a = kEdgeNodes[k][0];
    const int b = kEdgeNodes[k][1];
    m.edge[k] = 0.25 * (x.col(b) - x.col(a)).dot(d.col(a) + d.col(b));
  }
  Vec3 q = Vec3::Zero();
  for (int i = 0; i < 4; ++i) {
    q += basis.gamma[i] * d.col(i);
  }
  m.hourglass = Vec2(q.dot(g_xi), q.dot(g_eta));
  return m;
}

/// Generalised resultants conjugate to the measures (N mm for curvature, hourglass; N for the
/// edges): the power of the element is curvature . dK/dt + edge . de/dt + hourglass . dq/dt.
struct DirectorResultants {
  Vec3 curvature = Vec3::Zero();
  double edge[4] = {0.0, 0.0, 0.0, 0.0};
  Vec2 hourglass = Vec2::Zero();
};

/// Adds the nodal forces f (N) and moments m (N mm) of the resultants r at coordinates x and
/// directors d (global components; dg = compute_director_gradients(d)): f_I = r . dM/dx_I,
/// m_I = d_I x (r . dM/dd_I), the latter because a rotation w_I turns d_I at the rate w_I x d_I.
/// gamma from `basis`, as the measures.
inline void add_director_forces(const Quad3& x, const Quad3& d, const QuadDirectorGradients& dg,
                                const QuadBasis& basis, const DirectorResultants& r, Quad3& f,
                                Quad3& m) {
  const Vec3 g_xi = 0.25 * (-x.col(0) + x.col(1) + x.col(2) - x.col(3));
  const Vec3 g_eta = 0.25 * (-x.col(0) - x.col(1) + x.col(2) + x.col(3));
  const Vec3& d_xi = dg.d_xi;
  const Vec3& d_eta = dg.d_eta;
  Vec3 q = Vec3::Zero();
  for (int i = 0; i < 4; ++i) {
    q += basis.gamma[i] * d.col(i);
  }
  // Curvature and hourglass: x_I through g; d_I through the arc differences (curvature) and Q.
  const Vec3 along_x = r.curvature(0) * d_xi + r.curvature(2) * d_eta + r.hourglass(0) * q;
  const Vec3 along_e = r.curvature(1) * d_eta + r.curvature(2) * d_xi + r.hourglass(1) * q;
  const Vec3 dir_xi = r.curvature(0) * g_xi + r.curvature(2) * g_eta;
  const Vec3 dir_eta = r.curvature(1) * g_eta + r.curvature(2) * g_xi;
  const Vec3 dir_hg = r.hourglass(0) * g_xi + r.hourglass(1) * g_eta;
  Quad3 a;  // dW/dd_I
  for (int i = 0; i < 4; ++i) {
    f.col(i) += 0.25 * (kXi[i] * along_x + kEta[i] * along_e);
    a.col(i) = basis.gamma[i] * dir_hg;
  }
  for (int k = 0; k < 4; ++k) {
    Vec3 grad_a = Vec3::Zero();
    Vec3 grad_b = Vec3::Zero();
    add_arc_difference_gradient(dg.edge[k], 0.25 * (k < 2 ? dir_xi : dir_eta), grad_a, grad_b);
    a.col(kEdgeNodes[k][0]) += grad_a;
    a.col(kEdgeNodes[k][1]) += grad_b;
  }
  for (int k = 0; k < 4; ++k) {
    const int i = kEdgeNodes[k][0];
    const int j = kEdgeNodes[k][1];
    const Vec3 fx = (0.25 * r.edge[k]) * (d.col(i) + d.col(j));
    f.col(j) += fx;
    f.col(i) -= fx;
    const Vec3 fd = (0.25 * r.edge[k]) * (x.col(j) - x.col(i));
    a.col(i) += fd;
    a.col(j) += fd;
  }
  for (int i = 0; i < 4; ++i) {
    m.col(i) += d.col(i).cross(a.col(i));
  }
}

/// In-plane Cartesian components, in the frame (e1, e2), of the contravariant vectors: p =
/// grad xi, r = grad eta (1/mm).
struct CartesianMap {
  Vec2 p;
  Vec2 r;
};

inline CartesianMap make_cartesian_map(const QuadBasis& b, const Mat3& frame) {
  return {Vec2(b.grad_xi.dot(frame.col(0)), b.grad_xi.dot(frame.col(1))),
          Vec2(b.grad_eta.dot(frame.col(0)), b.grad_eta.dot(frame.col(1)))};
}

/// Cartesian curvature (1/mm; xx, yy, engineering xy) of a covariant K: kappa = -T K, so that
/// kappa = -sym grad beta as the Belytschko-Lin-Tsay element's.
inline Vec3 to_cartesian_curvature(const CartesianMap& c, const Vec3& k) {
  const Vec2& p = c.p;
  const Vec2& r = c.r;
  return -Vec3(
      p(0) * p(0) * k(0) + r(0) * r(0) * k(1) + p(0) * r(0) * k(2),
      p(1) * p(1) * k(0) + r(1) * r(1) * k(1) + p(1) * r(1) * k(2),
      2.0 * p(0) * p(1) * k(0) + 2.0 * r(0) * r(1) * k(1) + (p(0) * r(1) + p(1) * r(0)) * k(2));
}

/// The covariant resultant conjugate to K of a Cartesian moment m (N mm per mm, xx, yy, xy) times
/// the area (mm^2): -area T^T m.
inline Vec3 to_covariant_moment(const CartesianMap& c, const Vec3& m, double area) {
  const Vec2& p = c.p;
  const Vec2& r = c.r;
  return -area * Vec3(m(0) * p(0) * p(0) + m(1) * p(1) * p(1) + 2.0 * m(2) * p(0) * p(1),
                      m(0) * r(0) * r(0) + m(1) * r(1) * r(1) + 2.0 * m(2) * r(0) * r(1),
                      m(0) * p(0) * r(0) + m(1) * p(1) * r(1) + m(2) * (p(0) * r(1) + p(1) * r(0)));
}

}  // namespace sf
