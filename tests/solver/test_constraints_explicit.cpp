// General constraints in explicit runs: the problems of test_constraints_static.cpp, loaded
// slowly (ramps over 10 first periods, held to 16) with mass-proportional damping near critical
// for the first mode, so that each run settles to its static solution (dynamic relaxation):
// - the strip on diaphragm ends under a uniform pressure: the static analysis's midspan
//   deflection, which is the Timoshenko beam's with the element's own error (exact for this
//   element, derivation in test_constraints_static.cpp);
// - the same strip turned 30 degrees about z with its diaphragms given by a normal: the same
//   motion to round-off, node by node (the held components are zeroed in each end node's axes);
// - a cantilever with a prescribed tip deflection (a displacement curve, turned into velocities by
//   central differences): the tip lands on the curve exactly, the reaction is the beam's
//   stiffness times it, and the work of the prescribed motion closes the energy balance;
// - a prescribed tip rotation: the uniform moment E I theta / L.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "model/build_model.hpp"
#include "solver/dynamic_relaxation.hpp"
#include "solver/explicit_driver.hpp"
#include "solver/springback.hpp"

namespace {

namespace fs = std::filesystem;

constexpr double kLength = 100.0;     // mm, tests/data/strip.geo: 20 x 1 quads
constexpr double kWidth = 10.0;       // mm
constexpr double kThickness = 2.0;    // mm
constexpr double kYoung = 210000.0;   // MPa, nu = 0
constexpr double kDensity = 7.85e-9;  // tonne/mm^3
constexpr double kInertia = kWidth * kThickness * kThickness * kThickness / 12.0;   // mm^4
constexpr double kShearStiffness = 5.0 / 6.0 * 0.5 * kYoung * kWidth * kThickness;  // N
constexpr double kElements = 20.0;

// First bending frequency (rad/s), Euler-Bernoulli: (beta L)^2 sqrt(E I / (rho A L^4)), beta L =
// pi simply supported, 1.8751 clamped-free.
double first_frequency(double beta_l) {
  return beta_l * beta_l *
         std::sqrt(kYoung * kInertia / (kDensity * kWidth * kThickness * std::pow(kLength, 4)));
}

std::string strip_geo(bool turned) {
  std::ifstream in(fs::path(SF_TEST_DATA_DIR) / "strip.geo");
  std::string geo((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (turned) {
    geo += "Rotate {{0, 0, 1}, {0, 0, 0}, Pi / 6} { Surface{1}; }\n";
  }
  return geo;
}

// An explicit case on the strip, damped near critically for the mode of frequency omega (rad/s)
// and run for 16 of its periods; `extra` holds the constraints and loads, in which "{ramp}" is
// the end of the 10-period ramp (s).
sf::Model build_case(const std::string& name, double omega, std::string extra,
                     bool turned = false) {
  const double period = 2.0 * std::numbers::pi / omega;
  const std::string ramp = fmt::format("{:.17g}", 10.0 * period);
  for (auto at = extra.find("{ramp}"); at != std::string::npos; at = extra.find("{ramp}")) {
    extra.replace(at, 6, ramp);
  }
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / "constraints_explicit" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "strip.geo") << strip_geo(turned);
  std::ofstream(folder / "case.toml") << fmt::format(R"([blank]
mesh = "strip.geo"
thickness = 2.0
integration_points = 5
material = "steel"
[materials.steel]
type = "elastic"
density = 7.85e-9
young = 210000.0
poisson = 0.0
[control]
end_time = {:.17g}
damping = {:.17g}
)",
                                                     16.0 * period, 2.0 * omega) +
                                             extra;
  return sf::build_model(sf::read_case(folder / "case.toml"));
}

sf::SolutionState run(sf::Model& model, sf::RunSummary* summary = nullptr) {
  sf::RunOptions options;
  options.write_results = false;
  sf::SolutionState s;
  const sf::RunSummary r = sf::run_explicit(model, options, &s);
  if (summary) {
    *summary = r;
  }
  return s;
}

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

constexpr double kPressure = 0.01;  // MPa: q = 0.1 N/mm

// The static solution on diaphragm ends (test_constraints_static.cpp): the element's own error
// -1.6 / n^2 on the bending deflection, exact for its nodal values.
double simply_supported_midspan() {
  const double q = kPressure * kWidth;
  return 5.0 * q * std::pow(kLength, 4) / (384.0 * kYoung * kInertia) *
             (1.0 - 1.6 / (kElements * kElements)) +
         q * kLength * kLength / (8.0 * kShearStiffness);
}

std::string diaphragms(bool turned) {
  const double c = std::cos(std::numbers::pi / 6.0), s = std::sin(std::numbers::pi / 6.0);
  std::string text;
  for (const char* group : {"clamp", "tip"}) {
    text += turned
                ? fmt::format(
                      "[[boundary]]\ngroup = \"{}\"\ntype = \"diaphragm\"\n"
                      "normal = [{:.17g}, {:.17g}, 0.0]\n",
                      group, c, s)
                : fmt::format("[[boundary]]\ngroup = \"{}\"\ntype = \"diaphragm\"\naxis = \"x\"\n",
                              group);
  }
  return text + fmt::format(R"([[load]]
group = "blank"
type = "pressure"
pressure = {}
curve = [[0.0, 0.0], [{{ramp}}, 1.0]]
)",
                            kPressure);
}

