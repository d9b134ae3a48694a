// Static analyses from the case file ([analysis] type = "static"), against closed forms:
// - a linear cantilever strip under a tip force: Timoshenko beam tip deflection
//   P L^3 / (3 E I) + P L / (k G A) (Mindlin shell, shear factor k = 5/6);
// - linear patch tests on distorted quadrilaterals: uniform membrane tension and uniform bending
//   reproduced exactly (to round-off) through the implicit path;
// - nonlinear: the same strip under an end moment rolls into a circular arc (the exact elastica,
//   REFERENCES.md "Analytic checks", grade B);
// - missing constraints give a clear error naming the free rigid-body modes, not a solution.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "core/errors.hpp"
#include "element/shell_output.hpp"
#include "model/build_model.hpp"
#include "solver/case_fixture.hpp"
#include "solver/static_driver.hpp"

namespace {

namespace fs = std::filesystem;

constexpr double kLength = 100.0;    // mm, tests/data/strip.geo
constexpr double kWidth = 10.0;      // mm
constexpr double kThickness = 2.0;   // mm
constexpr double kYoung = 210000.0;  // MPa
constexpr double kInertia = kWidth * kThickness * kThickness * kThickness / 12.0;  // mm^4

// A static case around a mesh in tests/data: `extra` holds the boundaries, loads, [analysis] and
// [implicit] tables.
sf::Model build_static_case(const std::string& name, const std::string& mesh, double poisson,
                            const std::string& extra, const std::string& blank_keys = "") {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "case.toml")
      << "[blank]\nmesh = \"" + (fs::path(SF_TEST_DATA_DIR) / mesh).string() +
             "\"\nthickness = 2.0\nintegration_points = 5\n"
             "material = \"steel\"\n" +
             blank_keys +
             "[materials.steel]\ntype = \"elastic\"\n"
             "density = 7.85e-9\nyoung = 210000.0\npoisson = " +
             std::to_string(poisson) + "\n[control]\nend_time = 1.0\n" + extra;
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

double mean_tip(const sf::Model& model, const sf::SolutionState& s, int component) {
  const auto& tip = model.blank.group("tip").nodes;
  double sum = 0.0;
  for (int node : tip) {
    sum += s.x(component, node) - model.blank.mesh.nodes(component, node);
  }
  return sum / static_cast<double>(tip.size());
}

// The strip clamped at x = 0 under a transverse tip force (N in total, half on each of the two
// tip nodes), linear analysis: the case's boundaries, loads and [analysis].
std::string linear_cantilever(double tip_force) {
  return fmt::format(R"(
[[boundary]]
group = "clamp"
type = "fixed"
[[load]]
group = "tip"
type = "force"
value = [0.0, 0.0, {}]
[analysis]
type = "static"
geometry = "linear"
)",
                     0.5 * tip_force);
}

TEST(StaticAnalysis, LinearCantileverMatchesTheBeamFormula) {
  const double force = 10.0;  // N in total, 5 N on each of the two tip nodes
  sf::Model model =
      build_static_case("static_cantilever_linear", "strip.geo", 0.0, linear_cantilever(force));
  sf::RunSummary summary;
  const sf::SolutionState s = run(model, &summary);
  const double bending = force * std::pow(kLength, 3) / (3.0 * kYoung * kInertia);
  const double shear = force * kLength / (5.0 / 6.0 * 0.5 * kYoung * kWidth * kThickness);
  const double w = mean_tip(model, s, 2);
  // 20 one-point elements along the strip: the constant-curvature element's tip deflection under
  // a linearly varying moment is PL^3/(3EI) (1 + 1/(4 n^2)) for reduced-integration Timoshenko
  // elements, +0.06 % at n = 20; 0.2 % covers it.
  EXPECT_NEAR(w / (bending + shear), 1.0, 2e-3) << "tip deflection " << w << " mm";
  ASSERT_TRUE(summary.static_step.has_value());
  EXPECT_EQ(summary.static_step->report.converged_increments, 1);
  EXPECT_EQ(summary.static_step->report.newton_iterations, 1);
  EXPECT_TRUE(summary.static_step->added_constraints.empty());  // the clamp holds everything
  // A stress-free linear tangent is symmetric: CHOLMOD takes it.
  EXPECT_EQ(summary.static_step->report.last_factorization.method,
            sf::FactorizationMethod::cholmod);
  EXPECT_GE(summary.static_step->report.last_factorization.fill_ratio, 1.0);
}

