// A blank of several parts (a tailor-welded blank, [[blank.parts]]): each part's thickness and
// material, against closed forms on a strip welded across (tests/data/twb_strip.geo: x in
// [0, 40] the "inner" part, [40, 100] the "outer", one row of 5 mm quads, nu = 0):
// - tension: the weld and the tip move by the two bars in series, F L_i / (E_i b t_i);
// - pure bending: each part bends at its own curvature M / (E_i I_i), I_i = b t_i^3 / 12;
// - the masses rho_i t_i A_i, the stable step of the faster material's elements;
// - two parts of one thickness and material give the one-part blank's bits (explicit run);
// - the errors: a missing group, an element in no part, a weld meshed twice, keys in the wrong
//   table.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "element/corner_forces.hpp"
#include "element/shell_mass.hpp"
#include "model/blank_parts.hpp"
#include "model/build_model.hpp"
#include "solver/case_fixture.hpp"
#include "solver/initial_state.hpp"
#include "solver/static_driver.hpp"
#include "support/expect_input_error.hpp"

namespace {

namespace fs = std::filesystem;

constexpr double kWeld = 40.0;                             // mm, the weld's x
constexpr double kLength = 100.0;                          // mm
constexpr double kWidth = 10.0;                            // mm
constexpr double kInnerT = 1.2;                            // mm
constexpr double kOuterT = 0.8;                            // mm
constexpr double kSteelE = 210000.0, kSteelRho = 7.85e-9;  // MPa, tonne/mm^3
constexpr double kAluE = 70000.0, kAluRho = 2.7e-9;

const std::string kMaterials = R"(
[materials.steel]
type = "elastic"
density = 7.85e-9
young = 210000.0
poisson = 0.0
[materials.aluminium]
type = "elastic"
density = 2.7e-9
young = 70000.0
poisson = 0.0
)";

std::string part_table(const std::string& name, double thickness, const std::string& material) {
  return fmt::format(
      "[[blank.parts]]\nname = \"{0}\"\ngroup = \"{0}\"\nthickness = {1}\n"
      "material = \"{2}\"\n",
      name, thickness, material);
}

// The inner part steel at 1.2 mm, the outer aluminium at 0.8 mm.
std::string steel_aluminium_parts() {
  return part_table("inner", kInnerT, "steel") + part_table("outer", kOuterT, "aluminium");
}

// Writes a case on a mesh of tests/data and reads it: `blank` goes into [blank] after its mesh
// key, `rest` after the materials.
sf::CaseConfig strip_case(const std::string& name, const std::string& blank,
                          const std::string& rest, const std::string& mesh = "twb_strip.geo") {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "case.toml")
      << "[blank]\nmesh = \"" << (fs::path(SF_TEST_DATA_DIR) / mesh).string() << "\"\n"
      << blank << kMaterials << "[[boundary]]\ngroup = \"clamp\"\ntype = \"fixed\"\n"
      << rest;
  return sf::read_case(folder / "case.toml");
}

const std::string kStaticLinear = R"(
[control]
end_time = 1.0
[analysis]
type = "static"
geometry = "linear"
)";

std::string tip_load(const std::string& type, double x, double y, double z) {
  return fmt::format("[[load]]\ngroup = \"tip\"\ntype = \"{}\"\nvalue = [{}, {}, {}]\n", type, x, y,
                     z);
}

sf::SolutionState solve_static(sf::Model& model) {
  sf::RunOptions options;
  options.write_results = false;
  sf::SolutionState s;
  sf::run_static(model, options, &s);
  return s;
}

// The mean displacement component of a node group's nodes (mm).
double mean_displacement(const sf::Model& model, const sf::SolutionState& s,
                         const std::string& group, int component) {
  const auto& nodes = model.blank.group(group).nodes;
  double sum = 0.0;
  for (const int node : nodes) {
    sum += s.x(component, node) - model.blank.mesh.nodes(component, node);
  }
  return sum / static_cast<double>(nodes.size());
}