TEST(ConstraintsExplicit, DiaphragmEndsSettleOnTheSimplySupportedBeam) {
  sf::Model model = build_case("diaphragm", first_frequency(std::numbers::pi), diaphragms(false));
  sf::RunSummary summary;
  const sf::SolutionState s = run(model, &summary);
  const double w = -mean_at(model, s, 50.0, 2);
  const double expected = simply_supported_midspan();
  std::printf("explicit midspan deflection %.8f mm, static %.8f mm (%+.2e)\n", w, expected,
              w / expected - 1.0);
  // Tolerance 1e-4: what is left of the motion after 6 periods at about critical damping of the
  // first mode (the slow ramp hardly excites the others); measured -8.6e-6.
  EXPECT_NEAR(w / expected, 1.0, 1e-4);
  // Each diaphragm carries half the load (q L / 2 = 5 N), to the same accuracy.
  EXPECT_NEAR(reaction(summary, "boundary[0]").force.z(), 5.0, 5e-3);
  EXPECT_NEAR(reaction(summary, "boundary[1]").force.z(), 5.0, 5e-3);
  // The held components stay at zero: the end nodes neither rise nor move sideways.
  for (const int node : model.blank.group("tip").nodes) {
    EXPECT_EQ(s.x(2, node), model.blank.mesh.nodes(2, node));
    EXPECT_EQ(s.x(1, node), model.blank.mesh.nodes(1, node));
  }
}

TEST(ConstraintsExplicit, TurnedStripWithDiaphragmsByTheirNormalMovesAsTheStraightOne) {
  const double omega = first_frequency(std::numbers::pi);
  sf::Model straight = build_case("diaphragm_straight", omega, diaphragms(false));
  const sf::SolutionState s0 = run(straight);
  sf::Model turned = build_case("diaphragm_turned", omega, diaphragms(true), true);
  EXPECT_EQ(turned.constraints.frames.count(), 4);
  const sf::SolutionState s1 = run(turned);
  ASSERT_EQ(s0.cycle, s1.cycle);
  const double c = std::cos(std::numbers::pi / 6.0), s = std::sin(std::numbers::pi / 6.0);
  const sf::Mat3 turn = (sf::Mat3() << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0).finished();
  double worst = 0.0, largest = 0.0, along = 0.0;
  for (Eigen::Index i = 0; i < s0.x.cols(); ++i) {
    const sf::Vec3 u0 = s0.x.col(i) - straight.blank.mesh.nodes.col(i);
    const sf::Vec3 u1 = turn.transpose() * (s1.x.col(i) - turned.blank.mesh.nodes.col(i));
    worst = std::max(worst, (u1 - u0).norm());
    largest = std::max(largest, u0.norm());
    along = std::max(along, std::abs(u0.x()));
  }
  std::printf(
      "turned strip, %ld cycles: largest difference %.2e of the largest displacement %.4e mm "
      "(axial motion up to %.2e mm)\n",
      s0.cycle, worst / largest, largest, along);
  // The meshes agree to gmsh's round-off (1e-10 mm on 100 mm), which the damped linear response
  // carries through; 1e-8 of the displacement.
  EXPECT_LT(worst, 1e-8 * largest);
}

TEST(ConstraintsExplicit, PrescribedTipDeflectionLandsOnTheCurveWithTheBeamReaction) {
  const double d = 1.5;  // mm
  sf::Model model = build_case("prescribed_tip", first_frequency(1.8751),
                               fmt::format(R"(
[[boundary]]
group = "clamp"
type = "fixed"
[[prescribed_motion]]
group = "tip"
dof = "uz"
curve = [[0.0, 0.0], [{{ramp}}, {}]]
)",
                                           d));
  sf::RunSummary summary;
  const sf::SolutionState s = run(model, &summary);
  for (const int node : model.blank.group("tip").nodes) {
    // Central differences reach the displacement at every step end: d to round-off.
    EXPECT_NEAR(s.x(2, node) - model.blank.mesh.nodes(2, node), d, 1e-12);
  }
  // The linear static reaction (test_constraints_static.cpp): d / (L^3 / (3 E I) (1 - 1/(4 n^2)) +
  // L / (k G A)).
  const double compliance =
      std::pow(kLength, 3) / (3.0 * kYoung * kInertia) * (1.0 - 0.25 / (kElements * kElements)) +
      kLength / kShearStiffness;
  const double expected = d / compliance;
  const sf::ConstraintReaction& r = reaction(summary, "prescribed_motion[0]");
  ASSERT_TRUE(r.along.has_value());
  std::printf("explicit reaction %.6f N, static %.6f N (%+.2e); energy balance %+.2e\n", *r.along,
              expected, *r.along / expected - 1.0, summary.energies.balance_error());
  // Tolerance 1e-3: the motion left after the hold (measured +2.3e-4: the tip's lateral
  // reaction carries the inertia of the clamped-free modes the ramp's corner excites).
  EXPECT_NEAR(*r.along / expected, 1.0, 1e-3);
  // The work of the prescribed motion is the external work: the strain energy R d / 2 plus what
  // damping took; the balance closes to the scheme's second-order error.
  EXPECT_NEAR(summary.energies.external_work,
              summary.energies.internal + summary.energies.hourglass + summary.energies.kinetic +
                  summary.energies.damping,
              1e-3 * summary.energies.external_work);
  EXPECT_NEAR(summary.energies.internal, 0.5 * expected * d, 2e-3 * 0.5 * expected * d);
}