// The cantilever strip meshed in triangles (assumed-strain triangles), linear analysis under a
// tip force (N): the tip deflection (mm), the run's summary into *summary.
double linear_triangle_strip_tip(double tip_force, sf::RunSummary* summary_out = nullptr) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / "static_triangle_strip";
  fs::create_directories(folder);
  std::ifstream quads(fs::path(SF_TEST_DATA_DIR) / "strip.geo");
  std::ofstream triangles(folder / "strip_triangles.geo");
  for (std::string line; std::getline(quads, line);) {
    if (line.rfind("Recombine", 0) != 0) {
      triangles << line << "\n";
    }
  }
  triangles.close();
  sf::Model model =
      build_static_case("static_triangle_strip", (folder / "strip_triangles.geo").string(), 0.0,
                        linear_cantilever(tip_force), "element = \"as_meshed\"\n");
  EXPECT_GT(model.blank.part.triangles.cols(), 0);
  EXPECT_EQ(model.blank.part.quads.cols(), 0);
  sf::RunSummary summary;
  const sf::SolutionState s = run(model, &summary);
  EXPECT_TRUE(summary.static_step.has_value() &&
              summary.static_step->report.newton_iterations == 1);
  if (summary_out) {
    *summary_out = summary;
  }
  return mean_tip(model, s, 2);
}

// A linear analysis is linear in its load, u(2P) = 2 u(P), to the solver's round-off (2e-9
// relative), in one Newton iteration each.
TEST(StaticAnalysis, LinearAnalysisOfTrianglesIsLinearInTheLoad) {
  const double w1 = linear_triangle_strip_tip(10.0);
  const double w2 = linear_triangle_strip_tip(20.0);
  EXPECT_GT(w1, 0.0);
  EXPECT_NEAR(w2 / w1, 2.0, 2e-9) << "tip deflections " << w1 << " and " << w2 << " mm";
}

// The energy balance of a linear analysis at a finite rotation (the strip's tip turns 0.036 rad
// under 10 N): triangles as close as quads. Its evaluation about the committed state turns every
// corner's director back by half the rotation; when only the quads' were (until issue 34), the
// triangles' balance was -1.4e-4 against the quads' -3.7e-5 (now -6.4e-5). What remains, in both,
// grows with the rotation (the triangles' -1.5e-4 at 20 N): the internal work is the element
// pass's over the increment, second order in the rotation, against the linear solution's load
// work; the twisted beam's tiny rotations close to 2e-8 (below).
TEST(StaticAnalysis, LinearAnalysisBalanceOfTrianglesIsThatOfQuads) {
  sf::Model quads = build_static_case("static_cantilever_linear_balance", "strip.geo", 0.0,
                                      linear_cantilever(10.0));
  sf::RunSummary quad_summary, triangle_summary;
  run(quads, &quad_summary);
  linear_triangle_strip_tip(10.0, &triangle_summary);
  const double quad_error = quad_summary.energies.balance_error();
  const double triangle_error = triangle_summary.energies.balance_error();
  EXPECT_LT(std::abs(quad_error), 1e-4);
  EXPECT_LT(std::abs(triangle_error), 2.0 * std::abs(quad_error))
      << "triangles " << triangle_error << ", quads " << quad_error;
}

// The patch: left edge symmetric in x, bottom edge symmetric in y; consistent edge loads on the
// right edge (a quarter of the resultant at each corner, a half at the middle node).
std::string patch_loads(const std::string& type, double resultant, int component) {
  std::array<double, 3> corner{0.0, 0.0, 0.0};
  std::array<double, 3> mid{0.0, 0.0, 0.0};
  corner[static_cast<std::size_t>(component)] = 0.25 * resultant;
  mid[static_cast<std::size_t>(component)] = 0.5 * resultant;
  auto vec = [](const std::array<double, 3>& v) {
    return fmt::format("[{}, {}, {}]", v[0], v[1], v[2]);
  };
  return R"(
[[boundary]]
group = "left"
type = "symmetry"
axis = "x"
[[boundary]]
group = "bottom"
type = "symmetry"
axis = "y"
[[load]]
group = "right_corners"
type = ")" +
         type + R"("
value = )" +
         vec(corner) + R"(
