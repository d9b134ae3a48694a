// Selective mass scaling (docs/time-integration.md), at run level:
// - a quasi-static cantilever on a graded mesh gives the same tip deflection with and without
//   scaling, in fewer cycles by the ratio of the steps, and the added mass reported is the sum of
//   the element mass increases (checked against an independent count from the mesh);
// - mass added during the run (elements compressed below the target step) keeps the momentum
//   exactly and the energy balance closed, with the kinetic energy it removes reported.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "case_fixture.hpp"

namespace {

constexpr double young = 210000.0;   // MPa
constexpr double density = 7.85e-9;  // tonne/mm^3
constexpr double thickness = 2.0;    // mm

// Sum over elements of (density_factor - 1) x element mass: what the nodal masses must hold.
double sum_of_element_increases(const sf::MassScaling& m) {
  double sum = 0.0;
  for (std::size_t e = 0; e < m.element_mass.size(); ++e) {
    sum += (m.density_factor[e] - 1.0) * m.element_mass[e];
  }
  return sum;
}

// A 100 x 10 mm strip of 12 x 1 elements whose length grows by 1.1 from the clamp (x = 0, 4.7 mm)
// to the tip (13.3 mm): the short elements near the clamp limit the step, as a refined radius
// does in a forming mesh.
const char* graded_strip_geo = R"(
L = 100; b = 10; n = 12;
Point(1) = {0, 0, 0}; Point(2) = {L, 0, 0}; Point(3) = {L, b, 0}; Point(4) = {0, b, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {4, 3}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, -3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = n + 1 Using Progression 1.1;
Transfinite Curve{2, 4} = 2;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("blank") = {1};
Physical Curve("clamp") = {4};
Physical Curve("tip") = {2};
)";

TEST(MassScaling, QuasiStaticCantileverIsUnchangedInFewerCycles) {
  // Tip force F = 1 N ramped over 10 first periods and held to 16, with mass-proportional damping
  // 2 w1 (critical for the first mode of the unscaled strip): dynamic relaxation to the static
  // deflection, which does not depend on the mass.
  const double inertia = 10.0 * thickness * thickness * thickness / 12.0;  // mm^4
  const double omega1 =
      1.8751 * 1.8751 * std::sqrt(young * inertia / (density * 10.0 * thickness * 1e8));
  const double period = 2.0 * std::numbers::pi / omega1;
  const std::string case_text = R"(thickness = 2.0
material = "steel"
[materials.steel]
type = "elastic"
density = 7.85e-9
young = 210000.0
poisson = 0.0
[[boundary]]
group = "clamp"
type = "fixed"
[[load]]
group = "tip"
type = "force"
value = [0.0, 0.0, -0.5]
curve = [[0.0, 0.0], [)" + std::to_string(10.0 * period) +
                                R"(, 1.0]]
[[draw_in]]
name = "tip"
group = "tip"
direction = [0.0, 0.0, -1.0]
[control]
damping = )" + std::to_string(2.0 * omega1) +
                                R"(
end_time = )" + std::to_string(16.0 * period) +
                                "\n";
  sf::CaseConfig config =
      sf::test::write_case("mass_scaling_cantilever", graded_strip_geo, case_text);
  sf::RunOptions options;
  options.write_results = false;

  sf::Model plain = sf::build_model(config);
  const double dt0 = plain.time.time_step;
  EXPECT_EQ(plain.time.limiting_element, 0);  // the shortest element, at the clamp
  EXPECT_EQ(plain.blank.scaling.added_mass, 0.0);
  const sf::RunSummary a = sf::run_explicit(plain, options);
  EXPECT_EQ(a.added_mass, 0.0);

  const double factor = 1.8;  // target step / unscaled step
  config.control.mass_scaling_dt = factor * dt0;
  sf::Model scaled = sf::build_model(config);
  const sf::MassScaling& m = scaled.blank.scaling;
  EXPECT_NEAR(scaled.time.time_step / (factor * dt0), 1.0, 1e-12);