TEST(ConstraintsExplicit, PrescribedTipRotationGivesTheUniformMoment) {
  const double theta = 0.01;  // rad, about -y: the tip lifts
  sf::Model model = build_case("prescribed_rotation", first_frequency(1.8751),
                               fmt::format(R"(
[[boundary]]
group = "clamp"
type = "fixed"
[[prescribed_motion]]
group = "tip"
dof = "ry"
curve = [[0.0, 0.0], [{{ramp}}, {}]]
)",
                                           -theta));
  sf::RunSummary summary;
  const sf::SolutionState s = run(model, &summary);
  const double expected = -kYoung * kInertia * theta / kLength;  // N mm
  const sf::ConstraintReaction& r = reaction(summary, "prescribed_motion[0]");
  ASSERT_TRUE(r.along.has_value());
  const double w = mean_at(model, s, kLength, 2);
  std::printf("explicit moment %.6f N mm (E I theta / L %.6f, %+.2e), tip %.6f mm (%.6f)\n",
              *r.along, expected, *r.along / expected - 1.0, w, 0.5 * theta * kLength);
  // Uniform bending, exact for the element: the tolerance is the motion left, as above
  // (measured 1e-11: a uniform moment excites no mode beyond the ramp's own).
  EXPECT_NEAR(*r.along / expected, 1.0, 1e-4);
  EXPECT_NEAR(w, 0.5 * theta * kLength, 1e-3 * 0.5 * theta * kLength);
}

TEST(ConstraintsExplicit, SpringbackOfTheTurnedStripMatchesTheStraightOneByBothRoutes) {
  // The loaded strips of the tests above, unloaded by the implicit springback (the static step in
  // node axes) and by dynamic relaxation (kinetic damping; the explicit update in node axes):
  // elastic, they come back flat, and the turned one exactly as the straight one.
  const double omega = first_frequency(std::numbers::pi);
  const double c = std::cos(std::numbers::pi / 6.0), s = std::sin(std::numbers::pi / 6.0);
  const sf::Mat3 turn = (sf::Mat3() << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0).finished();
  for (const bool implicit : {true, false}) {
    SCOPED_TRACE(implicit ? "implicit" : "dynamic relaxation");
    sf::Matrix3X back[2];
    double loaded = 0.0;
    for (const bool turned : {false, true}) {
      sf::Model model =
          build_case(fmt::format("springback_{}_{}", implicit ? "implicit" : "relaxation",
                                 turned ? "turned" : "straight"),
                     omega, diaphragms(turned), turned);
      sf::SolutionState state = run(model);
      loaded = std::max(loaded, (state.x - model.blank.mesh.nodes).cwiseAbs().maxCoeff());
      model.loads.pressures.clear();  // the load taken away: what is left springs back
      if (implicit) {
        sf::run_implicit_springback(model, state, nullptr);
      } else {
        sf::SpringbackConfig config;
        config.method = sf::SpringbackConfig::Method::dynamic_relaxation;
        config.release_time = 2.0 * std::numbers::pi / omega;
        config.max_time = 40.0 * config.release_time;
        config.kinetic_tolerance = 1e-10;  // an amplitude of about sqrt(1e-10) = 1e-5 left
        const sf::DynamicRelaxationResult r =
            sf::run_dynamic_relaxation(model, state, nullptr, config);
        EXPECT_TRUE(r.at_rest);
      }
      back[turned] = state.x - model.blank.mesh.nodes;
      if (turned) {
        back[1] = turn.transpose() * back[1];
      }
    }
    // Flat again: the transverse deflection gone to 1e-6 of the loaded one by the static step (an
    // elastic strip; measured 7e-7), to 1e-4 by dynamic relaxation, whose stop rule leaves a
    // kinetic energy of 1e-10 of the internal one, an amplitude of about 1e-5.
    const double z_left =
        std::max(back[0].row(2).cwiseAbs().maxCoeff(), back[1].row(2).cwiseAbs().maxCoeff());
    const double difference = (back[1] - back[0]).cwiseAbs().maxCoeff();
    std::printf(
        "after springback: deflection %.2e of the loaded %.4e mm; turned - straight %.2e mm\n",
        z_left / loaded, loaded, difference);
    EXPECT_LT(z_left, (implicit ? 1e-6 : 1e-4) * loaded);
    // The same to round-off carried through the two runs: 1e-8 of the loaded deflection.
    EXPECT_LT(difference, 1e-8 * loaded);
  }
}

}  // namespace