[[load]]
group = "right_mid"
type = ")" +
         type + R"("
value = )" +
         vec(mid) + R"(
[analysis]
type = "static"
geometry = "linear"
)";
}

TEST(StaticAnalysis, LinearMembranePatchTestIsExact) {
  const double sigma = 50.0;                           // MPa
  const double resultant = sigma * kThickness * 10.0;  // N on the 10 mm edge
  sf::Model model = build_static_case("static_patch_membrane", "patch_distorted.geo", 0.3,
                                      patch_loads("force", resultant, 0));
  sf::RunSummary summary;
  const sf::SolutionState s = run(model, &summary);
  // One free rigid-body mode (translation along z) is held automatically.
  ASSERT_TRUE(summary.static_step.has_value());
  EXPECT_EQ(summary.static_step->added_constraints.size(), 1u);
  // A linear analysis refers its stresses to the undeformed geometry (as its frames do).
  sf::ShellStressOutput out;
  sf::compute_element_stress_output(model.blank.part, model.blank.mesh.nodes, s.shell, out);
  for (Eigen::Index e = 0; e < out.mid.cols(); ++e) {
    EXPECT_NEAR(out.mid(0, e), sigma, 1e-9 * sigma) << "element " << e;
    EXPECT_NEAR(out.mid(1, e), 0.0, 1e-9 * sigma) << "element " << e;
    EXPECT_NEAR(out.mid(3, e), 0.0, 1e-9 * sigma) << "element " << e;
    EXPECT_NEAR(out.top(0, e), sigma, 1e-9 * sigma) << "no bending, element " << e;
  }
  // Displacements linear: u = sigma / E x, v = -nu sigma / E y, at every node.
  for (Eigen::Index i = 0; i < s.x.cols(); ++i) {
    const sf::Vec3 x0 = model.blank.mesh.nodes.col(i);
    EXPECT_NEAR(s.x(0, i) - x0.x(), sigma / kYoung * x0.x(), 1e-12) << "node " << i;
    EXPECT_NEAR(s.x(1, i) - x0.y(), -0.3 * sigma / kYoung * x0.y(), 1e-12) << "node " << i;
  }
}

// The bending patch of LinearBendingPatchTest...: the largest deviation, as a fraction of the
// surface stress 6 m / t^2, from m_x = m, m_y = m_xy = 0 and no membrane force in every element.
double bending_patch_deviation(const std::string& formulation, double m) {
  // A uniform bending moment m per unit length about y on the right edge of unequal rectangles
  // (patch_rectangles.geo), consistent nodal moments m x the tributary lengths 3.05, 5.0 and
  // 1.95 mm: the plate bends cylindrically with m_x = m and m_y = 0 (free y edges) everywhere,
  // the outer-point stress 6 m / t^2 x zeta_5 and no membrane force, to round-off.
  std::string loads;
  for (const auto& [group, length] : {std::pair{"right_bottom", 3.05}, std::pair{"right_mid", 5.0},
                                      std::pair{"right_top", 1.95}}) {
    loads += fmt::format("[[load]]\ngroup = \"{}\"\ntype = \"moment\"\nvalue = [0.0, {}, 0.0]\n",
                         group, m * length);
  }
  sf::Model model =
      build_static_case("static_patch_bending_" + formulation, "patch_rectangles.geo", 0.3, R"(
[[boundary]]
group = "left"
type = "symmetry"
axis = "x"
[[boundary]]
group = "bottom"
type = "symmetry"
axis = "y"
[analysis]
type = "static"
geometry = "linear"
)" + loads,
                        "formulation = \"" + formulation + "\"\n");
  const sf::SolutionState s = run(model);
  sf::ShellStressOutput out;
  sf::compute_element_stress_output(model.blank.part, model.blank.mesh.nodes, s.shell, out);
  const double surface = 6.0 * m / (kThickness * kThickness);
  // The outermost of the 5 Gauss points (zeta = 0.9062) carries that fraction of the surface
  // stress.
  const double at_point = model.blank.part.section.zeta[4] * surface;
  double worst = 0.0;
  for (Eigen::Index e = 0; e < out.mid.cols(); ++e) {
    worst = std::max({worst, std::abs(std::abs(out.top(0, e)) - at_point),
                      std::abs(out.top(0, e) + out.bottom(0, e)), std::abs(out.top(1, e)),
                      std::abs(out.top(3, e)), std::abs(out.mid(0, e))});
  }
  return worst / surface;
}

