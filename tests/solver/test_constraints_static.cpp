// General constraints in static analyses ([analysis] type = "static"), against closed forms:
// - a strip simply supported by diaphragm ends under a uniform pressure: the Timoshenko beam's
//   midspan deflection 5 q L^4 / (384 E I) + q L^2 / (8 k G A) (Timoshenko & Gere, Mechanics of
//   Materials, 1972; shear factor k = 5/6), with the element's own known error (below);
// - the same strip turned 30 degrees about z, its diaphragms given by a normal or by a hold in
//   turned axes: the same answer to round-off;
// - a cantilever with a prescribed tip deflection d (linear): the reaction d / (L^3 / (3 E I)
//   (1 - 1/(4 n^2)) + L / (k G A)), 3 E I d / L^3 within 0.04 %;
// - the same to a large deflection (nonlinear): the reaction of the exact elastica (Bisshopp &
//   Drucker 1945, Mattiasson 1981: alpha = P L^2 / (E I) = 2 at a tip deflection of 0.49346 L);
// - a prescribed tip rotation: a uniform moment E I theta / L (linear), and rolled up to a
//   quarter circle (nonlinear), the circular elastica;
// - a prescribed motion on a strip held by nothing else moves it rigidly; a load the automatic
//   rigid-body holds would carry is an error.
//
// The element's known error. Along a strip one element wide the Belytschko-Lin-Tsay quad with
// one-point integration is the linear Timoshenko beam element with reduced integration: per
// element of length h, curvature (theta2 - theta1) / h and shear strain (w2 - w1) / h + (theta1 +
// theta2) / 2. One element clamped at node 1 under a tip force P: minimising
// E I theta2^2 / (2 h) + k G A h gamma^2 / 2 - P w2 gives gamma = P / (k G A), theta2 = -P h^2 /
// (2 E I), w2 = P h^3 / (4 E I) + P h / (k G A), against the exact P h^3 / (3 E I) + P h /
// (k G A): the element is the exact (Timoshenko) element with the shear flexibility 1 / (k G A)
// lowered by h^2 / (12 E I), and it gives nodal values exact for that beam under nodal loads. So:
// - a cantilever, tip force: P L^3 / (3 E I) (1 - 1/(4 n^2)) + P L / (k G A) (n elements; the
//   measured ratio of StaticAnalysis.LinearCantilever..., 0.999375 of the Timoshenko value at
//   n = 20, is exactly 1 - 1/(4 n^2));
// - a simply supported beam under a uniform load q, shared equally by the nodes (lumped): at
//   midspan -(q L^2 / 8) h^2 / (12 E I) from the element, and -q h^2 L^2 / (96 E I) from the
//   lumping (the nodal loads' moment is the uniform load's at the nodes and linear between them:
//   q (x - x_i)(x_i+1 - x) / 2 less, against the unit-load moment's area L^2 / 8), each -0.8 /
//   n^2 of the bending deflection: 5 q L^4 / (384 E I) (1 - 1.6 / n^2) + q L^2 / (8 k G A).
// n = 20 here: -0.0625 % and -0.4 %.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "core/errors.hpp"
#include "model/build_model.hpp"
#include "solver/static_driver.hpp"

