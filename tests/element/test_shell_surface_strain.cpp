// Surface strains measured from the shape (element/shell_surface_strain.hpp), against closed
// forms: a homogeneous stretch of a flat element (exact), a rigid motion (zero), and a strip
// bent onto a cylinder (the chord of the surface's arc: exact for the bilinear map, and within
// phi^2 / 6 + phi^4 / 90 of the continuum's ln(1 + z / R) for a half-angle phi).
#include <gtest/gtest.h>

#include <array>
#include <cmath>

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
  // A strip element of width w along x and depth d along y, flat at z = 0, bent about the y axis
  // onto a cylinder of mid-surface radius R (its centre at z = -R), thickness unchanged.
  const double w = 2.0, d = 1.0, R = 20.0, t = 1.0, phi = w / (2.0 * R);
  Corners c = flat_rectangle(w, d);
  for (std::size_t a = 0; a < 4; ++a) {
    const double angle = (c.X[a].x() - 0.5 * w) / R;
    c.x[a] = Vec3(R * std::sin(angle), c.X[a].y(), R * std::cos(angle) - R);
    c.n[a] = Vec3(std::sin(angle), 0.0, std::cos(angle));
  }
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

}  // namespace
}  // namespace sf
