// The implicit static step (src/implicit/static_step.hpp) on a cantilever strip, driven through
// its API with loads that rise and fall:
// - elastic-perfectly-plastic pure bending to M = 1.4 M_y, then unloading: the curvature under
//   load follows the closed form kappa = kappa_y / sqrt(3 - 2 M / M_y) (rectangular section) to
//   the through-thickness quadrature's accuracy, and unloading takes off exactly M / (E I)
//   (elastic unloading, no reverse yield below 2 M_y);
// - Newton converges quadratically near the solution of a large-rotation problem;
// - an unconstrained body whose rigid-body modes are not removed gives a ConvergenceError, not a
//   displacement.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "core/errors.hpp"
#include "element/shell_part.hpp"
#include "implicit/static_constraints.hpp"
#include "implicit/static_step.hpp"
#include "model/build_model.hpp"
#include "solver/explicit_driver.hpp"

namespace {

namespace fs = std::filesystem;

constexpr double kLength = 100.0;    // mm, tests/data/strip.geo
constexpr double kWidth = 10.0;      // mm
constexpr double kThickness = 2.0;   // mm
constexpr double kYoung = 210000.0;  // MPa
constexpr double kYield = 200.0;     // MPa
constexpr double kInertia = kWidth * kThickness * kThickness * kThickness / 12.0;  // mm^4

sf::Model build_strip(const std::string& name, const std::string& material, int points,
                      const std::string& boundary) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "case.toml")
      << "[blank]\nmesh = \"" + (fs::path(SF_TEST_DATA_DIR) / "strip.geo").string() +
             "\"\nthickness = 2.0\nintegration_points = " + std::to_string(points) +
             "\nmaterial = \"steel\"\n[materials.steel]\n" + material + boundary +
             // The tip group, read through a draw-in entry (the loads are applied here in code).
             "\n[[draw_in]]\nname = \"tip\"\ngroup = \"tip\"\n[control]\nend_time = 1.0\n";
  return sf::build_model(sf::read_case(folder / "case.toml"));
}

constexpr const char* kClamp = "[[boundary]]\ngroup = \"clamp\"\ntype = \"fixed\"\n";

// Curvature (1/mm) of a strip bent into a circular arc from its clamped end, from the tip's mean
// position: the tip chord makes the angle kappa L / 2 with the strip's axis.
double arc_curvature(const sf::Model& model, const sf::Matrix3X& x) {
  const auto& tip = model.blank.group("tip").nodes;
  double px = 0.0, pz = 0.0;
  for (int node : tip) {
    px += x(0, node);
    pz += x(2, node);
  }
  return 2.0 * std::atan2(pz, px) / kLength;
}

// A tip moment about -y (lifting the tip towards +z) of total `moment` (N mm) x profile(lambda).
sf::StaticLoad tip_moment(const sf::Model& model, double moment,
                          std::function<double(double)> profile) {
  sf::StaticLoad load;
  const std::vector<int> tip = model.blank.group("tip").nodes;
  load.at = [tip, moment, profile](double lambda, const sf::Matrix3X&, sf::Matrix3X& f,
                                   sf::Matrix3X& m) {
    f.setZero();
    m.setZero();
    for (int node : tip) {
      m(1, node) = -moment * profile(lambda) / static_cast<double>(tip.size());
    }
  };
  return load;
}

std::string node_name(int node) {
  return "node " + std::to_string(node);
}

