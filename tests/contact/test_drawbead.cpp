// The drawbead line model (src/contact/drawbead_line.hpp) and the round bead's forces
// (src/contact/round_drawbead.hpp), against closed forms:
//  - the round bead's wrap angle: the span is tangent to both the shoulder's and the bead's
//    mid-surface circles (checked by the distances of their centres from the line);
//  - frictionless, the six bends and unbends give T = 4 dT_s + 2 dT_b, dT = S t^2 / (4 rho)
//    (Marciniak, Duncan & Hu 2002, ch. 6), and friction multiplies each arc by exp(mu alpha);
//  - the line model on a sheet of nodes drawn across it: the slip limits sum to F_r times the
//    length of line the sheet covers (a uniform grid w / m apart: the cosine window's sum is
//    exact), the uplift likewise, the closure read off the gap, nothing beyond the line's ends,
//    a locking bead holding by its springs, the same bits on 1 and 2 threads, and the same
//    forces turned with a turned tool.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "contact/drawbead_line.hpp"
#include "contact/round_drawbead.hpp"
#include "core/errors.hpp"

namespace sf {
namespace {

// ---- round bead ----------------------------------------------------------------------------

std::function<double(double)> constant(double stress) {
  return [stress](double) { return stress; };
}

TEST(RoundDrawbead, WrapAngleMakesTheSpanTangentToBothCircles) {
  const double t = 1.0;
  for (const double clearance : {0.0, 0.3, 1.5}) {
    for (const double depth : {0.5, 2.0, 4.0, 7.0}) {
      const RoundBeadGeometry bead{
          .bead_radius = 4.0, .shoulder_radius = 3.0, .depth = depth, .clearance = clearance};
      const double theta = round_bead_wrap_angle(bead, t);
      const double rho_s = 3.0 + 0.5 * t;
      const double rho_b = 4.0 + 0.5 * t;
      const double a = rho_s + rho_b + clearance;
      // Mid-surface plane outside the bead at z = 0; shoulder centre (-a, -rho_s), bead centre
      // (0, rho_b - depth); the span leaves the shoulder descending at theta.
      const Vec3 shoulder(-a, -rho_s, 0.0);
      const Vec3 crest(0.0, rho_b - depth, 0.0);
      const Vec3 normal(std::sin(theta), std::cos(theta), 0.0);  // the span's, pointing up
      const Vec3 touch = shoulder + rho_s * normal;              // where it leaves the shoulder
      EXPECT_NEAR((crest - touch).dot(normal), rho_b, 1e-12) << depth << " " << clearance;
      EXPECT_GT(theta, 0.0);
      EXPECT_LE(theta, std::numbers::pi / 2 + 1e-12);
    }
  }
  EXPECT_EQ(round_bead_wrap_angle({4.0, 3.0, 0.0, 0.5}, t), 0.0);
  // No clearance: the sheet runs straight down between bead and shoulder once deep enough.
  EXPECT_NEAR(round_bead_wrap_angle({4.0, 3.0, 8.0, 0.0}, t), std::numbers::pi / 2, 1e-12);
}

TEST(RoundDrawbead, FrictionlessIsSixBendsAndFrictionMultipliesEachArc) {
  const RoundBeadGeometry bead{.bead_radius = 4.0, .shoulder_radius = 5.0, .depth = 3.0};
  RoundBeadSheet sheet{.thickness = 1.0, .flow_stress = constant(300.0), .friction = 0.0};
  const double S = 2.0 / std::sqrt(3.0) * 300.0;  // MPa, plane strain
  const double dT_s = S * 1.0 / (4.0 * 5.5);      // N/mm per bend on a shoulder
  const double dT_b = S * 1.0 / (4.0 * 4.5);      // N/mm per bend on the bead
  const RoundBeadForces dry = round_bead_forces(bead, sheet);
  EXPECT_NEAR(dry.restraining, 4.0 * dT_s + 2.0 * dT_b, 1e-12);
  EXPECT_NEAR(dry.uplift, (2.0 * dT_s + 2.0 * dT_s + 2.0 * dT_b) * std::sin(dry.wrap_angle), 1e-12);
  sheet.friction = 0.12;
  const RoundBeadForces wet = round_bead_forces(bead, sheet);
  // Arc by arc: bend, capstan, unbend (entry shoulder theta, bead 2 theta, exit shoulder theta).
  const double theta = wet.wrap_angle;
  double T = 0.0;
  double spans[2] = {0.0, 0.0};
  const double arcs[3][2] = {{dT_s, theta}, {dT_b, 2.0 * theta}, {dT_s, theta}};
  for (int k = 0; k < 3; ++k) {
    T = (T + arcs[k][0]) * std::exp(0.12 * arcs[k][1]) + arcs[k][0];
    if (k < 2) {
      spans[k] = T;
    }
  }
  EXPECT_NEAR(wet.restraining, T, 1e-12 * T);
  EXPECT_NEAR(wet.uplift, (spans[0] + spans[1]) * std::sin(theta), 1e-12 * T);
  EXPECT_GT(wet.restraining, dry.restraining);
  // Deeper beads wrap more and hold harder.
  double last = 0.0;
  for (const double depth : {0.5, 1.0, 2.0, 4.0}) {
    const RoundBeadForces f = round_bead_forces({4.0, 5.0, depth, 0.0}, sheet);
    EXPECT_GT(f.restraining, last);
    last = f.restraining;
  }
}

TEST(RoundDrawbead, EachBendHardensOnTheStrainOfTheBendsBeforeIt) {
  // Linear hardening sigma = s0 + H e: M_k = 2 int_0^{t/2} 2/sqrt(3) (s0 + H c_k z) z dz
  //   = 2/sqrt(3) (s0 t^2 / 4 + H c_k t^3 / 12), c_k = 2/sqrt(3) (sum_{j<k} 1/rho_j + 1/(2 rho_k)).
  const double s0 = 200.0, H = 900.0, t = 1.2, rho_s = 5.6, rho_b = 3.6;
  const RoundBeadSheet sheet{
      .thickness = t, .flow_stress = [&](double e) { return s0 + H * e; }, .friction = 0.0};
  const double rho[6] = {rho_s, rho_s, rho_b, rho_b, rho_s, rho_s};
  const double g = 2.0 / std::sqrt(3.0);
  double before = 0.0;
  double moments[6];
  for (int k = 0; k < 6; ++k) {
    const double c = g * (before + 0.5 / rho[k]);
    const double expected = g * (s0 * t * t / 4.0 + H * c * t * t * t / 12.0);
    moments[k] = round_bead_bend_moment(sheet, rho_s, rho_b, k);
    EXPECT_NEAR(moments[k], expected, 1e-12 * expected) << k;
    before += 1.0 / rho[k];
  }
  // The frictionless tension is the six steps' sum.
  const RoundBeadForces f = round_bead_forces({3.0, 5.0, 2.0, 0.2}, sheet);
  double sum = 0.0;
  for (int k = 0; k < 6; ++k) {
    sum += moments[k] / rho[k];
  }
  EXPECT_NEAR(f.restraining, sum, 1e-12 * sum);
}

TEST(RoundDrawbead, RefusesWhatNoBeadHas) {
  const RoundBeadSheet sheet{.thickness = 1.0, .flow_stress = constant(300.0), .friction = 0.1};
  EXPECT_THROW(round_bead_forces({0.0, 5.0, 3.0, 0.0}, sheet), InputError);
  EXPECT_THROW(round_bead_forces({4.0, -5.0, 3.0, 0.0}, sheet), InputError);
  EXPECT_THROW(round_bead_forces({4.0, 5.0, -1.0, 0.0}, sheet), InputError);
  EXPECT_THROW(round_bead_forces({4.0, 5.0, 3.0, NAN}, sheet), InputError);
  EXPECT_THROW(round_bead_forces({4.0, 5.0, 3.0, 0.0}, {1.0, constant(0.0), 0.1}), InputError);
  EXPECT_THROW(round_bead_forces({4.0, 5.0, 3.0, 0.0}, {1.0, constant(300.0), -0.1}), InputError);
  EXPECT_THROW(round_bead_forces({4.0, 5.0, 3.0, 0.0}, {1.0, nullptr, 0.1}), InputError);
}

// ---- the line model ------------------------------------------------------------------------

// A flat sheet of nodes 1 mm apart, x in [-x_half, x_half], y in [-y_half, y_half], its
// mid-surface at z = -h (the tool's face at z = 0, the sheet under it), and a bead line along y
// on the tool's face.
struct Sheet {
  Matrix3X x;
  Matrix3X v;
  VectorX half_thickness;
  DrawbeadLine line;
  DrawbeadState state;
  Matrix3X f;

