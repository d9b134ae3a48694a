// A blank of quadrilaterals and triangles, end to end: gmsh meshes tests/data/mixed_strip.geo as
// written (blank.element = "as_meshed"), build_model takes both element types, the explicit loop
// runs a few hundred cycles under a pressure on every element, the energy balance holds, and the
// results (one XDMF "Mixed" topology) are read by ParaView when it is installed.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "casefile/case_config.hpp"
#include "model/build_model.hpp"
#include "solver/explicit_driver.hpp"

namespace fs = std::filesystem;

namespace {

sf::Model build_mixed_case(const fs::path& folder, const std::string& element) {
  fs::create_directories(folder);
  std::ofstream(folder / "case.toml") << R"(
[blank]
mesh = ")" + (fs::path(SF_TEST_DATA_DIR) / "mixed_strip.geo").string() +
                                             R"("
element = ")" + element + R"("
thickness = 1.0
integration_points = 5
material = "steel"
[materials.steel]
type = "elastic"
density = 7.85e-9
young = 210000.0
poisson = 0.3
[[boundary]]
group = "clamp"
type = "fixed"
[[load]]
group = "blank"
type = "pressure"
pressure = 0.01
curve = [[0.0, 0.0], [2.0e-4, 1.0]]
[control]
end_time = 2.4e-4
output_frames = 4
)";
  return sf::build_model(sf::read_case(folder / "case.toml"));
}

