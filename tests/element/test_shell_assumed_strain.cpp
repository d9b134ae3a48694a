// The assumed-strain shell formulation (quads and triangles with directors): objectivity under
// large rigid rotations of a curved patch, blindness to the drilling rotation, membrane and
// bending patch tests on distorted elements, internal force = gradient of the stored energy,
// equilibrium, the zero-energy modes of a free element, and the highest frequency with the lumped
// mass (the stable time step). Exact references; tolerances beside each check.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>

#include "element/shell_directors.hpp"
#include "element/shell_mass.hpp"
#include "element/shell_test_support.hpp"

namespace sf {
namespace {

using test::kE;
using test::kNu;
using test::kRho;

const J2PlaneStress kSteel{kE, kNu, SwiftHardening{565.32, 0.007117, 0.2589}};

ShellPart make_as_part(const QuadConn& quads, const TriConn& triangles, const Material& material,
                       int n_points = 5) {
  ShellPart p;
  p.quads = quads;
  p.triangles = triangles;
  p.section = make_gauss_section(n_points);
  p.materials[0].law = material;
  p.materials[0].density = kRho;
  p.formulation = ShellFormulation::assumed_strain;
  return p;
}

ShellState make_as_state(const ShellPart& part, const Matrix3X& x, double t) {
  ShellState st = make_shell_state(element_count(part), part.section.n_points, t);
  initialize_directors(part, x, st);
  return st;
}

// An n x n patch of quads on a sphere of radius r (mm) around the pole, 24 mm across, and the same
// nodes split into triangles (alternating diagonals).
struct CurvedPatch {
  Matrix3X x;
  QuadConn quads;
  TriConn triangles;
};
CurvedPatch make_curved_patch(int n, double r) {
  CurvedPatch p;
  p.x.resize(3, (n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      // A distorted grid: node positions perturbed inside, then put on the sphere.
      const double u =
          24.0 * i / n - 12.0 + ((i % n) && (j % n) ? 1.1 * std::sin(3.0 * i + j) : 0.0);
      const double w =
          24.0 * j / n - 12.0 + ((i % n) && (j % n) ? 0.9 * std::cos(i + 2.0 * j) : 0.0);
      p.x.col(j * (n + 1) + i) = Vec3(u, w, std::sqrt(r * r - u * u - w * w) - r);
    }
  }
  p.quads.resize(4, n * n);
  p.triangles.resize(3, 2 * n * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      const int e = j * n + i;
      p.quads.col(e) << a, a + 1, a + n + 2, a + n + 1;
      p.triangles.col(2 * e) << a, a + 1, a + n + 2;
      p.triangles.col(2 * e + 1) << a, a + n + 2, a + n + 1;
    }
  }
  return p;
}

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double a : v) {
    m = std::max(m, std::abs(a));
  }
  return m;
}

class AssumedStrain : public ::testing::TestWithParam<bool> {  // true: triangles
 protected:
  ShellPart part_of(const CurvedPatch& p, const Material& material) const {
    return GetParam() ? make_as_part(QuadConn(4, 0), p.triangles, material)
                      : make_as_part(p.quads, TriConn(3, 0), material);
  }
};

TEST_P(AssumedStrain, LargeRigidRotationOfACurvedPatchGivesNoStrain) {
  // 60 steps of 0.05 rad (172 deg in all) about a skew axis, the central-difference velocities of
  // the exact rotation: a rigid motion. Directors turn with the nodes, positions with the rotation,
  // so the measures, dot products, are unchanged: stresses stay zero to round-off (1e-13 E: a
  // strain of 1e-13 after 60 steps; measured 7e-15 E), as do the forces (1e-13 E t L; measured
  // 1.3e-15).
  const CurvedPatch p = make_curved_patch(3, 30.0);
  const ShellPart part = part_of(p, kSteel);
  ShellState st = make_as_state(part, p.x, 1.0);
  const Vec3 axis = Vec3(1.0, -2.0, 0.7).normalized();
  const Mat3 step = test::rotation(axis, 0.05);
  const double dt = 1e-6;
  Matrix3X x = p.x;
  test::StepOut o;
  for (int n = 0; n < 60; ++n) {
    const Matrix3X x_next = step * x;
    const Matrix3X v = (x_next - x) / dt;
    const Matrix3X w = (axis * (0.05 / dt)).replicate(1, x.cols());
    o = test::run_step(part, x_next, v, w, dt, st);
    x = x_next;
  }
  EXPECT_LT(max_abs(st.sxx) + max_abs(st.syy) + max_abs(st.sxy), 1e-13 * kE);
  EXPECT_LT(max_abs(st.sxz) + max_abs(st.syz), 1e-13 * kE);
  EXPECT_LT(max_abs(st.hourglass), 1e-13 * kE * 24.0);
  EXPECT_LT(o.f.cwiseAbs().maxCoeff() + o.m.cwiseAbs().maxCoeff() / 24.0, 1e-13 * kE * 24.0);
}