TEST(StaticAnalysis, LinearBendingPatchTestIsExactOnRectangles) {
  // Belytschko-Tsay: strain increments on the undeformed geometry, exact to round-off.
  EXPECT_LT(bending_patch_deviation("belytschko_tsay", 100.0), 1e-9);
  // Assumed strain: the director measures are centred on the undeformed geometry, which cancels
  // their second-order terms but leaves a third-order one (relative error ~ rotation^2, the
  // rotations here 7e-3 rad at m = 100 N mm/mm): exact to 1e-9 when it is negligible, and the
  // deviation at larger moments is that term, 1000 times smaller for 10 times the moment
  // (docs/static-analysis.md, linear analysis).
  EXPECT_LT(bending_patch_deviation("assumed_strain", 1.0), 1e-9);
  const double at_100 = bending_patch_deviation("assumed_strain", 100.0);
  const double at_10 = bending_patch_deviation("assumed_strain", 10.0);
  EXPECT_LT(at_100, 1e-5);
  EXPECT_NEAR(at_100 / at_10, 100.0, 5.0) << at_100 << " at m = 100, " << at_10 << " at m = 10";
}

TEST(StaticAnalysis, NonlinearEndMomentRollsTheStripIntoTheElasticaArc) {
  // M L / (E I) = pi / 2: a quarter circle. Exact elastica: the tip at (L / theta) (sin theta,
  // 1 - cos theta) (REFERENCES.md, grade B). Every node held in the plane of bending (symmetry
  // about y): a moment of fixed global axis is not conservative for 3-D rotations and would turn
  // the strip out of that plane (as in test_cantilever.cpp).
  const double theta = 0.5 * std::numbers::pi;
  const double moment = theta * kYoung * kInertia / kLength;  // N mm in total
  sf::Model model = build_static_case("static_elastica", "strip.geo", 0.0, R"(
[[boundary]]
group = "clamp"
type = "fixed"
[[boundary]]
group = "blank"
type = "symmetry"
axis = "y"
[[load]]
group = "tip"
type = "moment"
value = [0.0, )" + std::to_string(-0.5 * moment) + R"(, 0.0]
[analysis]
type = "static"
[implicit]
increments = 16
force_tolerance = 1e-8
)");
  // 16 increments: the element's incremental kinematics (one midpoint step per increment, the
  // nodal rotation increments taken as its angular velocity x dt) are exact for a rigid motion,
  // but a node's relative rotation picks up an error growing with the square of the rigid
  // rotation of the increment: measured 0.9 % of the curvature with 4 increments of 22.5 deg
  // at the tip; 16 increments of 5.6 deg cut it 16-fold.
  sf::RunSummary summary;
  const sf::SolutionState s = run(model, &summary);
  const double radius = kLength / theta;
  const double x_tip = kLength + mean_tip(model, s, 0);
  const double z_tip = mean_tip(model, s, 2);
  std::printf("tip x %.4f (exact %.4f), z %.4f (exact %.4f) mm\n", x_tip, radius * std::sin(theta),
              z_tip, radius * (1.0 - std::cos(theta)));
  // 2e-3 L as in test_cantilever.cpp: 20 flat elements on the arc put the nodes on a circle
  // larger by (pi/80)/sin(pi/80) - 1 = 2.6e-4 for the quarter circle, plus the solver tolerance.
  EXPECT_NEAR(x_tip, radius * std::sin(theta), 2e-3 * kLength);
  EXPECT_NEAR(z_tip, radius * (1.0 - std::cos(theta)), 2e-3 * kLength);
  ASSERT_TRUE(summary.static_step.has_value());
  EXPECT_GE(summary.static_step->report.converged_increments, 16);
  EXPECT_LT(summary.static_step->report.final_residual, 1e-8);
}