namespace {

namespace fs = std::filesystem;

constexpr double kLength = 100.0;    // mm, tests/data/strip.geo: 20 x 1 quads
constexpr double kWidth = 10.0;      // mm
constexpr double kThickness = 2.0;   // mm
constexpr double kYoung = 210000.0;  // MPa, nu = 0 (a beam: no anticlastic coupling)
constexpr double kInertia = kWidth * kThickness * kThickness * kThickness / 12.0;   // mm^4
constexpr double kShearStiffness = 5.0 / 6.0 * 0.5 * kYoung * kWidth * kThickness;  // k G A, N
constexpr double kElements = 20.0;

// The strip of tests/data/strip.geo, or (turned) the same turned by 30 degrees about z.
std::string strip_geo(bool turned) {
  std::ifstream in(fs::path(SF_TEST_DATA_DIR) / "strip.geo");
  std::string geo((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (turned) {
    geo += "Rotate {{0, 0, 1}, {0, 0, 0}, Pi / 6} { Surface{1}; }\n";
  }
  return geo;
}

// A static case on the strip: `extra` holds the boundaries, loads, prescriptions, [analysis] and
// [implicit] tables; `formulation` the blank's element.
sf::Model build_case(const std::string& name, const std::string& extra, bool turned = false,
                     const std::string& formulation = "assumed_strain") {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / "constraints_static" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "strip.geo") << strip_geo(turned);
  std::ofstream(folder / "case.toml") << R"([blank]
mesh = "strip.geo"
thickness = 2.0
integration_points = 5
material = "steel"
formulation = ")" + formulation + R"("
[materials.steel]
type = "elastic"
density = 7.85e-9
young = 210000.0
poisson = 0.0
[control]
end_time = 1.0
)" + extra;
  return sf::build_model(sf::read_case(folder / "case.toml"));
}

sf::SolutionState run(sf::Model& model, sf::RunSummary* summary = nullptr) {
  sf::RunOptions options;
  options.write_results = false;
  sf::SolutionState s;
  const sf::RunSummary r = sf::run_static(model, options, &s);
  if (summary) {
    *summary = r;
  }
  return s;
}

// The mean displacement component of the nodes at x = x0 along the unturned strip (mm).
double mean_at(const sf::Model& model, const sf::SolutionState& s, double x0, int component) {
  double sum = 0.0;
  int count = 0;
  for (Eigen::Index i = 0; i < s.x.cols(); ++i) {
    const sf::Vec3 x = model.blank.mesh.nodes.col(i);
    if (std::abs(x.x() - x0) < 1e-9) {
      sum += s.x(component, i) - x(component);
      ++count;
    }
  }
  EXPECT_GT(count, 0);
  return sum / count;
}

const sf::ConstraintReaction& reaction(const sf::RunSummary& summary, const std::string& entry) {
  for (const sf::ConstraintReaction& r : summary.reactions) {
    if (r.entry == entry) {
      return r;
    }
  }
  ADD_FAILURE() << "no reaction for " << entry;
  static const sf::ConstraintReaction none;
  return none;
}

const char* const kDiaphragms = R"(
[[boundary]]
group = "clamp"
type = "diaphragm"
axis = "x"
[[boundary]]
group = "tip"
type = "diaphragm"
axis = "x"
[[load]]
group = "blank"
type = "pressure"
pressure = 0.01
[analysis]
type = "static"
geometry = "linear"
)";

constexpr double kPressure = 0.01;  // MPa: q = 0.1 N/mm on the 10 mm strip

double simply_supported_midspan() {
  const double q = kPressure * kWidth;  // N/mm
  const double bending = 5.0 * q * std::pow(kLength, 4) / (384.0 * kYoung * kInertia);
  return bending * (1.0 - 1.6 / (kElements * kElements)) +
         q * kLength * kLength / (8.0 * kShearStiffness);
}