TEST_P(AssumedStrain, RotationAboutTheDirectorsMovesNothing) {
  // Every node turned about its own director (the drilling rotation) by a different rate: no
  // director moves, so no strain, no stress and no force: zero to round-off (1e-14 E, and 1e-14
  // E t L for the forces; measured 1e-17 and 4e-19).
  const CurvedPatch p = make_curved_patch(3, 30.0);
  const ShellPart part = part_of(p, ElasticPlaneStress{kE, kNu});
  ShellState st = make_as_state(part, p.x, 1.0);
  const Matrix3X normal = compute_nodal_normals(part, p.x);
  Matrix3X w(3, p.x.cols());
  for (Eigen::Index i = 0; i < w.cols(); ++i) {
    w.col(i) = (100.0 + 37.0 * static_cast<double>(i % 5)) * normal.col(i);
  }
  const test::StepOut o = test::run_step(part, p.x, Matrix3X::Zero(3, p.x.cols()), w, 1e-4, st);
  EXPECT_LT(max_abs(st.sxx) + max_abs(st.syy) + max_abs(st.sxy) + max_abs(st.sxz) + max_abs(st.syz),
            1e-14 * kE);
  EXPECT_LT(o.f.cwiseAbs().maxCoeff() + o.m.cwiseAbs().maxCoeff() / 24.0, 1e-14 * kE * 24.0);
}

TEST_P(AssumedStrain, ForcesAndMomentsAreInEquilibrium) {
  // Random velocities and rotations on the curved distorted patch, plastic material, two steps:
  // the internal forces sum to zero and their moment about the origin, sum x_I x f_I + m_I, is
  // zero (round-off: 1e-9 of the force scale times the patch size).
  const CurvedPatch p = make_curved_patch(3, 30.0);
  const ShellPart part = part_of(p, kSteel);
  ShellState st = make_as_state(part, p.x, 1.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  Matrix3X v(3, p.x.cols());
  Matrix3X w(3, p.x.cols());
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    v(i) = 5e3 * uni(rng);
    w(i) = 500.0 * uni(rng);
  }
  const double dt = 1e-6;
  test::StepOut o = test::run_step(part, p.x + dt * v, v, w, dt, st);
  o = test::run_step(part, p.x + 2 * dt * v, v, w, dt, st);
  const Matrix3X x = p.x + 2 * dt * v;
  Vec3 force = Vec3::Zero();
  Vec3 moment = Vec3::Zero();
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    force += o.f.col(i);
    moment += x.col(i).cross(o.f.col(i)) + o.m.col(i);
  }
  const double scale = o.f.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 1.0);
  EXPECT_LT(force.norm(), 1e-9 * scale);
  EXPECT_LT(moment.norm(), 1e-9 * scale * 24.0);
}

// The stiffness (6 n x 6 n: ux uy uz per node, then rx ry rz per node) of a stress-free elastic
// part at x0, by central differences of one step from rest (dt = 1), symmetrised.
Eigen::MatrixXd element_stiffness(const ShellPart& part, const Matrix3X& x0, double t) {
  const int n = static_cast<int>(x0.cols());
  Eigen::MatrixXd k(6 * n, 6 * n);
  for (int j = 0; j < 6 * n; ++j) {
    const double h = 1e-7 * (j < 3 * n ? 1.0 : 0.1);
    Eigen::VectorXd col = Eigen::VectorXd::Zero(6 * n);
    for (double sgn : {1.0, -1.0}) {
      Matrix3X u = Matrix3X::Zero(3, n);
      Matrix3X phi = Matrix3X::Zero(3, n);
      (j < 3 * n ? u(j) : phi(j - 3 * n)) = sgn * h;
      ShellState st = make_as_state(part, x0, t);
      const test::StepOut o = test::run_step(part, x0 + u, u, phi, 1.0, st);
      for (int i = 0; i < 3 * n; ++i) {
        col(i) += sgn * o.f(i) / (2 * h);
        col(3 * n + i) += sgn * o.m(i) / (2 * h);
      }
    }
    k.col(j) = col;
  }
  return 0.5 * (k + k.transpose());
}