  // Independent count of the mass added at the start, from the mesh: element e (h_e x 10 mm,
  // h_e <= 10 mm) has the step 0.9 h_e / c at the physical density (L = A / longest side = h_e;
  // c = sqrt(E / rho) with nu = 0) and gets the factor (target / step)^2 when that is > 1.
  const double c = std::sqrt(young / density);
  double expected_added = 0.0;
  int expected_scaled = 0;
  for (Eigen::Index e = 0; e < scaled.blank.mesh.quads.cols(); ++e) {
    const auto q = scaled.blank.mesh.quads.col(e);
    const double x_min =
        std::min({scaled.blank.mesh.nodes(0, q[0]), scaled.blank.mesh.nodes(0, q[1]),
                  scaled.blank.mesh.nodes(0, q[2]), scaled.blank.mesh.nodes(0, q[3])});
    const double x_max =
        std::max({scaled.blank.mesh.nodes(0, q[0]), scaled.blank.mesh.nodes(0, q[1]),
                  scaled.blank.mesh.nodes(0, q[2]), scaled.blank.mesh.nodes(0, q[3])});
    const double h = x_max - x_min;
    const double step = 0.9 * std::min(h, 10.0) / c;
    const double f = std::pow(factor * dt0 / step, 2);
    if (f > 1.0) {
      expected_added += (f - 1.0) * density * thickness * h * 10.0;
      ++expected_scaled;
    }
  }
  std::printf(
      "start: %d of 12 elements scaled (expected %d), added %.6e tonne (expected %.6e), "
      "%.2f %% of %.6e tonne\n",
      m.scaled_elements, expected_scaled, m.added_mass, expected_added,
      100.0 * m.added_mass / scaled.blank.physical_mass, scaled.blank.physical_mass);
  EXPECT_EQ(m.scaled_elements, expected_scaled);
  EXPECT_GT(expected_scaled, 0);
  EXPECT_LT(expected_scaled, 12);  // selective: the long elements keep their density
  // Tolerance 1e-12: the same sums in another order.
  EXPECT_NEAR(m.added_mass / expected_added, 1.0, 1e-12);

  sf::SolutionState end_b;  // the run state at the end: the masses and the scaling grown in it
  const sf::RunSummary b = sf::run_explicit(scaled, options, &end_b);
  const double deflection_a = a.draw_ins.front().computed;
  const double deflection_b = b.draw_ins.front().computed;
  const double beam = 1.0 * std::pow(100.0, 3) / (3.0 * young * inertia);
  std::printf(
      "tip deflection %.6f mm unscaled (%ld cycles), %.6f mm scaled (%ld cycles): "
      "%+.2e relative; cycle ratio %.4f (expected %.4f); beam theory %.6f mm; added mass "
      "%.2f %% at the end; energy balance %.2e unscaled, %.2e scaled\n",
      deflection_a, a.cycles, deflection_b, b.cycles, deflection_b / deflection_a - 1.0,
      static_cast<double>(a.cycles) / static_cast<double>(b.cycles), factor, beam,
      100.0 * b.added_mass_fraction, a.energies.balance_error(), b.energies.balance_error());
  // Both runs reach the static answer (beam theory within 2 %: 12 one-point elements, coarse at
  // the tip) ...
  EXPECT_NEAR(deflection_a / beam, 1.0, 0.02);
  // ... and agree to 1e-4: the residual motion left after 6 damped periods of hold is below
  // 1e-6 of the deflection for the unscaled strip (damping ratio 1 on mode 1) and the scaled
  // one (mode 1 slightly slower, over-damped); 1e-4 leaves room for the higher modes' remains.
  EXPECT_NEAR(deflection_b / deflection_a, 1.0, 1e-4);
  // Cycles drop by the ratio of the steps (tolerance 0.2 %: the 20 output landings each add at
  // most one cycle to either run; measured 1.7999 for 1.8).
  EXPECT_NEAR(static_cast<double>(a.cycles) / static_cast<double>(b.cycles), factor,
              0.002 * factor);
  EXPECT_NEAR(b.min_time_step / (factor * dt0), 1.0, 1e-6);
  // The added mass reported is the sum of the element mass increases, and what the nodes hold.
  EXPECT_NEAR(b.added_mass / sum_of_element_increases(end_b.scaling), 1.0, 1e-12);
  EXPECT_NEAR((end_b.mass.sum() - scaled.blank.physical_mass) / b.added_mass, 1.0, 1e-9);
  // Energy balance at the end: measured 9.0e-11 unscaled and 2.9e-10 scaled (the same with the
  // kinetic energy at the half step: the strip is at rest by then, so the kinetic and half-kick
  // energies are gone and what is left is the accounting of the damping work). Bound 1e-6: far
  // below any first-order accounting slip, with room for that damping residual.
  EXPECT_LT(std::abs(a.energies.balance_error()), 1e-6);
  EXPECT_LT(std::abs(b.energies.balance_error()), 1e-6);
}

TEST(MassScaling, MassAddedDuringTheRunKeepsMomentumAndEnergy) {
  // A free 100 x 10 x 2 mm strip (20 x 1 elements, 5 x 10 mm) whose left half moves at
  // v = 200 m/s into the right half at rest: the compression wave (strain about v / 2c = 2 %)
  // shortens the elements, whose step L = A / longest side = 5 mm x stretch falls below the
  // target, which is set to the undeformed step, so mass is added during the run only.
  sf::CaseConfig config = sf::test::write_case("mass_scaling_impact", R"(
Point(1) = {0, 0, 0}; Point(2) = {50, 0, 0}; Point(3) = {100, 0, 0};
Point(4) = {100, 10, 0}; Point(5) = {50, 10, 0}; Point(6) = {0, 10, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6};
Line(6) = {6, 1}; Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6}; Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7}; Plane Surface(2) = {2};
Transfinite Curve{1, 2, 4, 5} = 11;
Transfinite Curve{3, 6, 7} = 2;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};
Physical Surface("blank") = {1, 2};
Physical Surface("left") = {1};
)",
                                               R"(thickness = 2.0
