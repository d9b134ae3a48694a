#pragma once
// Curvature and DSG3 transverse shear of the 3-node shell triangle as functions of its nodes'
// positions x_I and directors d_I (global components), for the assumed-strain formulation: total,
// objective, blind to the drilling rotation, as the quad's (shell_quad_directors.hpp). The
// natural coordinates are those of the linear triangle, x = x_0 + s1 (x_1 - x_0) + s2 (x_2 - x_0).
#include "core/types.hpp"
#include "element/shell_quad_directors.hpp"

namespace sf {

/// Contravariant vectors (tangent, 1/mm) of the basis (a1, a2) of two edge vectors from a node.
struct EdgeDual {
  Vec3 grad1;
  Vec3 grad2;
};

inline EdgeDual compute_edge_dual(const Vec3& a1, const Vec3& a2) {
  const double a11 = a1.squaredNorm();
  const double a22 = a2.squaredNorm();
  const double a12 = a1.dot(a2);
  const double det = a11 * a22 - a12 * a12;
  return {(a22 * a1 - a12 * a2) / det, (a11 * a2 - a12 * a1) / det};
}

/// The sides of the triangle, a -> b: 0 = (0 -> 1), 1 = (0 -> 2), 2 = (1 -> 2).
inline constexpr int kSideNodes[3][2] = {{0, 1}, {0, 2}, {1, 2}};

/// The covariant measures of one configuration: K = (a1 . d_1, a2 . d_2, a1 . d_2 + a2 . d_1)
/// with a1 = x_1 - x_0, a2 = x_2 - x_0, d_1 = the arc difference from d_0 to d_1 (mm), and the
/// shear gap of each side, (x_b - x_a) . (d_a + d_b) / 2 (mm).
struct TriangleDirectorMeasures {
  Vec3 curvature;
  double gap[3];
};

inline TriangleDirectorMeasures compute_triangle_director_measures(const Tri3& x, const Tri3& d) {
  TriangleDirectorMeasures m;
  const Vec3 a1 = x.col(1) - x.col(0);
  const Vec3 a2 = x.col(2) - x.col(0);
  const Vec3 d1 = make_arc_difference(d.col(0), d.col(1)).value;
  const Vec3 d2 = make_arc_difference(d.col(0), d.col(2)).value;
  m.curvature = Vec3(a1.dot(d1), a2.dot(d2), a1.dot(d2) + a2.dot(d1));
  for (int k = 0; k < 3; ++k) {
    const int a = kSideNodes[k][0];
    const int b = kSideNodes[k][1];
    m.gap[k] = 0.5 * (x.col(b) - x.col(a)).dot(d.col(a) + d.col(b));
  }
  return m;
}

/// DSG3 (Bletzinger, Bischoff & Ramm 2000): the Cartesian shear of origin node s is
/// grad1_s g_sp + grad2_s g_sq (p, q the next nodes, grad_s the dual of (x_p - x_s, x_q - x_s)),
/// averaged over the three origins. weight(c, k): the frame component c (0, 1) of the weight of
/// side k's gap (signed: g_ba = -g_ab).
struct Dsg3Weights {
  Eigen::Matrix<double, 2, 3> weight;
};

inline Dsg3Weights compute_dsg3_weights(const Tri3& x, const Mat3& frame) {
  Dsg3Weights w;
  w.weight.setZero();
  // Side index and sign of the gap from node i to node j.
  auto side = [](int i, int j, double& sign) {
    sign = i < j ? 1.0 : -1.0;
    const int lo = i < j ? i : j;
    const int hi = i < j ? j : i;
    return lo == 0 ? (hi == 1 ? 0 : 1) : 2;
  };
  for (int s = 0; s < 3; ++s) {
    const int p = (s + 1) % 3;
    const int q = (s + 2) % 3;
    const EdgeDual dual = compute_edge_dual(x.col(p) - x.col(s), x.col(q) - x.col(s));
    double sign_p = 0.0;
    double sign_q = 0.0;
    const int kp = side(s, p, sign_p);
    const int kq = side(s, q, sign_q);
    for (int c = 0; c < 2; ++c) {
      w.weight(c, kp) += sign_p * dual.grad1.dot(frame.col(c)) / 3.0;
      w.weight(c, kq) += sign_q * dual.grad2.dot(frame.col(c)) / 3.0;
    }
  }
  return w;
}

/// Adds the nodal forces f (N) and moments m (N mm) of the resultants conjugate to the measures
/// (curvature: N mm; gaps: N) at coordinates x and directors d: f_I = r . dM/dx_I,
/// m_I = d_I x (r . dM/dd_I).
inline void add_triangle_director_forces(const Tri3& x, const Tri3& d, const Vec3& curvature,
                                         const double gap[3], Tri3& f, Tri3& m) {
  const Vec3 a1 = x.col(1) - x.col(0);
  const Vec3 a2 = x.col(2) - x.col(0);
  const ArcDifference arc1 = make_arc_difference(d.col(0), d.col(1));
  const ArcDifference arc2 = make_arc_difference(d.col(0), d.col(2));
  const Vec3& d1 = arc1.value;
  const Vec3& d2 = arc2.value;
  const Vec3 at1 = curvature(0) * d1 + curvature(2) * d2;  // dW/dx_1 (and -dW/dx_0)
  const Vec3 at2 = curvature(1) * d2 + curvature(2) * d1;  // dW/dx_2
  const Vec3 dd1 = curvature(0) * a1 + curvature(2) * a2;  // dW/dd_1
  const Vec3 dd2 = curvature(1) * a2 + curvature(2) * a1;  // dW/dd_2
  f.col(1) += at1;
  f.col(2) += at2;
  f.col(0) -= at1 + at2;
  Tri3 a = Tri3::Zero();
  Vec3 grad0 = Vec3::Zero();
  Vec3 grad1 = Vec3::Zero();
  Vec3 grad2 = Vec3::Zero();
  add_arc_difference_gradient(arc1, dd1, grad0, grad1);
  add_arc_difference_gradient(arc2, dd2, grad0, grad2);
  a.col(0) = grad0;
  a.col(1) = grad1;
  a.col(2) = grad2;
  for (int k = 0; k < 3; ++k) {
    const int i = kSideNodes[k][0];
    const int j = kSideNodes[k][1];
    const Vec3 fx = (0.5 * gap[k]) * (d.col(i) + d.col(j));
    f.col(j) += fx;
    f.col(i) -= fx;
    const Vec3 fd = (0.5 * gap[k]) * (x.col(j) - x.col(i));
    a.col(i) += fd;
    a.col(j) += fd;
  }
  for (int i = 0; i < 3; ++i) {
    m.col(i) += d.col(i).cross(a.col(i));
  }
}

}  // namespace sf