// A warped, distorted quad (nodes up to 0.6 mm off the mean plane of a ~10 mm element) in a
// skew position, and a triangle of three of its nodes.
Matrix3X warped_quad() {
  Matrix3X x(3, 4);
  x << 0.0, 11.0, 9.0, -1.5,  //
      0.0, 1.0, 8.0, 6.0,     //
      0.6, -0.6, 0.6, -0.6;
  return test::rotation(Vec3(-1, 2, 1), 0.9) * x + Vec3(1, 2, 3).replicate(1, 4);
}

TEST_P(AssumedStrain, AFreePatchHasOnlyRigidAndDrillingZeroModes) {
  // Eigenvalues of the stiffness of a free 2 x 2 patch (9 nodes) on the sphere: the 6 rigid-body
  // modes and one drilling rotation per node have zero energy (< 1e-9 of the largest,
  // finite-difference noise); every other mode, the hourglass patterns included, is resisted
  // (> 1e-7 of the largest: the smallest physical modes, bending, are (t/L)^2 / 12 ~ 1e-3 of the
  // membrane ones here). (A single linear triangle has one more zero mode, 9 deformation modes
  // against 8 strains; a mesh does not.)
  const CurvedPatch p = make_curved_patch(2, 30.0);
  const ShellPart part = part_of(p, ElasticPlaneStress{kE, kNu});
  const Eigen::VectorXd lambda =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(element_stiffness(part, p.x, 1.0))
          .eigenvalues();
  const double largest = lambda.cwiseAbs().maxCoeff();
  const int zero_modes = 6 + static_cast<int>(p.x.cols());
  for (int i = 0; i < zero_modes; ++i) {
    EXPECT_LT(std::abs(lambda(i)) / largest, 1e-9) << "mode " << i;
  }
  EXPECT_GT(lambda(zero_modes) / largest, 1e-7);
  std::printf("%s: %d zero modes; next eigenvalue / largest = %.3e\n",
              GetParam() ? "triangles" : "quads", zero_modes, lambda(zero_modes) / largest);
}

// The warped quad or, for triangles, the triangle of its first three nodes.
struct OneElement {
  Matrix3X x;
  ShellPart part;
};
OneElement one_element(bool triangle, const Material& material, int n_points) {
  const Matrix3X xq = warped_quad();
  if (triangle) {
    TriConn t(3, 1);
    t << 0, 1, 2;
    return {xq.leftCols<3>(), make_as_part(QuadConn(4, 0), t, material, n_points)};
  }
  QuadConn q(4, 1);
  q << 0, 1, 2, 3;
  return {xq, make_as_part(q, TriConn(3, 0), material, n_points)};
}

// Work of one step from rest with displacement u and rotation phi (dt = 1), elastic: the stored
// energy (stress work + stabilisation), and the forces of that step.
test::StepOut step_from_rest(const OneElement& el, const Matrix3X& u, const Matrix3X& phi) {
  ShellState st = make_as_state(el.part, el.x, 0.9);
  return test::run_step(el.part, el.x + u, u, phi, 1.0, st);
}