material = "steel"
formulation = "belytschko_tsay"
hourglass = 0.0
[materials.steel]
type = "elastic"
density = 7.85e-9
young = 210000.0
poisson = 0.3
[[initial_velocity]]
group = "left"
velocity = [200000.0, 0.0, 0.0]
[control]
end_time = 1.0e-3
)");
  const double dt0 = sf::build_model(config).time.time_step;
  config.control.mass_scaling_dt = dt0;
  sf::Model model = sf::build_model(config);
  ASSERT_EQ(model.blank.scaling.added_mass, 0.0);  // nothing below the target at the start

  sf::SolutionState s = sf::make_initial_state(model);
  sf::compute_forces(model, s, 0.0);
  auto momentum = [&](const sf::SolutionState& state) {
    sf::Vec3 p = sf::Vec3::Zero();
    for (Eigen::Index i = 0; i < state.v.cols(); ++i) {
      p += state.mass[i] * state.v.col(i);
    }
    return p;
  };
  const sf::Vec3 p0 = momentum(s);
  double max_momentum_error = 0.0;
  double max_balance_error = 0.0;   // the reported one
  double max_discrete_error = 0.0;  // offset-corrected, see below
  const double e0 = s.energies.initial_kinetic;
  // Steps of exactly the target (the mass scaling holds every element at or above it), so that
  // the central-difference energy invariant is exact but for the geometric nonlinearity; the
  // driver's own loop varies the step when elements stretch back above the target.
  const double dt = model.blank.scaling.target_dt;
  double dt_previous = 0.0;
  double min_stable_dt = 1.0;
  for (int cycle = 0; cycle < 100; ++cycle) {
    min_stable_dt = std::min(min_stable_dt, sf::compute_time_step(model, s));
    sf::advance_one_step(model, s, dt, dt_previous);
    dt_previous = dt;
    max_momentum_error = std::max(max_momentum_error, (momentum(s) - p0).norm() / p0.norm());
    max_balance_error = std::max(max_balance_error, std::abs(s.energies.balance_error()));
    // The reported balance (kinetic energy at the step end) is off by the half-kick energy D =
    // 1/2 sum m |dt/2 a|^2, second order in dt but large in this shock problem (up to 3.4e-2 of
    // the energy; the kinetic energy at the half step swung by 9.3e-2); without it (H of
    // test_verification.cpp) the balance is an identity of the scheme at a constant step.
    const sf::Energies& e = s.energies;
    max_discrete_error =
        std::max(max_discrete_error,
                 std::abs(e.total() - sf::test::half_kick_energy(model, s) - e.supplied()) / e0);
  }
  const sf::MassScaling& m = s.scaling;
  std::printf(
      "in the run: %d elements scaled, %.3f %% mass added; kinetic energy removed %.3e of "
      "E0; max |balance error| %.3e reported, %.3e offset-corrected; max momentum error %.2e; step "
      "%.6e to %.6e s "
      "(target %.6e)\n",
      m.scaled_elements, 100.0 * m.added_mass / model.blank.physical_mass,
      s.energies.mass_scaling / e0, max_balance_error, max_discrete_error, max_momentum_error,
      s.min_stable_dt, s.max_stable_dt, dt0);
  EXPECT_GT(m.scaled_elements, 0);
  EXPECT_GT(m.added_mass, 0.0);
  // The step is held at the target (tolerance: the trigger margin kMassScalingTolerance).
  EXPECT_GE(min_stable_dt, dt0 * (1.0 - sf::kMassScalingTolerance));
  // Momentum: mass added at fixed nodal momentum; no external force. Tolerance 1e-12: round-off
  // of the force sums over some hundred steps.
  EXPECT_LT(max_momentum_error, 1e-12);
  EXPECT_NEAR(m.added_mass / sum_of_element_increases(m), 1.0, 1e-12);
  EXPECT_NEAR((s.mass.sum() - model.blank.physical_mass) / m.added_mass, 1.0, 1e-9);
  // Energy: the kinetic energy taken out by the added mass enters the balance as its own term.
  // At a constant step the offset-corrected balance total - D - supplied is an algebraic
  // identity of central difference with trapezoidal work increments (for any forces), so with the
  // mass-scaling term counted as docs/time-integration.md says it must close to round-off:
  // tolerance 1e-12 of the energy over 100 steps (measured 5.3e-16). The term is the drop of the
  // whole-step kinetic energy less that of D; it is 2.6e-2 of the energy here (counting the
  // kinetic-energy drop alone leaves 4.3e-3 unexplained, and the half-step drop of a first
  // version of this code 1.2e-2).
  EXPECT_LT(max_discrete_error, 1e-12);
  EXPECT_GT(s.energies.mass_scaling / e0, 1e-2);
  // The reported balance error itself: bound 5e-2 on the measured 3.4e-2 (D, above).
  EXPECT_LT(max_balance_error, 5e-2);
}

}  // namespace