  Sheet(int x_half, int y_half, double y_line_half, double h = 0.5) {
    const int nx = 2 * x_half + 1;
    const int ny = 2 * y_half + 1;
    x.resize(3, nx * ny);
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        x.col(j * nx + i) = Vec3(i - x_half, j - y_half, -h);
      }
    }
    v = Matrix3X::Zero(3, x.cols());
    half_thickness = VectorX::Constant(x.cols(), h);
    f = Matrix3X::Zero(3, x.cols());
    line.name = "bead";
    line.points = {Vec3(0.0, -y_line_half, 0.0), Vec3(0.0, y_line_half, 0.0)};
    line.normals = {Vec3::UnitZ(), Vec3::UnitZ()};
    line.width = 4.0;  // 4 node spacings: the window's sum is exact
    line.height = 2.0;
    line.closure = {0.0, 1.0};
    line.restraining = {0.0, 60.0};  // N/mm
    line.uplift = {0.0, 25.0};       // N/mm
    line.stiffness = VectorX::Constant(x.cols(), 1e6);
    // Tributary areas of the grid: 1 mm^2 inside, halved on an edge, quartered at a corner.
    line.area = VectorX::Ones(x.cols());
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        line.area[j * nx + i] =
            (i == 0 || i == nx - 1 ? 0.5 : 1.0) * (j == 0 || j == ny - 1 ? 0.5 : 1.0);
      }
    }
    line.start_half_thickness = half_thickness;
    line.set_box(2.0 * h);
  }

  // One call with every node moving at velocity u (mm/s) over dt (s), after moving them.
  DrawbeadResult step(const Vec3& u, double dt) {
    for (Eigen::Index i = 0; i < x.cols(); ++i) {
      x.col(i) += dt * u;
      v.col(i) = u;
    }
    f.setZero();
    const ContactKinematics kin{.x = x,
                                .v = v,
                                .half_thickness = half_thickness,
                                .tool_displacement = Vec3::Zero(),
                                .tool_displacement_increment = Vec3::Zero(),
                                .dt = dt};
    return compute_drawbead_forces(line, state, kin, f);
  }
};