TEST_P(AssumedStrain, InternalForceIsTheGradientOfTheStoredEnergy) {
  // For an elastic step from rest the work of the step (stresses and stabilisation, trapezoidal
  // on a linear law) is the stored energy W(u, phi), and f_int = dW/du, m_int = dW/dphi up to the
  // O(|u| / L) ~ 1e-6 difference between the mid-step and end-of-step geometry. Central
  // differences; tolerance 1e-4 on the relative norm of the whole vector and of the moments.
  const OneElement el = one_element(GetParam(), ElasticPlaneStress{kE, kNu}, 3);
  const int n = static_cast<int>(el.x.cols());
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  Matrix3X u(3, n);
  Matrix3X phi(3, n);
  for (int i = 0; i < 3 * n; ++i) {
    u(i) = 1e-5 * uni(rng);
    phi(i) = 1e-6 * uni(rng);
  }
  auto energy = [&](const Matrix3X& du, const Matrix3X& dphi) {
    const test::StepOut o = step_from_rest(el, du, dphi);
    return o.r.internal_work + o.r.hourglass_work;
  };
  const test::StepOut o = step_from_rest(el, u, phi);
  Eigen::VectorXd f(6 * n);
  Eigen::VectorXd fd(6 * n);
  for (int j = 0; j < 3 * n; ++j) {
    f(j) = o.f(j);
    f(3 * n + j) = o.m(j);
    Matrix3X up = u, um = u, pp = phi, pm = phi;
    up(j) += 1e-8;
    um(j) -= 1e-8;
    pp(j) += 1e-9;
    pm(j) -= 1e-9;
    fd(j) = (energy(up, phi) - energy(um, phi)) / 2e-8;
    fd(3 * n + j) = (energy(u, pp) - energy(u, pm)) / 2e-9;
  }
  const double err = (f - fd).norm() / f.norm();
  const double err_m = (f.tail(3 * n) - fd.tail(3 * n)).norm() / f.tail(3 * n).norm();
  EXPECT_LT(err, 1e-4);
  EXPECT_LT(err_m, 1e-4);
  std::printf("energy gradient: relative error %.2e (moments %.2e)\n", err, err_m);
}

// The 5-element patch of MacNeal & Harder as quads, or each quad split into two triangles.
ShellPart patch_part(bool triangles, int n_points) {
  const QuadConn q = test::patch_quads();
  if (!triangles) {
    return make_as_part(q, TriConn(3, 0), ElasticPlaneStress{kE, kNu}, n_points);
  }
  TriConn t(3, 10);
  for (int e = 0; e < 5; ++e) {
    t.col(2 * e) << q(0, e), q(1, e), q(2, e);
    t.col(2 * e + 1) << q(0, e), q(2, e), q(3, e);
  }
  return make_as_part(QuadConn(4, 0), t, ElasticPlaneStress{kE, kNu}, n_points);
}