// The reactions balance the load to `reaction_tolerance` (relative).
void check_diaphragm_beam(const std::string& formulation, double reaction_tolerance) {
  SCOPED_TRACE(formulation);
  sf::Model model = build_case("diaphragm_" + formulation, kDiaphragms, false, formulation);
  // The diaphragms hold uy, uz of the end nodes (no frames); only the translation along x is
  // left free, and held automatically at one node.
  EXPECT_EQ(model.constraints.frames.count(), 0);
  EXPECT_EQ(model.constraints.mask[model.blank.group("tip").nodes[0]], 2u | 4u);
  sf::RunSummary summary;
  const sf::SolutionState s = run(model, &summary);
  ASSERT_TRUE(summary.static_step.has_value());
  EXPECT_EQ(summary.static_step->free_modes, std::vector<std::string>{"translation along x"});
  const double w = -mean_at(model, s, 50.0, 2);
  const double expected = simply_supported_midspan();
  std::printf(
      "midspan deflection %.8f mm, beam %.8f mm (%+.2e); bending alone %+.2e\n", w, expected,
      w / expected - 1.0,
      w / (5.0 * kPressure * kWidth * std::pow(kLength, 4) / (384.0 * kYoung * kInertia)) - 1.0);
  // Tolerance 1e-5: the beam with the element's own error (header) is exact for the nodal values
  // up to the solver's round-off; without the element's error (-0.4 %) it would fail.
  EXPECT_NEAR(w / expected, 1.0, 1e-5);
  // Each diaphragm carries half the load, q L / 2 = 5 N, upward (+z) on the strip.
  const double half = 0.5 * kPressure * kWidth * kLength;
  EXPECT_NEAR(reaction(summary, "boundary[0]").force.z(), half, reaction_tolerance * half);
  EXPECT_NEAR(reaction(summary, "boundary[1]").force.z(), half, reaction_tolerance * half);
  EXPECT_NEAR(reaction(summary, "boundary[0]").force.x(), 0.0, 1e-12);  // ux is free
}

TEST(ConstraintsStatic, DiaphragmEndsGiveTheSimplySupportedBeam) {
  // Belytschko-Tsay: forces linear in the increment, the finite-difference tangent exact: the
  // reactions balance the load to round-off.
  check_diaphragm_beam("belytschko_tsay", 1e-9);
  // Assumed strain: the small-strain forces keep a third-order term (docs/static-analysis.md),
  // which the central-difference tangent (step 1e-6 of the length) turns into an error of
  // order step^2: 1.5e-9 of the load measured, 1.5e-7 with 10 times the step; 1e-8 bounds it.
  check_diaphragm_beam("assumed_strain", 1e-8);
}

// The diaphragms of the turned strip, given by their normal, or as holds of uy, uz in turned axes.
std::string turned_diaphragms(bool as_hold) {
  const double c = std::cos(std::numbers::pi / 6.0), s = std::sin(std::numbers::pi / 6.0);
  std::string text;
  for (const char* group : {"clamp", "tip"}) {
    text += as_hold ? fmt::format(
                          "[[boundary]]\ngroup = \"{}\"\nhold = [\"uy\", \"uz\"]\n"
                          "axes = [[{:.17g}, {:.17g}, 0.0], [{:.17g}, {:.17g}, 0.0]]\n",
                          group, c, s, -s, c)
                    : fmt::format(
                          "[[boundary]]\ngroup = \"{}\"\ntype = \"diaphragm\"\n"
                          "normal = [{:.17g}, {:.17g}, 0.0]\n",
                          group, c, s);
  }
  return text + R"([[load]]
group = "blank"
type = "pressure"
pressure = 0.01
[analysis]
type = "static"
geometry = "linear"
)";
}