TEST(DrawbeadLine, SlidingSheetFeelsTheForcePerLengthTimesTheLengthItCovers) {
  // The line runs beyond the sheet (y in [-5, 5], line [-20, 20]): it covers 10 mm of line.
  Sheet sheet(12, 5, 20.0);
  for (int k = 0; k < 40; ++k) {
    const DrawbeadResult r = sheet.step(Vec3(100.0, 0.0, 0.0), 1e-4);  // 0.01 mm per step
    const Vec3 on_sheet = sheet.f.rowwise().sum();
    // Every node in the band slides (k du = 1e4 N beats every limit): the limits' sum.
    EXPECT_NEAR(on_sheet.x(), -60.0 * 10.0, 1e-9) << k;
    EXPECT_NEAR(on_sheet.z(), -25.0 * 10.0, 1e-9) << k;  // away from the tool, which is above
    EXPECT_NEAR(on_sheet.y(), 0.0, 1e-9);
    EXPECT_NEAR((r.force_on_tool + on_sheet).norm(), 0.0, 1e-9);
    EXPECT_EQ(r.sliding_nodes, r.nodes_in_bead);
    int in_band = 0;  // |s| < w / 2 (at |s| = w / 2 the window is 0 and the node is off)
    for (Eigen::Index i = 0; i < sheet.x.cols(); ++i) {
      in_band += std::abs(sheet.x(0, i)) < 2.0 ? 1 : 0;
    }
    EXPECT_EQ(r.nodes_in_bead, in_band);
    if (k > 0) {
      // Steady sliding: the slip work is the force times the distance, less the springs' change.
      EXPECT_NEAR(r.work, 600.0 * 0.01, 600.0 * 0.01 * 1e-2) << k;
    }
  }
}

TEST(DrawbeadLine, ClosureFollowsTheGapAndNothingActsBeyondTheEnds) {
  // Line ends midway between node rows (y = +-2.5): 5 rows of 1 mm, 5 mm of line covered.
  Sheet sheet(12, 5, 2.5);
  sheet.step(Vec3(50.0, 0.0, 0.0), 1e-4);
  EXPECT_NEAR(sheet.f.row(0).sum(), -60.0 * 5.0, 1e-9);
  // The sheet half a bead height below contact: closure 0.5, half the force and uplift.
  sheet.x.row(2).array() -= 1.0;
  sheet.step(Vec3(50.0, 0.0, 0.0), 1e-4);
  EXPECT_NEAR(sheet.f.row(0).sum(), -30.0 * 5.0, 1e-9);
  EXPECT_NEAR(sheet.f.row(2).sum(), -12.5 * 5.0, 1e-9);
  // A bead height and more away: nothing, and the springs reset.
  sheet.x.row(2).array() -= 1.5;
  const DrawbeadResult r = sheet.step(Vec3(50.0, 0.0, 0.0), 1e-4);
  EXPECT_EQ(r.nodes_in_bead, 0);
  EXPECT_EQ(sheet.f.norm(), 0.0);
  EXPECT_EQ(sheet.state.restraint.norm(), 0.0);
}