TEST_P(AssumedStrain, PatchTestsOnDistortedElements) {
  // The distorted patch (MacNeal & Harder 1985) in a skew plane, one step from rest (dt = 1):
  // (a) membrane u = G x: the strain sym(G) and stress C sym(G) in every element;
  // (b) constant curvature: w = -(kx x^2 + ky y^2 + kxy x y) / 2 with the Kirchhoff rotations
  //     beta = -grad w: the stress C z (kx, ky, kxy) at every thickness point, no shear;
  // with the interior nodes (4..7) free of force (a) or moment (b), the stabilisation silent.
  // Each load is applied with both signs and the half difference taken, which removes the
  // geometric terms of second order (the membrane strain w'^2 / 2, the frames' rotation): what
  // remains is third order and round-off. Tolerance 1e-8, except for the interior moments of the
  // bending test, 1e-7: there the third-order terms grow as (k L)^2 (L / t)^2 (measured 1.5e-7 at
  // k = 1e-6 /mm) and the round-off of the shear gaps, amplified by the stiff transverse shear, as
  // 1 / k (4e-8 at k = 1e-7 /mm); k = 3e-7 /mm gives 3e-8.
  const Mat3 q = test::rotation(Vec3(0.3, 1.0, -0.6), 1.1);
  const Matrix3X x_plane = test::patch_nodes();
  const Matrix3X x0 = q * x_plane;
  const double t = 0.8;
  const ShellPart part = patch_part(GetParam(), 3);
  const Mat3 c = plane_stress_stiffness(kE, kNu);
  const int np = part.section.n_points;
  const double z_top = 0.5 * t * part.section.zeta[np - 1];
  for (int load = 0; load < 2; ++load) {
    Matrix3X u = Matrix3X::Zero(3, 8);
    Matrix3X phi = Matrix3X::Zero(3, 8);
    Vec3 strain_top;  // expected strain at the top point, in the patch plane's axes
    if (load == 0) {
      Mat2 g;
      g << 1.0e-5, 0.4e-5, -0.2e-5, -0.5e-5;
      for (int i = 0; i < 8; ++i) {
        u.col(i).head<2>() = g * x_plane.col(i).head<2>();
      }
      strain_top = Vec3(g(0, 0), g(1, 1), g(0, 1) + g(1, 0));
    } else {
      const double kx = 3e-7, ky = -1.8e-7, kxy = 2.4e-7;  // 1/mm
      for (int i = 0; i < 8; ++i) {
        const double x = x_plane(0, i), y = x_plane(1, i);
        u(2, i) = -0.5 * (kx * x * x + ky * y * y + kxy * x * y);
        const double beta_x = kx * x + 0.5 * kxy * y;  // -dw/dx
        const double beta_y = ky * y + 0.5 * kxy * x;
        phi(0, i) = -beta_y;  // beta = (theta_y, -theta_x)
        phi(1, i) = beta_x;
      }
      strain_top = z_top * Vec3(kx, ky, kxy);
    }
    std::vector<double> top[2][3];
    std::vector<double> shear[2];
    Matrix3X f[2];
    Matrix3X m[2];
    double stabilisation = 0.0;
    double work = 0.0;
    for (int sign = 0; sign < 2; ++sign) {
      const double a = sign == 0 ? 1.0 : -1.0;
      ShellState st = make_as_state(part, x0, t);
      const test::StepOut o = test::run_step(part, x0 + a * q * u, a * q * u, a * q * phi, 1.0, st);
      for (int e = 0; e < element_count(part); ++e) {
        const std::size_t k = static_cast<std::size_t>(e * np + np - 1);
        top[sign][0].push_back(st.sxx[k]);
        top[sign][1].push_back(st.syy[k]);
        top[sign][2].push_back(st.sxy[k]);
        shear[sign].push_back(
            std::hypot(st.sxz[static_cast<std::size_t>(e)], st.syz[static_cast<std::size_t>(e)]));
      }
      f[sign] = o.f;
      m[sign] = o.m;
      stabilisation = std::max(stabilisation, std::abs(o.r.hourglass_work));
      work = std::max(work, o.r.internal_work);
    }
    // Top-point stress, half difference, in each element's frame: compare the invariants of the
    // in-plane tensor with the expected one (the element frames differ by an in-plane angle).
    const Vec3 s_top = c * strain_top;
    Mat2 expect;
    expect << s_top(0), s_top(2), s_top(2), s_top(1);
    for (int e = 0; e < element_count(part); ++e) {
      const std::size_t k = static_cast<std::size_t>(e);
      Mat2 got;
      const double sxx = 0.5 * (top[0][0][k] - top[1][0][k]);
      const double syy = 0.5 * (top[0][1][k] - top[1][1][k]);
      const double sxy = 0.5 * (top[0][2][k] - top[1][2][k]);
      got << sxx, sxy, sxy, syy;
      EXPECT_NEAR(got.trace() / expect.trace(), 1.0, 1e-8) << "load " << load << " el " << e;
      EXPECT_NEAR(got.determinant() / expect.determinant(), 1.0, 1e-8) << load << " " << e;
      EXPECT_LT(shear[0][k] + shear[1][k], 1e-8 * s_top.norm()) << load << " " << e;
    }
    const Matrix3X& fa = load == 0 ? f[0] : m[0];
    const Matrix3X& fb = load == 0 ? f[1] : m[1];
    const Matrix3X odd = 0.5 * (fa - fb);
    const double interior = odd.rightCols<4>().norm() / odd.leftCols<4>().norm();
    EXPECT_LT(interior, load == 0 ? 1e-8 : 1e-7) << "load " << load;
    EXPECT_LT(stabilisation, 1e-9 * work) << "load " << load;
    std::printf("patch load %d: interior / boundary %s %.2e, stabilisation / work %.2e\n", load,
                load == 0 ? "force" : "moment", interior, stabilisation / work);
  }
}

double max_frequency(const Eigen::MatrixXd& k, const Eigen::VectorXd& m) {
  const Eigen::VectorXd s = m.cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd a = s.asDiagonal() * k * s.asDiagonal();
  return std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a).eigenvalues().maxCoeff());
}