TEST(StaticStep, PerfectlyPlasticBendingUnloadsByMOverEI) {
  sf::Model model = build_strip("static_plastic_bending",
                                "type = \"von_mises\"\ndensity = 7.85e-9\nyoung = 210000.0\n"
                                "poisson = 0.0\n[materials.steel.hardening]\nlaw = \"linear\"\n"
                                "yield_stress = 200.0\nmodulus = 0.0\n",
                                9, kClamp);
  const double m_yield = kYield * kWidth * kThickness * kThickness / 6.0;  // N mm
  const double kappa_yield = 2.0 * kYield / (kYoung * kThickness);         // 1/mm
  const double ratio = 1.4;
  const double moment = ratio * m_yield;
  const sf::SolutionState s0 = sf::make_initial_state(model);
  sf::StaticShellBody body(model.blank.part, s0.x, s0.shell);
  const sf::StaticConstraints c = sf::make_static_constraints(
      s0.x, model.constraints.mask, sf::ImplicitConfig::RigidBodyModes::error, node_name);
  sf::StaticStepOptions options;
  options.controls.increments = 20;  // 10 up to the peak at lambda = 0.5, 10 down
  options.controls.force_tolerance = 1e-9;
  const sf::StaticLoad load =
      tip_moment(model, moment, [](double l) { return l <= 0.5 ? 2.0 * l : 2.0 * (1.0 - l); });
  double kappa_loaded = 0.0;
  double eps_p_peak = 0.0;
  const sf::StaticStepReport report = sf::solve_static_step(
      body, c.dofs, load, options,
      [&](double lambda, const sf::StaticShellBody& b, const sf::StaticStepReport&) {
        if (std::abs(lambda - 0.5) < 1e-12) {
          kappa_loaded = arc_curvature(model, b.x());
          eps_p_peak = *std::max_element(b.state().eps_p.begin(), b.state().eps_p.end());
        }
      });
  ASSERT_GT(kappa_loaded, 0.0) << "no increment ended at the peak";
  ASSERT_GT(eps_p_peak, 0.0) << "the section did not yield";
  const double kappa_residual = arc_curvature(model, body.x());
  const double unloading = kappa_loaded - kappa_residual;
  const double elastic = moment / (kYoung * kInertia);
  // The continuum closed form, and the same law integrated with the model's own 9 Gauss points
  // (the stress profile min(E kappa z, sigma_y) has a kink the rule cannot resolve exactly).
  const double kappa_closed = kappa_yield / std::sqrt(3.0 - 2.0 * ratio);
  const auto moment_of = [](double kappa, bool gauss) {  // N mm, perfectly plastic section
    if (!gauss) {
      const double r = 2.0 * kYield / (kYoung * kThickness) / kappa;  // kappa_y / kappa <= 1
      return kYield * kWidth * kThickness * kThickness / 6.0 * (1.5 - 0.5 * r * r);
    }
    const sf::ShellSection section = sf::make_gauss_section(9);
    double m = 0.0;
    for (int k = 0; k < 9; ++k) {
      const double z = 0.5 * kThickness * section.zeta[static_cast<std::size_t>(k)];
      const double stress = std::clamp(kYoung * kappa * z, -kYield, kYield);
      m += 0.5 * kThickness * section.weight[static_cast<std::size_t>(k)] * kWidth * z * stress;
    }
    return m;
  };
  std::printf(
      "kappa loaded %.6e (closed form %.6e, %+.3f %%; section moment there: 9-point "
      "rule %+.2e, continuum %+.3f %% of M), unloading %.6e (M/EI %.6e, %+.4f %%), "
      "residual %.6e 1/mm; %d increments, %d iterations\n",
      kappa_loaded, kappa_closed, 100.0 * (kappa_loaded / kappa_closed - 1.0),
      moment_of(kappa_loaded, true) / moment - 1.0,
      100.0 * (moment_of(kappa_loaded, false) / moment - 1.0), unloading, elastic,
      100.0 * (unloading / elastic - 1.0), kappa_residual, report.converged_increments,
      report.newton_iterations);
  // Unloading is elastic: exactly M / (E I) up to the solver tolerance and the arc measure.
  EXPECT_NEAR(unloading / elastic, 1.0, 1e-4);
  // Under load, against the uniaxial beam law: two effects keep this approximate. The shell
  // section is a plate's: with the yy plastic flow of J2 (half the xx flow, opposite sign) a
  // linear-in-z yy strain cannot follow, so sigma_yy is not zero in the plastic zones; and the
  // 9-point rule integrates a kinked profile (the uniaxial law on the same 9 points differs by
  // the printed "9-point rule" figure). Measured: the continuum moment at the computed curvature
  // is 0.5 % low, which the flat moment-curvature curve near M_p (d kappa / dM = 11 kappa_y /
  // M_y at 1.4 M_y) turns into 3.4 % of curvature. Bound: 1 % of the moment.
  EXPECT_NEAR(moment_of(kappa_loaded, false) / moment, 1.0, 1e-2);
}