TEST(ConstraintsStatic, TurnedStripWithDiaphragmsInItsAxesGivesTheSameAnswer) {
  sf::Model straight = build_case("diaphragm_straight", kDiaphragms);
  sf::RunSummary straight_summary;
  const sf::SolutionState s0 = run(straight, &straight_summary);
  const sf::Vec3 straight_force = reaction(straight_summary, "boundary[1]").force;
  const double c = std::cos(std::numbers::pi / 6.0), s = std::sin(std::numbers::pi / 6.0);
  const sf::Mat3 turn = (sf::Mat3() << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0).finished();
  for (const bool as_hold : {false, true}) {
    SCOPED_TRACE(as_hold ? "hold in turned axes" : "diaphragm by its normal");
    sf::Model turned = build_case(as_hold ? "diaphragm_turned_hold" : "diaphragm_turned_normal",
                                  turned_diaphragms(as_hold), true);
    ASSERT_EQ(turned.blank.mesh.nodes.cols(), straight.blank.mesh.nodes.cols());
    EXPECT_EQ(turned.constraints.frames.count(), 4);  // the four end nodes
    sf::RunSummary summary;
    const sf::SolutionState s1 = run(turned, &summary);
    // Node by node (the same meshing, turned): the displacement turned back equals the straight
    // strip's. Round-off: the turned coordinates differ in the last bits; measured below.
    double worst = 0.0, largest = 0.0;
    for (Eigen::Index i = 0; i < s0.x.cols(); ++i) {
      const sf::Vec3 x0 = straight.blank.mesh.nodes.col(i);
      // gmsh turns the geometry, then meshes it: the nodes agree to its round-off (1.2e-10 mm).
      ASSERT_NEAR((turned.blank.mesh.nodes.col(i) - turn * x0).norm(), 0.0, 1e-9) << i;
      const sf::Vec3 u0 = s0.x.col(i) - x0;
      const sf::Vec3 u1 = turn.transpose() * (s1.x.col(i) - turned.blank.mesh.nodes.col(i));
      worst = std::max(worst, (u1 - u0).norm());
      largest = std::max(largest, u0.norm());
    }
    std::printf("turned strip: largest difference %.2e of the largest displacement %.4e mm\n",
                worst / largest, largest);
    EXPECT_LT(worst, 1e-10 * largest);
    // The reactions too: turned back, the straight strip's (q L / 2 = 5 N upward) to round-off.
    const sf::ConstraintReaction& r = reaction(summary, "boundary[1]");
    EXPECT_NEAR((turn.transpose() * r.force - straight_force).norm(), 0.0, 1e-9 * 5.0);
    ASSERT_TRUE(r.axes.has_value());
  }
}

// The cantilever's tip deflection d prescribed (both tip nodes, uz; the rotations free).
const char* const kClamp = R"(
[[boundary]]
group = "clamp"
type = "fixed"
)";

TEST(ConstraintsStatic, PrescribedTipDeflectionReactionIsTheBeamStiffness) {
  const double d = 1.5;  // mm, a constant value: ramped from 0 over the pseudo-time
  sf::Model model = build_case("prescribed_tip_linear", std::string(kClamp) + fmt::format(R"(
[[prescribed_motion]]
group = "tip"
dof = "uz"
value = {}
[analysis]
type = "static"
geometry = "linear"
)",
                                                                                          d));
  sf::RunSummary summary;
  const sf::SolutionState s = run(model, &summary);
  for (const int node : model.blank.group("tip").nodes) {
    EXPECT_NEAR(s.x(2, node) - model.blank.mesh.nodes(2, node), d, 1e-12);
  }
  const double compliance =
      std::pow(kLength, 3) / (3.0 * kYoung * kInertia) * (1.0 - 0.25 / (kElements * kElements)) +
      kLength / kShearStiffness;
  const double expected = d / compliance;
  const double euler_bernoulli = 3.0 * kYoung * kInertia * d / std::pow(kLength, 3);
  const sf::ConstraintReaction& r = reaction(summary, "prescribed_motion[0]");
  ASSERT_TRUE(r.along.has_value());
  std::printf(
      "reaction %.8f N; beam with the element's error %.8f N (%+.2e); 3 E I d / L^3 = %.8f N "
      "(%+.2e)\n",
      *r.along, expected, *r.along / expected - 1.0, euler_bernoulli,
      *r.along / euler_bernoulli - 1.0);
  // Tolerance 1e-6: the element's known error is in `expected` (header), exact for the nodal
  // values; 3 E I d / L^3 is 0.04 % off it (the element 0.0625 % stiffer, shear 0.024 % softer),
  // which the tolerance separates.
  EXPECT_NEAR(*r.along / expected, 1.0, 1e-6);
  EXPECT_NEAR(*r.along / euler_bernoulli, 1.0, 5e-4);
  // The clamp carries the opposite force and the moment R L about y (the tip force's moment
  // about the clamp is (L, 0, 0) x (0, 0, R) = -R L).
  const sf::ConstraintReaction& clamp = reaction(summary, "boundary[0]");
  // To 1e-6: the solve used the finite-difference tangent, which predicts the forces to about
  // 1e-7 (docs/static-analysis.md), and the reactions are the linear forces of the solution.
  EXPECT_NEAR(clamp.force.z(), -*r.along, 1e-6 * *r.along);
  EXPECT_NEAR(clamp.moment.y(), *r.along * kLength, 1e-6 * *r.along * kLength);
  // The work of the prescribed motion is the strain energy: R d / 2 (linear, trapezoidal: exact).
  ASSERT_TRUE(summary.static_step.has_value());
  EXPECT_NEAR(summary.static_step->report.prescribed_work, 0.5 * *r.along * d, 1e-9 * *r.along * d);
}

