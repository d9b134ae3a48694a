// What check and the run banner print about a model: the element formulation the shell part
// holds, and where each pressure load pushes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "casefile/case_config.hpp"
#include "model/build_model.hpp"
#include "model/external_loads.hpp"
#include "solver/model_report.hpp"

namespace fs = std::filesystem;

namespace {

// An elastic strip of a tests/data mesh with `extra` appended (loads, [control]).
sf::Model build(const std::string& name, const std::string& mesh, const std::string& extra) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "case.toml")
      << "[blank]\nmesh = \"" << (fs::path(SF_TEST_DATA_DIR) / mesh).string()
      << "\"\nelement = \"as_meshed\"\nthickness = 2.0\nmaterial = \"steel\"\n"
         "[materials.steel]\ntype = \"elastic\"\ndensity = 7.85e-9\nyoung = 210000.0\n"
         "poisson = 0.3\n"
      << extra << "[control]\nend_time = 1.0\n";
  return sf::build_model(sf::read_case(folder / "case.toml"));
}

TEST(ModelReport, FormulationIsWhatTheShellPartHolds) {
  const sf::Model model = build("report_strip", "strip.geo", "");
  // Assumed strain (the default): the same in explicit and static analyses.
  sf::ShellPart as = model.blank.part;
  EXPECT_EQ(as.formulation, sf::ShellFormulation::assumed_strain);
  const std::string assumed_strain =
      "20 assumed-strain quadrilaterals (one in-plane point, directors, MITC4 transverse shear, "
      "physical hourglass stabilisation); 5 Gauss points through the thickness";
  EXPECT_EQ(sf::describe_shell_formulation(as, false), assumed_strain);
  EXPECT_EQ(sf::describe_shell_formulation(as, true), assumed_strain);
  sf::ShellPart triangles = as;  // a part of triangles only
  triangles.quads.resize(4, 0);
  triangles.triangles.resize(3, 2);
  triangles.section = sf::make_section(3, sf::ThroughThicknessRule::lobatto);
  EXPECT_EQ(sf::describe_shell_formulation(triangles, false),
            "2 assumed-strain triangles (directors, DSG3 transverse shear); 3 Lobatto points "
            "through the thickness");

  // Belytschko-Tsay with its default viscous form, coefficient 0.1.
  sf::ShellPart bt = model.blank.part;
  bt.formulation = sf::ShellFormulation::belytschko_tsay;
  EXPECT_EQ(sf::describe_shell_formulation(bt, false),
            "20 Belytschko-Lin-Tsay quadrilaterals (one in-plane point, viscous hourglass "
            "control, coefficient 0.1); 5 Gauss points through the thickness");
  // The static step replaces the viscous form by the stiffness form, and says so.
  EXPECT_EQ(sf::describe_shell_formulation(bt, true),
            "20 Belytschko-Lin-Tsay quadrilaterals (one in-plane point, stiffness hourglass "
            "control, coefficient 0.1; the case's viscous form has no static stiffness); 5 Gauss "
            "points through the thickness");
  bt.quads.resize(4, 0);
  bt.triangles.resize(3, 2);
  bt.section = sf::make_section(3, sf::ThroughThicknessRule::lobatto);
  EXPECT_EQ(sf::describe_shell_formulation(bt, false),
            "2 C0 triangles (DSG3 transverse shear); 3 Lobatto points through the thickness");
}

TEST(ModelReport, PressureDirectionOfAFlatStrip) {
  // strip.geo is meshed counter-clockwise seen from +z: its top side faces +z, and a positive
  // pressure on it pushes along -z with the resultant p x 100 x 10 mm^2.
  const sf::Model model = build("report_pressure", "strip.geo",
                                "[[load]]\ngroup = \"blank\"\ntype = \"pressure\"\npressure = "
                                "0.3\n[[load]]\ngroup = \"blank\"\ntype = \"pressure\"\n"
                                "pressure = -0.5\n");
  ASSERT_EQ(model.loads.pressures.size(), 2u);
  const sf::PressureDirection d =
      sf::compute_pressure_direction(model, model.loads.pressures[0], model.blank.mesh.nodes);
  EXPECT_NEAR(d.area, 1000.0, 1e-9);  // mm^2
  EXPECT_EQ(d.top_normal, sf::Vec3(0.0, 0.0, 1.0));
  EXPECT_EQ(d.push, sf::Vec3(0.0, 0.0, -1.0));
  EXPECT_NEAR(d.resultant.z(), -300.0, 1e-9);  // N
  EXPECT_EQ(d.resultant.x(), 0.0);
  // A suction (negative pressure) pulls the top side outward: along +z.
  const sf::PressureDirection suction =
      sf::compute_pressure_direction(model, model.loads.pressures[1], model.blank.mesh.nodes);
  EXPECT_EQ(suction.push, sf::Vec3(0.0, 0.0, 1.0));
  EXPECT_NEAR(suction.resultant.z(), 500.0, 1e-9);
  // The resultant is the sum of the nodal pressure forces the loop applies (at full value).
  sf::Matrix3X f(3, model.blank.mesh.nodes.cols()), m(3, model.blank.mesh.nodes.cols());
  sf::Model only_first =
      build("report_pressure_one", "strip.geo",
            "[[load]]\ngroup = \"blank\"\ntype = \"pressure\"\npressure = 0.3\n");
  sf::compute_external_forces(only_first, 0.0, only_first.blank.mesh.nodes, f, m);
  EXPECT_NEAR(f.row(2).sum(), d.resultant.z(), 1e-9);
}

}  // namespace