TEST(TailorWelded, PartsHoldTheirElementsThicknessAndMaterial) {
  const sf::Model model =
      sf::build_model(strip_case("twb_parts", steel_aluminium_parts(),
                                 "[control]\nend_time = 1e-4\n[[history]]\ngroup = \"weld\"\n"));
  ASSERT_EQ(model.blank.parts.size(), 2u);
  EXPECT_EQ(model.blank.parts[0].name, "inner");
  const sf::ShellPart& part = model.blank.part;
  ASSERT_EQ(element_count(part), 20);
  // The inner part (8 elements, surface 2 in the file) comes first: sorted by the case's order.
  for (int e = 0; e < 20; ++e) {
    const int expected = e < 8 ? 0 : 1;
    EXPECT_EQ(sf::material_index(part, e), expected) << "element " << e;
    EXPECT_EQ(model.initial.element_thickness[static_cast<std::size_t>(e)],
              expected == 0 ? kInnerT : kOuterT);
    double centre = 0.0;
    for (int a = 0; a < 4; ++a) {
      centre += 0.25 * model.blank.mesh.nodes(0, part.quads(a, e));
    }
    EXPECT_EQ(centre < kWeld, expected == 0) << "element " << e << " at x = " << centre;
  }
  // Masses: rho_i t_i A_i per part (exact up to round-off).
  const double mass =
      kSteelRho * kInnerT * kWeld * kWidth + kAluRho * kOuterT * (kLength - kWeld) * kWidth;
  EXPECT_NEAR(model.blank.physical_mass / mass, 1.0, 1e-13);
  // The stable step: L / c with L = 5 mm (a square's area / its side), c the plate wave speed of
  // the faster material, steel (sqrt(E / rho) 5.17e6 mm/s against aluminium's 5.09e6).
  const sf::ShellState state = sf::make_blank_shell_state(model.blank, model.initial);
  const sf::StableStep step = sf::compute_stable_time_step(part, model.blank.mesh.nodes, state);
  // (1e-11: the nodes' x from gmsh's transfinite interpolation differ from multiples of 5 mm in
  // the last digits, 1.5e-12 relative here.)
  EXPECT_NEAR(step.dt / (5.0 / std::sqrt(kSteelE / kSteelRho)), 1.0, 1e-11);
  EXPECT_LT(step.element, 8);
  // The contact offset: half an element's own thickness, the mean of two at a weld node.
  sf::VectorX half(model.blank.mesh.nodes.cols());
  sf::gather_half_thickness(model.blank.node_corners, state.thickness,
                            model.blank.inverse_element_count, half);
  for (Eigen::Index i = 0; i < half.size(); ++i) {
    const double x = model.blank.mesh.nodes(0, i);
    const double expected = std::abs(x - kWeld) < 1e-9 ? 0.25 * (kInnerT + kOuterT)
                            : x < kWeld                ? 0.5 * kInnerT
                                                       : 0.5 * kOuterT;
    EXPECT_NEAR(half[i], expected, 1e-14) << "node at x = " << x;
  }
}

TEST(TailorWelded, TensionMovesTheWeldAndTheTipAsTwoBarsInSeries) {
  const double force = 100.0;  // N, half on each of the two tip nodes
  sf::Model model =
      sf::build_model(strip_case("twb_tension", steel_aluminium_parts(),
                                 tip_load("force", 0.5 * force, 0.0, 0.0) +
                                     "[[history]]\ngroup = \"weld\"\n" + kStaticLinear));
  const sf::SolutionState s = solve_static(model);
  // Uniform stress F / (b t_i) in each part (nu = 0: nothing restrains the width): exact for the
  // elements, so only the linear solve's round-off remains.
  const double weld = force * kWeld / (kSteelE * kWidth * kInnerT);
  const double tip = weld + force * (kLength - kWeld) / (kAluE * kWidth * kOuterT);
  EXPECT_NEAR(mean_displacement(model, s, "weld", 0) / weld, 1.0, 1e-9);
  EXPECT_NEAR(mean_displacement(model, s, "tip", 0) / tip, 1.0, 1e-9);
  // The thinner, softer part stretches more: the tip moves 7.7 times the weld here, where one
  // material and thickness would give 2.5.
  EXPECT_GT(mean_displacement(model, s, "tip", 0) / mean_displacement(model, s, "weld", 0), 7.0);
}

TEST(TailorWelded, PureBendingGivesEachPartItsOwnCurvature) {
  const double moment = 1.0;  // N mm about -y in total: the tip bends up (+z) by 2e-3 rad
  sf::Model model =
      sf::build_model(strip_case("twb_bending", steel_aluminium_parts(),
                                 tip_load("moment", 0.0, -0.5 * moment, 0.0) +
                                     "[[history]]\ngroup = \"weld\"\n" + kStaticLinear));
  const sf::SolutionState s = solve_static(model);
  const double inner_i = kWidth * std::pow(kInnerT, 3) / 12.0;  // mm^4
  const double outer_i = kWidth * std::pow(kOuterT, 3) / 12.0;
  const double kappa_inner = moment / (kSteelE * inner_i);  // 1/mm
  const double kappa_outer = moment / (kAluE * outer_i);
  const double outer = kLength - kWeld;
  const double w_weld = 0.5 * kappa_inner * kWeld * kWeld;
  const double w_tip = w_weld + kappa_inner * kWeld * outer + 0.5 * kappa_outer * outer * outer;
  // The strip falls short of the beam by 2.3e-8 (weld) and 1.8e-8 (tip) relative, the same at
  // 100 times the moment and, 2.2e-8 at the weld, when both parts are steel of 1.2 mm: the
  // element's own deviation on this strip, not the parts'. 1e-7 bounds it; a part's wrong
  // thickness or material would be off by tens of percent.
  EXPECT_NEAR(mean_displacement(model, s, "weld", 2) / w_weld, 1.0, 1e-7);
  EXPECT_NEAR(mean_displacement(model, s, "tip", 2) / w_tip, 1.0, 1e-7);
}

