// The implicit static step (src/implicit/static_step.hpp) on a cantilever strip, driven through
// its API with loads that rise and fall:
// - elastic-perfectly-plastic pure bending to M = 1.4 M_y, then unloading: the curvature under
//   load follows the closed form kappa = kappa_y / sqrt(3 - 2 M / M_y) (rectangular section) to
//   the through-thickness quadrature's accuracy, and unloading takes off exactly M / (E I)
//   (elastic unloading, no reverse yield below 2 M_y);
// - Newton converges quadratically near the solution of a large-rotation problem;
// - an unconstrained body whose rigid-body modes are not removed gives a ConvergenceError, not a
//   displacement;
// - releasing a pre-compressed cantilever (twice its Euler load, held by dead loads the way
//   springback holds a formed part) passes the buckling load: plain Newton cannot (no static path
//   exists there), the stabilised step ends stress-free in the exact stretched shape.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
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

// A clamped strip of a perfectly plastic material bent by a tip moment to 1.4 M_y and back to
// zero, statically, with this formulation and force tolerance.
void bend_plastically_and_unload(const std::string& name, sf::ShellFormulation formulation,
                                 double force_tolerance) {
  sf::Model model = build_strip(name,
                                "type = \"von_mises\"\ndensity = 7.85e-9\nyoung = 210000.0\n"
                                "poisson = 0.0\n[materials.steel.hardening]\nlaw = \"linear\"\n"
                                "yield_stress = 200.0\nmodulus = 0.0\n",
                                9, kClamp);
  model.blank.part.formulation = formulation;
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
  options.controls.force_tolerance = force_tolerance;
  const sf::StaticLoad load =
      tip_moment(model, moment, [](double l) { return l <= 0.5 ? 2.0 * l : 2.0 * (1.0 - l); });
  double kappa_loaded = 0.0;
  double eps_p_peak = 0.0;
  const sf::StaticStepReport report = sf::solve_static_step(
      body, c.dofs, load, options,
      [&](double lambda, const sf::StaticShellBody& b, const sf::StaticStepReport&,
          const sf::ConvergedIncrement&) {
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

TEST(StaticStep, PerfectlyPlasticBendingUnloadsByMOverEI) {
  bend_plastically_and_unload("static_plastic_bending_bt", sf::ShellFormulation::belytschko_tsay,
                              1e-9);
}

// The same with the assumed strain. With its stabilisation unloading elastically in a yielding
// element (the explicit loop's rule) the step stalled below lambda = 0.474 (residual 4e-8
// against 1e-9 after 8 halvings, 15 to 20 iterations per increment from lambda = 0.4): the
// switch between loading and unloading made the differenced tangent jump. The static step's
// rule (StabilizationUnloading::as_loading) converges like Belytschko-Tsay (96 iterations).
TEST(StaticStep, PerfectlyPlasticBendingUnloadsByMOverEIWithTheAssumedStrain) {
  bend_plastically_and_unload("static_plastic_bending_as", sf::ShellFormulation::assumed_strain,
                              1e-9);
}

// An elastic strip (nu = 0) of the given formulation rolled by a tip moment into a quarter
// circle, statically with these controls.
sf::StaticStepReport roll_to_quarter_circle(const std::string& name, int points,
                                            sf::ShellFormulation formulation,
                                            const sf::StaticStepOptions& options) {
  sf::Model model = build_strip(name,
                                "type = \"elastic\"\ndensity = 7.85e-9\nyoung = 210000.0\n"
                                "poisson = 0.0\n",
                                points, kClamp);
  model.blank.part.formulation = formulation;
  const double moment = 0.5 * std::numbers::pi * kYoung * kInertia / kLength;
  const sf::SolutionState s0 = sf::make_initial_state(model);
  sf::StaticShellBody body(model.blank.part, s0.x, s0.shell);
  const sf::StaticConstraints c = sf::make_static_constraints(
      s0.x, model.constraints.mask, sf::ImplicitConfig::RigidBodyModes::error, node_name);
  return sf::solve_static_step(body, c.dofs, tip_moment(model, moment, [](double l) { return l; }),
                               options);
}

TEST(StaticStep, NewtonConvergesQuadraticallyNearTheSolution) {
  // The solver's rate, on the Belytschko-Tsay element: at 45 degrees per increment the
  // assumed-strain element's Newton path inverts an element before it nears the solution and the
  // increment is cut (it converges at 22.5 degrees; docs/static-analysis.md). The tangent changes
  // along the way (large rotation).
  sf::StaticStepOptions options;
  options.controls.increments = 2;
  options.controls.force_tolerance = 1e-11;
  options.controls.displacement_tolerance = 1e-11;
  options.controls.line_search = false;
  const sf::StaticStepReport report = roll_to_quarter_circle(
      "static_newton_rate", 5, sf::ShellFormulation::belytschko_tsay, options);
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

// (internal + hourglass work - external work) / external work of a strip rolled by a tip moment
// into a quarter circle in `increments` equal increments.
double quarter_roll_balance(sf::ShellFormulation formulation, int increments) {
  sf::StaticStepOptions options;
  options.controls.increments = increments;
  options.controls.force_tolerance = 1e-10;
  options.controls.displacement_tolerance = 1e-10;
  const sf::StaticStepReport report =
      roll_to_quarter_circle("static_roll_balance", 3, formulation, options);
  EXPECT_EQ(report.cuts, 0);
  return (report.internal_work + report.hourglass_work - report.external_work) /
         report.external_work;
}

TEST(StaticStep, EnergyBalanceIsExactForBelytschkoTsayAndSecondOrderForAssumedStrain) {
  // Belytschko-Tsay's strain increments are linear in the increment's nodal motion and its stress
  // work equals the trapezoidal work of its nodal forces: the balance closes to round-off at any
  // increment size.
  EXPECT_LT(std::abs(quarter_roll_balance(sf::ShellFormulation::belytschko_tsay, 8)), 1e-12);
  // The assumed strain's measures are nonlinear in it (directors turned by finite rotations, the
  // arc of the turn): its stress work and the loads' trapezoidal work are two second-order
  // quadratures of the same work, so the balance error falls 4 times per halved increment
  // (measured on cases/verify_roll_up: 2.57e-4, 6.43e-5, 1.61e-5 at 2.25 degrees per increment and
  // half and a quarter of it). Ratio 4 within 10 %: a first-order error (ratio 2) or missing work
  // (ratio 1) fails.
  const double e8 = quarter_roll_balance(sf::ShellFormulation::assumed_strain, 8);
  const double e16 = quarter_roll_balance(sf::ShellFormulation::assumed_strain, 16);
  const double e32 = quarter_roll_balance(sf::ShellFormulation::assumed_strain, 32);
  std::printf("assumed strain, quarter roll: balance %.3e, %.3e, %.3e at 8, 16, 32 increments\n",
              e8, e16, e32);
  EXPECT_NEAR(e8 / e16, 4.0, 0.4);
  EXPECT_NEAR(e16 / e32, 4.0, 0.4);
  // Its size: 0.0417 per rad^2 of rotation per increment on the full roll-up (6.43e-5 at
  // 2.25 degrees); the same constant here (a quarter circle in 32 increments: 2.81 degrees).
  const double step = 0.5 * std::numbers::pi / 32.0;  // rad per increment
  EXPECT_NEAR(e32 / (step * step), 0.0417, 0.1 * 0.0417);
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

// A strip pre-stressed to -sigma0 along its length (uniaxial, nu = 0: the stress-free strain is
// sigma0 / E) and held in that state by the nodal forces its stresses exert, released as
// springback releases a formed part: loads (1 - lambda) f0, while a transverse tip force lambda F
// grows. With sigma0 A = 2 P_cr, the clamped-free Euler load P_cr = pi^2 E I / (4 L^2)
// (Timoshenko & Gere 1961, sec. 2.1), the compression (1 - lambda) 2 P_cr passes P_cr at
// lambda = 1/2, where the linear deflection under the lateral force, amplified by
// 1 / (1 - P / P_cr), is unbounded and changes sign (only the large-deflection terms keep a path:
// plain Newton needs 20 iterations and a cut there). At lambda = 1 the strip is stress-free but for
// the tip force: stretched by sigma0 L / E and bent to F L^3 / (3 E I). The stabilised step must
// end there, in equilibrium without its springs. (Plain Newton, printed for comparison, ends with
// the tip 3.6 % short of the beam formula: its excursion to large rotations at the buckling load
// and back leaves the incremental rotation kinematics' error in the state;
// docs/static-analysis.md.)
TEST(StaticStep, StabilisedReleaseThroughTheBucklingLoadEndsInTheUnstabilisedEquilibrium) {
  sf::Model model = build_strip(
      "static_release_buckling",
      "type = \"elastic\"\ndensity = 7.85e-9\nyoung = 210000.0\npoisson = 0.0\n", 5, kClamp);
  const double area = kWidth * kThickness;
  const double p_cr = std::numbers::pi * std::numbers::pi * kYoung * kInertia /
                      (4.0 * kLength * kLength);                                  // N, 345 N
  const double sigma0 = 2.0 * p_cr / area;                                        // MPa
  const double tip_force = 3.0 * kYoung * kInertia / std::pow(kLength, 3) * 0.1;  // N: 0.1 mm
  sf::SolutionState s0 = sf::make_initial_state(model);
  // Uniaxial along the strip: sxx or syy of the element frame, whose first axis is the side from
  // the quad's first node to its second (the strip's quads are rectangles along x).
  const int points = s0.shell.n_points;
  for (Eigen::Index e = 0; e < model.blank.part.quads.cols(); ++e) {
    const sf::Vec3 side =
        s0.x.col(model.blank.part.quads(1, e)) - s0.x.col(model.blank.part.quads(0, e));
    std::vector<double>& along =
        std::abs(side(0)) > std::abs(side(1)) ? s0.shell.sxx : s0.shell.syy;
    for (int k = 0; k < points; ++k) {
      along[static_cast<std::size_t>(e * points + k)] = -sigma0;
    }
  }
  const sf::Matrix3X x0 = s0.x;
  const sf::StaticConstraints c = sf::make_static_constraints(
      s0.x, model.constraints.mask, sf::ImplicitConfig::RigidBodyModes::error, node_name);
  const std::vector<int> tip = model.blank.group("tip").nodes;

  auto release = [&](sf::StaticShellBody& body) {
    const sf::Matrix3X zero = sf::Matrix3X::Zero(3, body.node_count());
    auto f0 = std::make_shared<sf::Matrix3X>();
    auto m0 = std::make_shared<sf::Matrix3X>();
    sf::ShellState trial;
    body.compute_forces(zero, zero, *f0, *m0, trial);
    sf::StaticLoad load;
    load.at = [f0, m0, tip, tip_force](double lambda, const sf::Matrix3X&, sf::Matrix3X& f,
                                       sf::Matrix3X& m) {
      f = (1.0 - lambda) * *f0;
      m = (1.0 - lambda) * *m0;
      for (int node : tip) {
        f(2, node) += lambda * tip_force / static_cast<double>(tip.size());
      }
    };
    load.reference_force = f0->norm();
    return load;
  };
  sf::StaticStepOptions options;
  options.controls.increments = 10;
  options.node_name = node_name;

  {
    sf::StaticShellBody plain(model.blank.part, s0.x, s0.shell);
    const sf::StaticLoad load = release(plain);
    sf::solve_static_step(plain, c.dofs, load, options);
    const sf::Matrix3X& x_plain = plain.x();
    double ux = 0.0, uz = 0.0;
    for (int node : tip) {
      ux += (x_plain(0, node) - x0(0, node)) / static_cast<double>(tip.size());
      uz += (x_plain(2, node) - x0(2, node)) / static_cast<double>(tip.size());
    }
    std::printf("plain Newton: tip ux %.6e uz %.6e mm\n", ux, uz);
  }

  sf::StaticShellBody body(model.blank.part, s0.x, s0.shell);
  const sf::StaticLoad load = release(body);
  options.stabilization = 1e-6 * body.membrane_stiffness();  // the springback default
  const sf::StaticStepReport report = sf::solve_static_step(body, c.dofs, load, options);
  double tip_ux = 0.0, tip_uz = 0.0;
  for (int node : tip) {
    tip_ux += (body.x()(0, node) - x0(0, node)) / static_cast<double>(tip.size());
    tip_uz += (body.x()(2, node) - x0(2, node)) / static_cast<double>(tip.size());
  }
  const double expected_ux = sigma0 / kYoung * kLength;                                     // mm
  const double expected_uz = tip_force * std::pow(kLength, 3) / (3.0 * kYoung * kInertia);  // mm
  std::printf(
      "release of 2 P_cr = %.1f N with a %.3f N tip force: tip ux %.6e mm (stress-free %.6e, "
      "%+.3f %%), tip uz %.6e mm (beam %.6e, %+.3f %%); %d increments + %d settling, %d cuts, "
      "%d iterations\n",
      2.0 * p_cr, tip_force, tip_ux, expected_ux, 100.0 * (tip_ux / expected_ux - 1.0), tip_uz,
      expected_uz, 100.0 * (tip_uz / expected_uz - 1.0), report.converged_increments,
      report.settling_increments, report.cuts, report.newton_iterations);
  EXPECT_GT(report.settling_increments, 0);
  EXPECT_EQ(report.increments.back().stabilization, 0.0)
      << "the last increment must be without springs";
  // The element's tip deflection is within 0.2 % of the beam formula (the linear cantilever test
  // in test_static_analysis.cpp); the bending shortens the strip by about (6/5) uz^2 / (2 L)
  // = 6e-5 mm, 0.4 % of the stretch.
  EXPECT_NEAR(tip_uz, expected_uz, 5e-3 * expected_uz);
  EXPECT_NEAR(tip_ux, expected_ux, 1e-2 * expected_ux);
}