TEST(StaticStep, NewtonConvergesQuadraticallyNearTheSolution) {
  sf::Model model = build_strip("static_newton_rate",
                                "type = \"elastic\"\ndensity = 7.85e-9\nyoung = 210000.0\n"
                                "poisson = 0.0\n",
                                5, kClamp);
  // Roll the strip into a quarter circle (large rotation: the tangent changes along the way).
  const double moment = 0.5 * std::numbers::pi * kYoung * kInertia / kLength;
  const sf::SolutionState s0 = sf::make_initial_state(model);
  sf::StaticShellBody body(model.blank.part, s0.x, s0.shell);
  const sf::StaticConstraints c = sf::make_static_constraints(
      s0.x, model.constraints.mask, sf::ImplicitConfig::RigidBodyModes::error, node_name);
  sf::StaticStepOptions options;
  options.controls.increments = 2;
  options.controls.force_tolerance = 1e-11;
  options.controls.displacement_tolerance = 1e-11;
  options.controls.line_search = false;
  const sf::StaticStepReport report = sf::solve_static_step(
      body, c.dofs, tip_moment(model, moment, [](double l) { return l; }), options);
  ASSERT_EQ(report.cuts, 0);
  // Near the solution Newton squares the residual: once it is below 1e-3, each iteration gives
  // at most 10 x its square while above the finite-difference tangent's floor (~1e-10), and it
  // reaches 1e-10 within 3 iterations (a linear rate of 0.1 would need 7).
  int quadratic_steps = 0;
  for (const sf::IncrementRecord& inc : report.increments) {
    double previous = inc.initial_residual;
    std::string sequence = fmt::format("{:.3e}", previous);
    int since_below = -1;
    for (const sf::NewtonIteration& it : inc.iterations) {
      sequence += fmt::format(" {:.3e}", it.residual);
      if (previous < 1e-3 && it.residual > 1e-10) {
        EXPECT_LT(it.residual, 10.0 * previous * previous)
            << "not quadratic: " << previous << " -> " << it.residual;
        ++quadratic_steps;
      }
      if (since_below >= 0 || it.residual < 1e-3) {
        ++since_below;
      }
      previous = it.residual;
    }
    EXPECT_LE(since_below, 3) << sequence;
    std::printf("increment to %.2f: residuals %s\n", inc.lambda_end, sequence.c_str());
  }
  EXPECT_GE(quadratic_steps, 1);
}

TEST(StaticStep, UnremovedRigidBodyModesGiveAConvergenceErrorNotADisplacement) {
  sf::Model model = build_strip("static_singular",
                                "type = \"elastic\"\ndensity = 7.85e-9\nyoung = 210000.0\n"
                                "poisson = 0.3\n",
                                5, "");
  const sf::SolutionState s0 = sf::make_initial_state(model);
  sf::StaticShellBody body(model.blank.part, s0.x, s0.shell);
  // Every degree of freedom free: bypass make_static_constraints on purpose.
  const sf::DofMap dofs(std::vector<unsigned char>(static_cast<std::size_t>(s0.x.cols()), 0));
  sf::StaticStepOptions options;
  try {
    sf::solve_static_step(body, dofs, tip_moment(model, 100.0, [](double l) { return l; }),
                          options);
    FAIL() << "a free body's static step returned a solution";
  } catch (const sf::ConvergenceError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("singular"), std::string::npos) << message;
  }
}

}  // namespace