// Exact inextensible elastica of a cantilever under a dead tip force (Bisshopp & Drucker 1945):
// the tip deflection / L for alpha = P L^2 / (E I), with p = sqrt((1 + sin phi0) / 2), sin phi1 =
// 1 / (p sqrt 2): sqrt(alpha) = K(p) - F(p, phi1), deflection / L = 1 - 2 (E(p) - E(p, phi1)) /
// sqrt(alpha) (as test_cantilever.cpp, which checks it against Mattiasson's table).
double elastica_deflection(double alpha) {
  auto residual = [alpha](double phi0) {
    const double p = std::sqrt(0.5 * (1.0 + std::sin(phi0)));
    return std::comp_ellint_1(p) - std::ellint_1(p, std::asin(1.0 / (p * std::sqrt(2.0)))) -
           std::sqrt(alpha);
  };
  double lo = 1e-12, hi = 0.5 * std::numbers::pi - 1e-12;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (residual(mid) < 0.0 ? lo : hi) = mid;
  }
  const double p = std::sqrt(0.5 * (1.0 + std::sin(0.5 * (lo + hi))));
  const double phi1 = std::asin(1.0 / (p * std::sqrt(2.0)));
  return 1.0 - 2.0 * (std::comp_ellint_2(p) - std::ellint_2(p, phi1)) / std::sqrt(alpha);
}

TEST(ConstraintsStatic, LargePrescribedTipDeflectionReactionFollowsTheElastica) {
  // The tip held at a deflection of 0.49346 L, free along x and in rotation: the reaction is a
  // vertical dead force, alpha = 2 (Mattiasson's table). Every node in the plane of bending
  // (symmetry about y), as the static elastica tests.
  const double alpha = 2.0;
  const double d = elastica_deflection(alpha) * kLength;
  ASSERT_NEAR(d / kLength, 0.49346, 1e-5);
  sf::Model model = build_case("prescribed_tip_nonlinear", std::string(kClamp) + fmt::format(R"(
[[boundary]]
group = "blank"
type = "symmetry"
axis = "y"
[[prescribed_motion]]
group = "tip"
dof = "uz"
curve = [[0.0, 0.0], [1.0, {:.17g}]]
[analysis]
type = "static"
[implicit]
increments = 20
force_tolerance = 1e-8
)",
                                                                                             d));
  sf::RunSummary summary;
  const sf::SolutionState s = run(model, &summary);
  const double expected = alpha * kYoung * kInertia / (kLength * kLength);  // N
  const sf::ConstraintReaction& r = reaction(summary, "prescribed_motion[0]");
  ASSERT_TRUE(r.along.has_value());
  const double x_tip = kLength + mean_at(model, s, kLength, 0);
  const double x_exact = (1.0 - 0.16064) * kLength;  // Mattiasson (1981), alpha = 2
  std::printf("reaction %.6f N, elastica %.6f N (%+.2e); tip x %.4f mm (elastica %.4f)\n", *r.along,
              expected, *r.along / expected - 1.0, x_tip, x_exact);
  // Tolerance 0.5 %: the strip's tip deflection under a given force is within 3e-4 L of the
  // elastica with 20 elements (test_cantilever.cpp), and near alpha = 2 the deflection grows only
  // about half as fast as the force (relative), which doubles the error on the force; the
  // element's 1/(4 n^2) adds 0.06 %.
  EXPECT_NEAR(*r.along / expected, 1.0, 5e-3);
  // The tip, free along x, draws in as the elastica's: 1e-3 L (test_cantilever.cpp's tolerance
  // for the force-loaded strip).
  EXPECT_NEAR(x_tip, x_exact, 1e-3 * kLength);
}