TEST(StaticAnalysis, ElasticLoadAndUnloadReturnsFlat) {
  // The end moment up to the quarter circle and back to zero (curve 0 -> 1 -> 0): an elastic
  // strip must come back flat; the static step's incremental stress update is reversible along
  // the same path. Residual to the solver's tolerance (measured 3e-11 mm).
  const double moment = 0.5 * std::numbers::pi * kYoung * kInertia / kLength;
  sf::Model model = build_static_case("static_load_unload", "strip.geo", 0.0, R"(
[[boundary]]
group = "clamp"
type = "fixed"
[[load]]
group = "tip"
type = "moment"
value = [0.0, )" + std::to_string(-0.5 * moment) + R"(, 0.0]
curve = [[0.0, 0.0], [0.5, 1.0], [1.0, 0.0]]
[analysis]
type = "static"
[implicit]
increments = 8
force_tolerance = 1e-8
)");
  sf::RunSummary summary;
  const sf::SolutionState s = run(model, &summary);
  double largest = 0.0;
  for (Eigen::Index i = 0; i < s.x.cols(); ++i) {
    largest = std::max(largest, (s.x.col(i) - model.blank.mesh.nodes.col(i)).norm());
  }
  EXPECT_LT(largest, 1e-8 * kLength);
  ASSERT_TRUE(summary.static_step.has_value());
  EXPECT_EQ(summary.static_step->report.converged_increments, 8);
}

TEST(StaticAnalysis, MissingConstraintsGiveAClearErrorNamingTheFreeModes) {
  // No boundary at all and rigid_body_modes = "error": six free modes, named, before any solve.
  sf::Model model = build_static_case("static_unconstrained", "strip.geo", 0.3, R"(
[[load]]
group = "tip"
type = "force"
value = [0.0, 0.0, 5.0]
[analysis]
type = "static"
[implicit]
rigid_body_modes = "error"
)");
  try {
    run(model);
    FAIL() << "no error for an unconstrained static analysis";
  } catch (const sf::InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("6 rigid-body modes free"), std::string::npos) << message;
    EXPECT_NE(message.find("translation"), std::string::npos) << message;
    EXPECT_NE(message.find("rigid_body_modes = \"auto\""), std::string::npos) << message;
  }
}

}  // namespace

namespace {

// The summary of the bundled thick twisted beam (in-plane tip load, 4 x 24 warped quads; linear
// static) with the given element.
sf::RunSummary twisted_beam_summary(sf::ShellFormulation formulation) {
  sf::CaseConfig config = sf::read_case(fs::path(SF_SOURCE_DIR) / "cases" /
                                        "shell_twisted_beam_thick_in_plane" / "case.toml");
  config.blank.formulation = formulation;
  sf::Model model = sf::build_model(config);
  sf::RunSummary summary;
  run(model, &summary);
  return summary;
}

}  // namespace

TEST(StaticAnalysis, EnergyBalanceClosesOnWarpedQuadsWithEveryWorkCounted) {
  // The work of the loads equals the internal work when every internal force's work is counted:
  // the static drilling springs' (1/2 k (n . dtheta)^2 per node and increment) in the internal
  // work, and the Belytschko-Tsay stiffness-form hourglass forces' apart. On the warped twisted
  // beam both are large: before they were counted the balance was -0.70 with Belytschko-Tsay. The
  // linear analysis's trapezoidal rule is exact for its linear forces; the bound 1e-6 is the
  // solver's residual (measured 2.5e-8 and 2.0e-8).
  const sf::RunSummary bt = twisted_beam_summary(sf::ShellFormulation::belytschko_tsay);
  EXPECT_GT(bt.energies.hourglass, 0.01 * bt.energies.external_work);
  EXPECT_LT(std::abs(bt.energies.balance_error()), 1e-6);
  const sf::RunSummary as = twisted_beam_summary(sf::ShellFormulation::assumed_strain);
  // Its physical stabilisation stores energy (>= 0), reported as hourglass energy as in explicit
  // runs: 0.2 % of the work here.
  EXPECT_GE(as.energies.hourglass, 0.0);
  EXPECT_LT(std::abs(as.energies.balance_error()), 1e-6);
}