TEST(DrawbeadLine, LockingBeadHoldsBySpringsWithNoLimit) {
  Sheet sheet(12, 5, 20.0);
  sheet.line.locking = true;
  sheet.step(Vec3::Zero(), 0.0);
  const double pull = 0.002;  // mm per step, 10 steps
  for (int k = 0; k < 10; ++k) {
    sheet.step(Vec3(pull / 1e-4, 0.0, 0.0), 1e-4);
  }
  // Every node of the band stretched its spring by 0.02 mm: k x 0.02 = 2e4 N each, far beyond
  // what a limited bead would give (60 N/mm x 1 mm x phi).
  for (Eigen::Index i = 0; i < sheet.x.cols(); ++i) {
    const double s = sheet.x(0, i);
    if (std::abs(s) < 2.0 - 1e-9) {
      EXPECT_NEAR(sheet.f(0, i), -1e6 * 10 * pull, 1e-6) << i;
    }
  }
}

TEST(DrawbeadLine, SameBitsOnOneAndTwoThreads) {
  const auto run = [](int threads) {
    omp_set_num_threads(threads);
    Sheet sheet(30, 40, 50.0);  // 61 x 81 nodes: several blocks
    for (int k = 0; k < 5; ++k) {
      sheet.step(Vec3(80.0, 3.0, 0.0), 1e-4);
    }
    return sheet.f;
  };
  const Matrix3X one = run(1);
  const Matrix3X two = run(2);
  omp_set_num_threads(1);
  EXPECT_EQ((one - two).cwiseAbs().maxCoeff(), 0.0);
}

TEST(DrawbeadLine, TurnedToolTurnsTheForces) {
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  Sheet plain(12, 5, 20.0);
  Sheet turned(12, 5, 20.0);
  for (Eigen::Index i = 0; i < turned.x.cols(); ++i) {
    turned.x.col(i) = R * turned.x.col(i);
  }
  for (int k = 0; k < 3; ++k) {
    plain.step(Vec3(100.0, 0.0, 0.0), 1e-4);
    for (Eigen::Index i = 0; i < turned.x.cols(); ++i) {
      turned.x.col(i) += 1e-4 * R * Vec3(100.0, 0.0, 0.0);
      turned.v.col(i) = R * Vec3(100.0, 0.0, 0.0);
    }
    turned.f.setZero();
    const ContactKinematics kin{.x = turned.x,
                                .v = turned.v,
                                .half_thickness = turned.half_thickness,
                                .tool_displacement = Vec3::Zero(),
                                .tool_displacement_increment = Vec3::Zero(),
                                .dt = 1e-4,
                                .tool_rotation = R,
                                .tool_rotation_previous = R};
    const DrawbeadResult r = compute_drawbead_forces(turned.line, turned.state, kin, turned.f);
    EXPECT_NEAR((turned.f - R * plain.f).cwiseAbs().maxCoeff(), 0.0, 1e-9);
    // The reaction's moment about the origin: that of the forces at the nodes.
    Vec3 moment = Vec3::Zero();
    for (Eigen::Index i = 0; i < turned.x.cols(); ++i) {
      moment += turned.x.col(i).cross(-turned.f.col(i));
    }
    EXPECT_NEAR((r.moment_on_tool - moment).norm(), 0.0, 1e-8);
  }
}

TEST(DrawbeadLine, CurveIsLinearBetweenItsPointsAndFlatBeyond) {
  DrawbeadLine line;
  line.closure = {0.2, 0.6, 1.0};
  line.restraining = {10.0, 50.0, 70.0};
  EXPECT_DOUBLE_EQ(line.restraining_at(0.0), 10.0);
  EXPECT_DOUBLE_EQ(line.restraining_at(0.4), 30.0);
  EXPECT_DOUBLE_EQ(line.restraining_at(0.8), 60.0);
  EXPECT_DOUBLE_EQ(line.restraining_at(1.0), 70.0);
  EXPECT_EQ(line.uplift_at(0.5), 0.0);  // none given
}

}  // namespace
}  // namespace sf