TEST(ConstraintsStatic, PrescribedTipRotationGivesTheUniformMoment) {
  // theta about -y lifts the tip (+z); the moment E I theta / L is uniform along the strip, which
  // the element reproduces exactly (the bending patch test): to round-off. The tip deflection of
  // the arc, theta L / 2 (small rotation).
  const double theta = 0.01;  // rad
  sf::Model model =
      build_case("prescribed_rotation_linear", std::string(kClamp) + fmt::format(R"(
[[prescribed_motion]]
group = "tip"
dof = "ry"
value = {}
[analysis]
type = "static"
geometry = "linear"
)",
                                                                                 -theta));
  sf::RunSummary summary;
  const sf::SolutionState s = run(model, &summary);
  const double expected = -kYoung * kInertia * theta / kLength;  // N mm about y
  const sf::ConstraintReaction& r = reaction(summary, "prescribed_motion[0]");
  ASSERT_TRUE(r.along.has_value());
  const double w = mean_at(model, s, kLength, 2);
  std::printf("moment %.8f N mm (E I theta / L %.8f, %+.2e), tip %.8f mm (theta L / 2 %.8f)\n",
              *r.along, expected, *r.along / expected - 1.0, w, 0.5 * theta * kLength);
  EXPECT_NEAR(*r.along / expected, 1.0, 1e-8);
  EXPECT_NEAR(w, 0.5 * theta * kLength, 1e-8 * theta * kLength);
  EXPECT_NEAR(r.force.norm(), 0.0, 1e-8 * std::abs(expected) / kLength);  // no force: pure moment
}

TEST(ConstraintsStatic, PrescribedTipRotationRollsTheStripIntoTheCircularElastica) {
  // A quarter circle: theta = pi / 2 prescribed about -y in 16 increments. Exact: the tip at
  // (L / theta) (sin theta, 1 - cos theta), the moment E I theta / L.
  const double theta = 0.5 * std::numbers::pi;
  sf::Model model =
      build_case("prescribed_rotation_nonlinear", std::string(kClamp) + fmt::format(R"(
[[boundary]]
group = "blank"
type = "symmetry"
axis = "y"
[[prescribed_motion]]
group = "tip"
dof = "ry"
curve = [[0.0, 0.0], [1.0, {:.17g}]]
[analysis]
type = "static"
[implicit]
increments = 16
force_tolerance = 1e-8
)",
                                                                                    -theta));
  sf::RunSummary summary;
  const sf::SolutionState s = run(model, &summary);
  const double radius = kLength / theta;
  const double x_tip = kLength + mean_at(model, s, kLength, 0);
  const double z_tip = mean_at(model, s, kLength, 2);
  const double expected = -kYoung * kInertia * theta / kLength;
  const sf::ConstraintReaction& r = reaction(summary, "prescribed_motion[0]");
  ASSERT_TRUE(r.along.has_value());
  std::printf("tip (%.4f, %.4f) mm, arc (%.4f, %.4f); moment %.4f N mm (%.4f, %+.2e)\n", x_tip,
              z_tip, radius * std::sin(theta), radius * (1.0 - std::cos(theta)), *r.along, expected,
              *r.along / expected - 1.0);
  // As StaticAnalysis.NonlinearEndMomentRollsTheStripIntoTheElasticaArc: 2e-3 L for the tip (the
  // faceting of the arc by 20 flat elements, 2.6e-4), and for the moment the increments' error
  // (0.9 % of the curvature at 22.5 degrees per increment, 16 times less at 5.6: 0.06 %), 0.3 %.
  EXPECT_NEAR(x_tip, radius * std::sin(theta), 2e-3 * kLength);
  EXPECT_NEAR(z_tip, radius * (1.0 - std::cos(theta)), 2e-3 * kLength);
  EXPECT_NEAR(*r.along / expected, 1.0, 3e-3);
}