TEST_P(AssumedStrain, RotationsAndStabilisationNeverLowerTheStableStep) {
  // K phi = w^2 M phi of one free element with the lumped mass and the scaled rotational inertia
  // (alpha = (A + t^2) / 4): the highest frequency with the rotations and the stabilisation must
  // not exceed the highest frequency of the translations alone (tolerance 1e-6, FD stiffness), so
  // the time step formula of the membrane stays the limit. For the square quad that membrane
  // maximum is 2/L sqrt(E / ((1 - nu) rho)), the stabilisation (in-plane bending) included. Over
  // t/L = 0.01 .. 1, nu = 0 .. 0.49, aspect ratio 1 and 4 (quads; triangles: the right triangle of
  // the same rectangle).
  for (double nu : {0.0, 0.3, 0.49}) {
    for (double aspect : {1.0, 4.0}) {
      for (double t_over_l : {0.01, 0.1, 0.5, 1.0}) {
        const double l = 10.0;
        const double t = t_over_l * l;
        Matrix3X x(3, 4);
        x << 0.0, aspect * l, aspect * l, 0.0,  //
            0.0, 0.0, l, l,                     //
            0.0, 0.0, 0.0, 0.0;
        QuadConn q(4, GetParam() ? 0 : 1);
        TriConn tri(3, GetParam() ? 1 : 0);
        if (GetParam()) {
          tri << 0, 1, 2;
          x.conservativeResize(3, 3);
        } else {
          q << 0, 1, 2, 3;
        }
        const ShellPart part = make_as_part(q, tri, ElasticPlaneStress{kE, nu});
        const int n = static_cast<int>(x.cols());
        const Eigen::MatrixXd k = element_stiffness(part, x, t);
        VectorX m;
        VectorX r;
        compute_lumped_mass(part, x, make_as_state(part, x, t), m, r);
        Eigen::VectorXd mass(6 * n);
        for (int i = 0; i < n; ++i) {
          mass.segment<3>(3 * i).setConstant(m(i));
          mass.segment<3>(3 * n + 3 * i).setConstant(r(i));
        }
        const double w_all = max_frequency(k, mass);
        const double w_trans = max_frequency(k.topLeftCorner(3 * n, 3 * n), mass.head(3 * n));
        EXPECT_LE(w_all, w_trans * (1 + 1e-6))
            << "nu " << nu << " aspect " << aspect << " t/L " << t_over_l;
        if (aspect == 1.0 && !GetParam()) {
          const double w_membrane = 2.0 / l * std::sqrt(kE / ((1 - nu) * kRho));
          EXPECT_NEAR(w_trans / w_membrane, 1.0, 1e-6) << "nu " << nu << " t/L " << t_over_l;
        }
      }
    }
  }
}

// The membrane stabilisation resultant of a flat 10 x 10 mm quad stretched along x (v_x = rate x,
// v_y = -rate y / 2: the plastic flow of uniaxial tension) with a small membrane hourglass motion
// superposed (v_x += a h, h = +1, -1, +1, -1), in steps of 2e-4 strain: its increment per step.
std::vector<double> membrane_stabilisation_increments(const Material& material, int steps) {
  Matrix3X x(3, 4);
  x << 0.0, 10.0, 10.0, 0.0, 0.0, 0.0, 10.0, 10.0, 0.0, 0.0, 0.0, 0.0;
  QuadConn q(4, 1);
  q << 0, 1, 2, 3;
  const ShellPart part = make_as_part(q, TriConn(3, 0), material, 3);
  ShellState st = make_as_state(part, x, 1.0);
  const double h[4] = {1.0, -1.0, 1.0, -1.0};
  Matrix3X v = Matrix3X::Zero(3, 4);
  for (int a = 0; a < 4; ++a) {
    v(0, a) = 2e-4 * x(0, a) + 1e-4 * h[a];
    v(1, a) = -1e-4 * x(1, a);
  }
  std::vector<double> increments;
  for (int k = 0; k < steps; ++k) {
    x += v;  // dt = 1
    const double before = st.hourglass[0];
    test::run_step(part, x, v, Matrix3X::Zero(3, 4), 1.0, st);
    increments.push_back(std::abs(st.hourglass[0] - before));
  }
  return increments;
}

