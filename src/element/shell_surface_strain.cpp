#include "element/shell_surface_strain.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace sf {

Matrix3X nodal_unit_normals(const QuadConn& quads, const TriConn& triangles, const Matrix3X& x) {
  Matrix3X normals = Matrix3X::Zero(3, x.cols());
  for (Eigen::Index e = 0; e < quads.cols(); ++e) {
    const Vec3 n = (x.col(quads(2, e)) - x.col(quads(0, e)))
                       .cross(x.col(quads(3, e)) - x.col(quads(1, e)))
                       .normalized();
    for (int a = 0; a < 4; ++a) {
      normals.col(quads(a, e)) += n;
    }
  }
  for (Eigen::Index k = 0; k < triangles.cols(); ++k) {
    const Vec3 n = (x.col(triangles(1, k)) - x.col(triangles(0, k)))
                       .cross(x.col(triangles(2, k)) - x.col(triangles(0, k)))
                       .normalized();
    for (int a = 0; a < 3; ++a) {
      normals.col(triangles(a, k)) += n;
    }
  }
  for (Eigen::Index i = 0; i < normals.cols(); ++i) {
    const double length = normals.col(i).norm();
    if (length > 0.0) {
      normals.col(i) /= length;
    }
  }
  return normals;
}

namespace {

// The tangents of the surface at zeta through the corners (their centre's parametric
// derivatives: a quad's bilinear map, a triangle's two edges), and its normal there.
Mat3 surface_basis(std::span<const Vec3> mid, std::span<const Vec3> normal, double offset) {
  auto point = [&](std::size_t a) -> Vec3 { return mid[a] + offset * normal[a]; };
  Vec3 g1, g2;
  if (mid.size() == 4) {
    g1 = 0.25 * (-point(0) + point(1) + point(2) - point(3));
    g2 = 0.25 * (-point(0) - point(1) + point(2) + point(3));
  } else {
    g1 = point(1) - point(0);
    g2 = point(2) - point(0);
  }
  Mat3 basis;
  basis.col(0) = g1;
  basis.col(1) = g2;
  basis.col(2) = g1.cross(g2).normalized();
  return basis;
}

}  // namespace

Strain6 surface_log_strain(const ElementCorners& c, double zeta, double t0, double t) {
  const Mat3 reference = surface_basis(c.X, c.N, 0.5 * zeta * t0);
  Mat3 current = surface_basis(c.x, c.n, 0.5 * zeta * t);
  current.col(2) *= t / t0;  // the normal fibre's stretch
  const Mat3 f = current * reference.inverse();
  const Eigen::SelfAdjointEigenSolver<Mat3> b(f * f.transpose());
  const Vec3 log_stretch = 0.5 * b.eigenvalues().array().log().matrix();
  const Mat3 strain = b.eigenvectors() * log_stretch.asDiagonal() * b.eigenvectors().transpose();
  Strain6 out;
  out << strain(0, 0), strain(1, 1), strain(2, 2), strain(0, 1), strain(1, 2), strain(0, 2);
  return out;
}

PrincipalStrains surface_principal_strains(const ElementCorners& c, double zeta, double t0,
                                           double t) {
  const Mat3 reference = surface_basis(c.X, c.N, 0.5 * zeta * t0);
  const Mat3 current = surface_basis(c.x, c.n, 0.5 * zeta * t);
  // Metrics of the tangents G_a (reference) and g_a (current); the squared principal stretches
  // are the eigenvalues of M = G^-1 g (2 x 2).
  const Eigen::Matrix2d big_g = reference.leftCols<2>().transpose() * reference.leftCols<2>();
  const Eigen::Matrix2d small_g = current.leftCols<2>().transpose() * current.leftCols<2>();
  const Eigen::Matrix2d m = big_g.inverse() * small_g;
  const double mean = 0.5 * m.trace();
  // mean^2 - det(M), written without its cancellation when the stretches are nearly equal.
  const double half_difference = 0.5 * (m(0, 0) - m(1, 1));
  const double radius =
      std::sqrt(std::max(0.0, half_difference * half_difference + m(0, 1) * m(1, 0)));
  return {0.5 * std::log(mean + radius), 0.5 * std::log(mean - radius)};
}

}  // namespace sf