TEST(MixedBlank, QuadsAndTrianglesRunWithTheEnergyBalance) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / "mixed_blank";
  fs::remove_all(folder);
  sf::Model model = build_mixed_case(folder, "as_meshed");
  // The .geo's own commands: surface 1 recombined (10 x 2 quads), surface 2 not (40 triangles).
  ASSERT_EQ(model.blank.part.quads.cols(), 20);
  ASSERT_EQ(model.blank.part.triangles.cols(), 40);
  ASSERT_EQ(model.blank.mesh.nodes.cols(), 63);
  // One orientation for both element types (extract_part_mesh orients quads and triangles
  // together): every normal along the same side of the z = 0 plane.
  const sf::Matrix3X& x0 = model.blank.mesh.nodes;
  const sf::QuadConn& quads = model.blank.part.quads;
  const sf::TriConn& triangles = model.blank.part.triangles;
  int up = 0;
  for (Eigen::Index e = 0; e < quads.cols(); ++e) {
    const sf::Vec3 n = (x0.col(quads(2, e)) - x0.col(quads(0, e)))
                           .cross(x0.col(quads(3, e)) - x0.col(quads(1, e)));
    up += n.z() > 0.0 ? 1 : -1;
  }
  for (Eigen::Index k = 0; k < triangles.cols(); ++k) {
    const sf::Vec3 n = (x0.col(triangles(1, k)) - x0.col(triangles(0, k)))
                           .cross(x0.col(triangles(2, k)) - x0.col(triangles(0, k)));
    up += n.z() > 0.0 ? 1 : -1;
  }
  EXPECT_EQ(std::abs(up), 60);
  // Every element of the group carries the pressure (quads first, then triangles).
  ASSERT_EQ(model.loads.pressures.size(), 1u);
  EXPECT_EQ(model.loads.pressures[0].elements.size(), 60u);
  // Mass: rho t A for the whole strip (1e-12 relative), quads and triangles both counted.
  EXPECT_NEAR(model.blank.mass.sum() / (7.85e-9 * 1.0 * 1000.0), 1.0, 1e-12);
  // The triangles (smallest altitude 5 / sqrt 2 = 3.54 mm < 5 mm quads) limit the step.
  EXPECT_GE(model.time.limiting_element, 20);
  const double c = std::sqrt(210000.0 / (7.85e-9 * (1.0 - 0.09)));
  // dt = 0.9 h_min / c; 1e-9 relative: gmsh's transfinite node coordinates carry round-off of
  // ~1e-11 mm (measured 5.9e-12 relative).
  EXPECT_NEAR(model.time.time_step / (0.9 * 5.0 / std::sqrt(2.0) / c), 1.0, 1e-9);

  sf::RunOptions options;
  options.output_directory = folder / "results";
  const sf::RunSummary summary = sf::run_explicit(model, options);
  std::printf(
      "mixed blank: %ld cycles, internal %.4e N mm, external work %.4e N mm, kinetic %.4e, "
      "balance error %.2e\n",
      summary.cycles, summary.energies.internal, summary.energies.external_work,
      summary.energies.kinetic, summary.energies.balance_error());
  EXPECT_GE(summary.cycles, 300);
  EXPECT_EQ(summary.elements, 60);
  EXPECT_GT(summary.energies.external_work, 0.0);
  EXPECT_GT(summary.energies.internal, 0.0);
  EXPECT_EQ(summary.energies.hourglass, summary.energies.hourglass);  // finite
  // Undamped elastic run, trapezoidal work increments, kinetic energy at the step end: the
  // residual is the change of the half-kick energy dt^2/8 F.M^-1.F (docs/time-integration.md),
  // second order. Measured 3.9e-6 here and 7.8e-6 for the same case meshed with quads only
  // (element = "quad": 40 quads, 292 cycles); the kinetic energy at the half step, which lags the
  // work in this accelerating transient (kinetic / internal = 17 at the end), gave -9.0e-4 and
  // -1.56e-3. The bound 2e-5 asks the triangles to do no worse than the quads, and would catch a
  // first-order slip in the accounting.
  EXPECT_LT(std::abs(summary.energies.balance_error()), 2e-5);

  // ParaView reads the mixed topology: 63 points, 60 cells (20 quads + 40 triangles), 5 frames.
  if (!fs::exists("/usr/bin/pvpython")) {
    GTEST_SKIP() << "ParaView is not installed (/usr/bin/pvpython missing); CI installs it";
  }
  // The frame times as written (round-trip text in the .xdmf): 5 frames, 0 to the end time.
  std::ifstream xdmf(folder / "results" / "blank.xdmf");
  std::stringstream xdmf_stream;
  xdmf_stream << xdmf.rdbuf();
  const std::string xdmf_text = xdmf_stream.str();
  const std::regex time_value("<Time Value=\"([^\"]+)\"/>");
  std::string times;
  int frames = 0;
  for (auto it = std::sregex_iterator(xdmf_text.begin(), xdmf_text.end(), time_value);
       it != std::sregex_iterator(); ++it) {
    times += ' ';
    times += (*it)[1].str();
    ++frames;
  }
  EXPECT_EQ(frames, 5);
  EXPECT_NE(xdmf_text.find("TopologyType=\"Mixed\" NumberOfElements=\"60\""), std::string::npos);
  const fs::path log = folder / "check_xdmf.log";
  const std::string command = "cd / && /usr/bin/pvpython '" SF_SOURCE_DIR
                              "/scripts/check_xdmf.py' '" +
                              (folder / "results" / "blank.xdmf").string() + "' --times" + times +
                              " --points 63 --cells 60"
                              " --point-arrays displacement:3 velocity:3 contact_force:3"
                              " --cell-arrays thickness:1 plastic_strain:1 stress_mid:6"
                              " stress_top:6 stress_bottom:6 major_strain_bottom:1"
                              " minor_strain_bottom:1 major_strain_mid:1 minor_strain_mid:1"
                              " major_strain_top:1 minor_strain_top:1 thinning_percent:1"
                              " flc_margin:1 formability_zone:1 wrinkle_indicator:1 > '" +
                              log.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command << "\n" << text.str();
}

TEST(MixedBlank, QuadElementRecombinesTheWholeGeo) {
  // blank.element = "quad" (the default) recombines every surface of a .geo: the same file gives
  // quadrilaterals only (gmsh recombines the transfinite triangle pairs: 40 quads).
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / "mixed_blank_quad";
  const sf::Model model = build_mixed_case(folder, "quad");
  EXPECT_EQ(model.blank.part.quads.cols(), 40);
  EXPECT_EQ(model.blank.part.triangles.cols(), 0);
}

}  // namespace
