// Surface strains measured from the shape (element/shell_surface_strain.hpp), against closed
// forms: a homogeneous stretch of a flat element (exact), a rigid motion (zero), and a strip
// bent onto a cylinder (the chord of the surface's arc: exact for the bilinear map, and within
// phi^2 / 6 + phi^4 / 90 of the continuum's ln(1 + z / R) for a half-angle phi). The in-plane
// principal strains (the formability results) against the same closed forms, on a distorted,
// tilted quadrilateral and a triangle stretched along axes at an angle to their edges.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "element/shell_surface_strain.hpp"

namespace sf {
namespace {

struct Corners {
  std::array<Vec3, 4> X, x, N, n;
  ElementCorners view() const { return {X, x, N, n}; }
};

Corners flat_rectangle(double a, double b) {
  Corners c;
  c.X = {Vec3(0, 0, 0), Vec3(a, 0, 0), Vec3(a, b, 0), Vec3(0, b, 0)};
  c.x = c.X;
  c.N.fill(Vec3::UnitZ());
  c.n = c.N;
  return c;
}

// A strip element of width w along x and depth d along y, flat at z = 0, bent about the y axis
// onto a cylinder of mid-surface radius R (its centre at z = -R), its nodal normals radial.
Corners strip_bent_onto_cylinder(double w, double d, double R) {
  Corners c = flat_rectangle(w, d);
  for (std::size_t a = 0; a < 4; ++a) {
    const double angle = (c.X[a].x() - 0.5 * w) / R;
    c.x[a] = Vec3(R * std::sin(angle), c.X[a].y(), R * std::cos(angle) - R);
    c.n[a] = Vec3(std::sin(angle), 0.0, std::cos(angle));
  }
  return c;
}

TEST(SurfaceStrain, HomogeneousStretchIsExactAtEverySurface) {
  Corners c = flat_rectangle(2.0, 1.0);
  const double l1 = 1.2, l2 = 0.9, t0 = 1.0, t = t0 / (l1 * l2);
  for (std::size_t a = 0; a < 4; ++a) {
    c.x[a] = Vec3(l1 * c.X[a].x(), l2 * c.X[a].y(), 0.0);
  }
  for (double zeta : {-1.0, 0.0, 1.0}) {
    const Strain6 e = surface_log_strain(c.view(), zeta, t0, t);
    EXPECT_NEAR(e[0], std::log(l1), 1e-14);
    EXPECT_NEAR(e[1], std::log(l2), 1e-14);
    EXPECT_NEAR(e[2], std::log(t / t0), 1e-14);
    EXPECT_NEAR(e[3], 0.0, 1e-14);
    EXPECT_NEAR(e[4], 0.0, 1e-14);
    EXPECT_NEAR(e[5], 0.0, 1e-14);
  }
}

TEST(SurfaceStrain, RigidMotionOfAWarpedElementIsNoStrain) {
  Corners c = flat_rectangle(2.0, 1.5);
  c.X[2].z() = 0.2;  // warped
  const TriConn no_triangles(3, 0);
  QuadConn quad(4, 1);
  quad << 0, 1, 2, 3;
  Matrix3X xs(3, 4);
  for (int a = 0; a < 4; ++a) {
    xs.col(a) = c.X[static_cast<std::size_t>(a)];
  }
  const Matrix3X normals = nodal_unit_normals(quad, no_triangles, xs);
  const Mat3 r = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  for (std::size_t a = 0; a < 4; ++a) {
    c.N[a] = normals.col(static_cast<Eigen::Index>(a));
    c.x[a] = r * c.X[a] + Vec3(5, -3, 2);
    c.n[a] = r * c.N[a];
  }
  for (double zeta : {-1.0, 1.0}) {
    EXPECT_LT(surface_log_strain(c.view(), zeta, 0.8, 0.8).cwiseAbs().maxCoeff(), 1e-14);
  }
}

TEST(SurfaceStrain, StripBentOntoACylinder) {
  // Thickness unchanged.
  const double w = 2.0, d = 1.0, R = 20.0, t = 1.0, phi = w / (2.0 * R);
  const Corners c = strip_bent_onto_cylinder(w, d, R);
  for (double zeta : {-1.0, 1.0}) {
    const double r = R + 0.5 * zeta * t;  // the surface's radius
    const Strain6 e = surface_log_strain(c.view(), zeta, t, t);
    // The bilinear map's tangent at the centre is the chord: 2 r sin(phi) against w = 2 R phi.
    EXPECT_NEAR(e[0], std::log(r * std::sin(phi) / (R * phi)), 1e-13);
    // The continuum's strain of that surface, ln(r / R): the chord's ln(sin(phi) / phi) =
    // -phi^2 / 6 - phi^4 / 180 - ... away.
    EXPECT_NEAR(e[0], std::log(r / R), phi * phi / 6.0 + std::pow(phi, 4) / 90.0);
    EXPECT_NEAR(e[1], 0.0, 1e-14);
    EXPECT_NEAR(e[2], 0.0, 1e-14);
  }
}

// A flat element in a tilted plane, stretched homogeneously by l1 along a direction at 0.6 rad to
// its first edge and l2 across it, then turned rigidly: the in-plane principal strains are
// ln l1 and ln l2 exactly (to rounding) at every surface, for a distorted quad and a triangle.
TEST(SurfacePrincipalStrains, HomogeneousStretchOfTiltedDistortedElements) {
  const Mat3 tilt = Eigen::AngleAxisd(0.4, Vec3(1, -1, 0.5).normalized()).toRotationMatrix();
  const Mat3 turn = Eigen::AngleAxisd(1.1, Vec3(-2, 1, 3).normalized()).toRotationMatrix();
  const double angle = 0.6, l1 = 1.25, l2 = 0.85, t0 = 1.2, t = t0 / (l1 * l2);
  const Eigen::Matrix2d q = Eigen::Rotation2Dd(angle).toRotationMatrix();
  const Eigen::Matrix2d f = q * Eigen::Vector2d(l1, l2).asDiagonal() * q.transpose();
  const std::array<Eigen::Vector2d, 4> plane = {Eigen::Vector2d(0, 0), Eigen::Vector2d(2.3, -0.2),
                                                Eigen::Vector2d(1.9, 1.4),
                                                Eigen::Vector2d(-0.3, 0.9)};
  for (std::size_t corners : {4u, 3u}) {
    Corners c;
    for (std::size_t a = 0; a < corners; ++a) {
      const Eigen::Vector2d p = plane[a], fp = f * plane[a];
      c.X[a] = tilt * Vec3(p.x(), p.y(), 0.0);
      c.x[a] = turn * tilt * Vec3(fp.x(), fp.y(), 0.0) + Vec3(4, 5, 6);
      c.N[a] = tilt * Vec3::UnitZ();
      c.n[a] = turn * c.N[a];
    }
    const ElementCorners view{
        {c.X.data(), corners}, {c.x.data(), corners}, {c.N.data(), corners}, {c.n.data(), corners}};
    for (double zeta : {-1.0, 0.0, 1.0}) {
      const PrincipalStrains p = surface_principal_strains(view, zeta, t0, t);
      EXPECT_NEAR(p.major, std::log(l1), 1e-14) << corners << " corners, zeta " << zeta;
      EXPECT_NEAR(p.minor, std::log(l2), 1e-14) << corners << " corners, zeta " << zeta;
    }
  }
}

// The bent strip of StripBentOntoACylinder: the top surface stretches along the strip (major =
// the chord's strain, minor 0 across), the bottom shortens (major 0 across, minor the chord's).
TEST(SurfacePrincipalStrains, StripBentOntoACylinderHasTheChordsStrain) {
  const double w = 2.0, d = 1.0, R = 20.0, t = 1.0, phi = w / (2.0 * R);
  const Corners c = strip_bent_onto_cylinder(w, d, R);
  const auto chord_strain = [&](double zeta) {
    return std::log((R + 0.5 * zeta * t) * std::sin(phi) / (R * phi));
  };
  const PrincipalStrains top = surface_principal_strains(c.view(), 1.0, t, t);
  EXPECT_NEAR(top.major, chord_strain(1.0), 1e-13);
  EXPECT_NEAR(top.minor, 0.0, 1e-14);
  const PrincipalStrains bottom = surface_principal_strains(c.view(), -1.0, t, t);
  EXPECT_NEAR(bottom.major, 0.0, 1e-14);
  EXPECT_NEAR(bottom.minor, chord_strain(-1.0), 1e-13);
  // The mid-surface's chord is shorter than the strip by sin(phi) / phi.
  EXPECT_NEAR(surface_principal_strains(c.view(), 0.0, t, t).minor, chord_strain(0.0), 1e-13);
}

// On a warped element under a general deformation (shear, stretch and thinning), the principal
// strains are the in-plane eigenvalues of surface_log_strain's tensor (its third eigenvalue, along
// the normal, is ln(t / t0)).
TEST(SurfacePrincipalStrains, AreTheInPlaneEigenvaluesOfTheSurfaceStrain) {
  Corners c = flat_rectangle(2.0, 1.5);
  c.X[2].z() = 0.15;  // warped
  Mat3 f;
  f << 1.2, 0.15, 0.05, -0.1, 0.9, 0.02, 0.03, 0.04, 1.0;
  QuadConn quad(4, 1);
  quad << 0, 1, 2, 3;
  Matrix3X X(3, 4), x(3, 4);
  for (int a = 0; a < 4; ++a) {
    X.col(a) = c.X[static_cast<std::size_t>(a)];
    x.col(a) = f * X.col(a);
  }
  const Matrix3X N = nodal_unit_normals(quad, TriConn(3, 0), X);
  const Matrix3X n = nodal_unit_normals(quad, TriConn(3, 0), x);
  for (std::size_t a = 0; a < 4; ++a) {
    c.x[a] = x.col(static_cast<Eigen::Index>(a));
    c.N[a] = N.col(static_cast<Eigen::Index>(a));
    c.n[a] = n.col(static_cast<Eigen::Index>(a));
  }
  const double t0 = 1.0, t = 0.93;
  for (double zeta : {-1.0, 0.0, 1.0}) {
    const Strain6 e = surface_log_strain(c.view(), zeta, t0, t);
    Mat3 strain;
    strain << e[0], e[3], e[5], e[3], e[1], e[4], e[5], e[4], e[2];
    Vec3 eigen = Eigen::SelfAdjointEigenSolver<Mat3>(strain).eigenvalues();
    // Drop the normal's ln(t / t0); the other two are major and minor.
    std::vector<double> in_plane(eigen.data(), eigen.data() + 3);
    const auto normal = std::min_element(in_plane.begin(), in_plane.end(), [&](double a, double b) {
      return std::abs(a - std::log(t / t0)) < std::abs(b - std::log(t / t0));
    });
    EXPECT_NEAR(*normal, std::log(t / t0), 1e-12);
    in_plane.erase(normal);
    const PrincipalStrains p = surface_principal_strains(c.view(), zeta, t0, t);
    EXPECT_NEAR(p.major, std::max(in_plane[0], in_plane[1]), 1e-12) << "zeta " << zeta;
    EXPECT_NEAR(p.minor, std::min(in_plane[0], in_plane[1]), 1e-12) << "zeta " << zeta;
  }
}

}  // namespace
}  // namespace sf