TEST(ConstraintsStatic, PrescriptionAloneMovesAFreeStripRigidly) {
  // Nothing held; the tip's twist rx = 0.01 rad prescribed. The prescribed dofs count as held, the
  // automatic holds remove the other five modes, and they carry nothing: the strip turns rigidly
  // about an axis along x (any rigid motion meeting the prescription and the holds is one), stress
  // free, every reaction zero. Exact: uz = theta (y - y_axis) at every node.
  // Belytschko-Tsay, whose linear analysis is exactly linear (the assumed-strain one keeps a
  // third-order term, 1.7e-6 N mm of moment here: docs/static-analysis.md).
  const double theta = 0.01;
  sf::Model model = build_case("prescribed_free_body",
                               fmt::format(R"(
[[prescribed_motion]]
group = "tip"
dof = "rx"
value = {}
[analysis]
type = "static"
geometry = "linear"
)",
                                           theta),
                               false, "belytschko_tsay");
  sf::RunSummary summary;
  const sf::SolutionState s = run(model, &summary);
  ASSERT_TRUE(summary.static_step.has_value());
  EXPECT_EQ(summary.static_step->added_constraints.size(), 5u);
  // The twist of every cross-section is theta: uz(y = 10) - uz(y = 0) = 10 theta at each x.
  for (Eigen::Index i = 0; i < s.x.cols(); ++i) {
    const sf::Vec3 x0 = model.blank.mesh.nodes.col(i);
    if (x0.y() > 5.0) {
      continue;
    }
    for (Eigen::Index j = 0; j < s.x.cols(); ++j) {
      const sf::Vec3 x1 = model.blank.mesh.nodes.col(j);
      if (std::abs(x1.x() - x0.x()) < 1e-9 && x1.y() > 5.0) {
        EXPECT_NEAR((s.x(2, j) - x1.z()) - (s.x(2, i) - x0.z()), kWidth * theta, 1e-9)
            << "x = " << x0.x();
      }
    }
  }
  const sf::ConstraintReaction& r = reaction(summary, "prescribed_motion[0]");
  EXPECT_LT(r.moment.norm(), 1e-6);
  EXPECT_LT(
      std::abs(*std::max_element(s.shell.sxx.begin(), s.shell.sxx.end(),
                                 [](double a, double b) { return std::abs(a) < std::abs(b); })),
      1e-6);
}

TEST(ConstraintsStatic, UnbalancedLoadOnTheAutomaticHoldsIsAnError) {
  // The diaphragm strip pulled along x: nothing holds ux but the automatic hold, which would
  // carry the whole 10 N. No equilibrium without it: refused, naming the hold and the free mode.
  sf::Model model = build_case("unbalanced_axial", R"(
[[boundary]]
group = "clamp"
type = "diaphragm"
axis = "x"
[[boundary]]
group = "tip"
type = "diaphragm"
axis = "x"
[[load]]
group = "tip"
type = "force"
value = [5.0, 0.0, 0.0]
[analysis]
type = "static"
geometry = "linear"
)");
  try {
    run(model);
    FAIL() << "no error for a load the automatic holds carry";
  } catch (const sf::InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("automatic rigid-body holds"), std::string::npos) << message;
    EXPECT_NE(message.find("ux carries -10 N"), std::string::npos) << message;
    EXPECT_NE(message.find("(translation along x)"), std::string::npos) << message;
    EXPECT_NE(message.find("[[boundary]]"), std::string::npos) << message;
  }
}

}  // namespace