TEST(AssumedStrainQuad, MembraneStabilisationFollowsTheMaterialsIncrementalStiffness) {
  // Elastic: every step adds the elastic stabilisation stiffness times the hourglass increment.
  const std::vector<double> elastic =
      membrane_stabilisation_increments(ElasticPlaneStress{kE, kNu}, 40);
  EXPECT_GT(elastic.back(), 0.0);
  // Perfectly plastic J2 (yield at 200 MPa, about 1e-3 strain, step 5): once the element flows in
  // uniaxial tension its stresses stop changing, and so does its stabilisation, as the material
  // resists no further motion; before yield the steps are the elastic ones, bit for bit. With the
  // stabilisation at the elastic moduli the flowing element's hourglass modes kept the elastic
  // stiffness: the isotropic cup drew in 5 % less at 45 degrees (docs/element-and-material.md).
  const std::vector<double> plastic =
      membrane_stabilisation_increments(J2PlaneStress{kE, kNu, LinearHardening{200.0, 0.0}}, 40);
  EXPECT_EQ(plastic[0], elastic[0]);
  EXPECT_EQ(plastic[2], elastic[2]);
  EXPECT_LT(plastic.back(), 1e-2 * elastic.back());
  std::printf("stabilisation increment: elastic %.3e, flowing %.3e (step 40)\n", elastic.back(),
              plastic.back());
}

TEST(AssumedStrainQuad, StabilisationNeverGivesBackMoreThanItStored) {
  // A flat quad, perfectly plastic J2: its membrane hourglass mode is loaded while the element is
  // elastic, then brought back and beyond while the element flows in uniaxial tension. The
  // stabilisation's work over the history stays non-negative: unloading is elastic, so it returns
  // at most what it stored (scaling the unloading too gave a stabilisation energy of -0.065 % of
  // the internal energy at the end of the U-channel).
  Matrix3X x(3, 4);
  x << 0.0, 10.0, 10.0, 0.0, 0.0, 0.0, 10.0, 10.0, 0.0, 0.0, 0.0, 0.0;
  QuadConn q(4, 1);
  q << 0, 1, 2, 3;
  const ShellPart part =
      make_as_part(q, TriConn(3, 0), J2PlaneStress{kE, kNu, LinearHardening{200.0, 0.0}}, 3);
  ShellState st = make_as_state(part, x, 1.0);
  const double h[4] = {1.0, -1.0, 1.0, -1.0};
  const auto velocity = [&](double stretch, double hourglass) {
    Matrix3X v = Matrix3X::Zero(3, 4);
    for (int a = 0; a < 4; ++a) {
      v(0, a) = stretch * x(0, a) + hourglass * h[a];
      v(1, a) = -0.5 * stretch * x(1, a);
    }
    return v;
  };
  double work = 0.0;
  double least = 0.0;
  const auto step = [&](double stretch, double hourglass) {
    const Matrix3X v = velocity(stretch, hourglass);
    x += v;
    work += test::run_step(part, x, v, Matrix3X::Zero(3, 4), 1.0, st).r.hourglass_work;
    least = std::min(least, work);
  };
  for (int k = 0; k < 5; ++k) {
    step(0.0, 2e-4);  // elastic loading of the hourglass mode
  }
  const double stored = work;
  for (int k = 0; k < 40; ++k) {
    step(2e-4, -5e-5);  // the element flows; the mode unloads, then loads the other way
  }
  // Bound: 1 % of the stored energy. The element stretches 4 % over the flow, which changes the
  // stabilisation stiffness the stored resultant is measured against: the least work measured is
  // -0.24 % of the stored energy. With the ratio applied to the unloading as well it was -214 %.
  EXPECT_GT(stored, 0.0);
  EXPECT_GE(least, -0.01 * stored);
  std::printf("stabilisation work: stored %.4e N mm elastically, %.4e after the flow\n", stored,
              work);
}

INSTANTIATE_TEST_SUITE_P(QuadsAndTriangles, AssumedStrain, ::testing::Bool(),
                         [](const auto& param) { return param.param ? "Triangles" : "Quads"; });

}  // namespace
}  // namespace sf