// Two parts of one thickness and material are the one-part blank: the same bits after an
// explicit run (the element loops split their runs at the parts' boundary; each element's work
// is its own, and the sums are exact).
TEST(TailorWelded, TwoEqualPartsGiveTheOnePartBlanksBits) {
  const std::string run = tip_load("force", 0.0, 0.0, 0.5) + "[control]\nend_time = 2e-4\n";
  // Parts listed in the file's order, so that sorting leaves the elements where they were.
  const std::string parts = part_table("outer", 1.0, "steel") + part_table("inner", 1.0, "steel");
  sf::Model two = sf::build_model(strip_case("twb_equal_parts", parts, run));
  sf::Model one =
      sf::build_model(strip_case("twb_one_part", "thickness = 1.0\nmaterial = \"steel\"\n", run));
  ASSERT_EQ(two.blank.part.quads, one.blank.part.quads);
  ASSERT_FALSE(two.blank.part.element_material.empty());
  sf::SolutionState a = sf::make_initial_state(two);
  sf::SolutionState b = sf::make_initial_state(one);
  sf::compute_forces(two, a, 0.0);
  sf::compute_forces(one, b, 0.0);
  sf::test::run_to_end(two, a, [](const sf::SolutionState&) {});
  sf::test::run_to_end(one, b, [](const sf::SolutionState&) {});
  ASSERT_GT(a.cycle, 100);
  EXPECT_EQ(a.cycle, b.cycle);
  EXPECT_TRUE(a.x == b.x) << "max difference " << (a.x - b.x).cwiseAbs().maxCoeff() << " mm";
  EXPECT_EQ(a.shell.sxx, b.shell.sxx);
  EXPECT_EQ(a.energies.internal, b.energies.internal);
}

using sf::test::expect_input_error;

TEST(TailorWelded, RefusesPartsThatDoNotMakeTheBlank) {
  const std::string control = "[control]\nend_time = 1e-4\n";
  // A group the mesh does not have.
  expect_input_error(
      [&] {
        sf::build_model(strip_case(
            "twb_missing_group",
            part_table("inner", 1.0, "steel") + part_table("middle", 1.0, "steel"), control));
      },
      {"blank.parts[1]", "'middle'", "no 2-D physical group", "inner (2-D)"});
  // The outer part's elements in no part.
  expect_input_error(
      [&] {
        const std::string parts = part_table("inner", 1.0, "steel") +
                                  "[[blank.parts]]\nname = \"all\"\ngroup = \"inner\"\n"
                                  "thickness = 1.0\nmaterial = \"steel\"\n";
        sf::build_model(strip_case("twb_no_part", parts, control));
      },
      {"blank.parts[1].group", "no other part has"});
  expect_input_error(
      [&] {
        const std::string parts = part_table("inner", 1.0, "steel") +
                                  "[[blank.parts]]\nname = \"all\"\ngroup = \"blank\"\n"
                                  "thickness = 1.0\nmaterial = \"steel\"\n";
        sf::build_model(strip_case("twb_two_parts", parts, control));
      },
      {"blank.parts[1]", "is also in part 'inner'"});
  // The weld meshed twice: the parts are not joined.
  expect_input_error(
      [&] {
        sf::build_model(
            strip_case("twb_unjoined", steel_aluminium_parts(), control, "twb_strip_unjoined.geo"));
      },
      {"blank.parts: gmsh nodes", "not joined", "share the nodes of their weld line"});
}

TEST(TailorWelded, RefusesKeysInTheWrongTable) {
  const std::string control = "[control]\nend_time = 1e-4\n";
  expect_input_error(
      [&] {
        strip_case("twb_thickness_too", "thickness = 1.0\n" + steel_aluminium_parts(), control);
      },
      {"blank.thickness", "[[blank.parts]]"});
  expect_input_error([&] { strip_case("twb_one", part_table("inner", 1.0, "steel"), control); },
                     {"blank.parts", "two or more"});
  expect_input_error(
      [&] {
        strip_case("twb_bad_material",
                   part_table("inner", 1.0, "steel") + part_table("outer", 1.0, "titanium"),
                   control);
      },
      {"blank.parts[1].material", "\"titanium\"", "\"steel\""});
  expect_input_error(
      [&] {
        strip_case("twb_same_name",
                   part_table("inner", 1.0, "steel") + part_table("inner", 1.0, "steel"), control);
      },
      {"blank.parts[1].name", "taken"});
}

}  // namespace
