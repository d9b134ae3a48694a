// Springback after forming (issue: implicit static step), on a strip bent in three points by a
// rigid punch between two rigid supports (tests/data/bend_strip.geo, bend_tools.geo):
// - an ELASTIC strip, bent and released by the implicit step, springs back flat: nothing in it
//   can keep a curvature, so the released shape is the initial plane (moved rigidly at most);
// - an elastic-plastic strip keeps a bend, smaller than the formed one;
// - the frames of the springback follow the forming frames in the same results, with the
//   springback displacement field.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "model/build_model.hpp"
#include "results/hdf5_file.hpp"
#include "solver/explicit_driver.hpp"

namespace {

namespace fs = std::filesystem;

sf::Model build_bend_case(const std::string& name, const std::string& material,
                          const std::string& springback, double stroke = 5.0) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / name;
  fs::create_directories(folder);
  const std::string data = fs::path(SF_TEST_DATA_DIR).string();
  std::ofstream(folder / "case.toml") << R"([blank]
mesh = ")" + data + R"(/bend_strip.geo"
thickness = 1.0
material = "steel"
formulation = "belytschko_tsay"
hourglass_form = "stiffness"
[materials.steel]
density = 7.85e-9
young = 210000.0
poisson = 0.3
)" + material + R"(
[[tools]]
name = "punch"
mesh = ")" + data + R"(/bend_tools.geo"
group = "punch"
[tools.motion]
type = "velocity"
direction = [0.0, 0.0, -1.0]
curve = [[0.0, 0.0], [0.0005, 2000.0]]
[[tools]]
name = "support"
mesh = ")" + data + R"(/bend_tools.geo"
group = "support"
[[contact]]
tool = "punch"
[[contact]]
tool = "support"
[[boundary]]
group = "sym_x"
type = "symmetry"
axis = "x"
[[boundary]]
group = "sym_y"
type = "symmetry"
axis = "y"
[control]
stroke = )" + std::to_string(stroke) + R"(
output_frames = 4
)" + springback;
  return sf::build_model(sf::read_case(folder / "case.toml"));
}

// The largest distance (mm) of a node from the mean plane z = const, and the largest in-plane
// distance from the initial position.
struct Flatness {
  double out_of_plane = 0.0;
  double in_plane = 0.0;
};

Flatness flatness(const sf::Model& model, const sf::Matrix3X& x) {
  const double z_mean = x.row(2).mean();
  Flatness f;
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    f.out_of_plane = std::max(f.out_of_plane, std::abs(x(2, i) - z_mean));
    f.in_plane =
        std::max(f.in_plane, (x.col(i).head<2>() - model.blank.mesh.nodes.col(i).head<2>()).norm());
  }
  return f;
}

TEST(Springback, ElasticStripSpringsBackFlat) {
  // Stroke 1 mm: the strip bends elastically (largest strain about 0.1 %).
  sf::Model model =
      build_bend_case("springback_elastic", "type = \"elastic\"\n", "[springback]\n", 1.0);
  sf::RunOptions options;
  options.write_results = false;
  sf::SolutionState s;
  const sf::RunSummary summary = sf::run_explicit(model, options, &s);
  ASSERT_TRUE(summary.springback.has_value());
  const sf::SpringbackSummary& sb = *summary.springback;
  ASSERT_TRUE(sb.implicit.has_value());
  EXPECT_GT(sb.max_displacement, 1.0);  // the formed deflection comes back
  const Flatness f = flatness(model, s.x);
  std::printf(
      "springback %.4f mm; after it: out of plane %.3e mm, in plane %.3e mm; %d "
      "increments, %d iterations, %s\n",
      sb.max_displacement, f.out_of_plane, f.in_plane, sb.implicit->report.converged_increments,
      sb.implicit->report.newton_iterations,
      sf::method_name(sb.implicit->report.last_factorization.method));
  // Flat and back in place, but not to round-off: the shell's stress update is a rate form in
  // the corotational frame (hypoelastic), which is not exactly integrable over the forming path
  // with its rotations and vibrations. Measured: 1.0e-4 of the springback at this 1 mm stroke,
  // 3.6e-4 at 2 mm (the strip wraps the punch). The static step alone is reversible to 3e-11
  // (StaticAnalysis.ElasticLoadAndUnloadReturnsFlat). With the viscous hourglass form the
  // forming would also leave a frozen hourglass zig-zag of 4e-4 of the springback, which the
  // static step (stiffness form from zero) cannot undo: springback cases use the stiffness
  // form (docs/static-analysis.md).
  EXPECT_LT(f.out_of_plane, 3e-4 * sb.max_displacement);
  EXPECT_LT(f.in_plane, 3e-4 * sb.max_displacement);
  // The case's symmetry leaves the translation along z free: one hold was added.
  EXPECT_EQ(sb.implicit->added_constraints.size(), 1u);
}

TEST(Springback, PlasticStripKeepsPartOfItsBendAndFramesFollowInTheResults) {
  sf::Model model = build_bend_case("springback_plastic",
                                    "type = \"von_mises\"\n[materials.steel.hardening]\n"
                                    "law = \"linear\"\nyield_stress = 200.0\nmodulus = 1000.0\n",
                                    "[springback]\n[implicit]\nincrements = 2\n");
  sf::RunOptions options;
  options.output_directory =
      fs::path(SF_BINARY_DIR) / "test_output" / "springback_plastic" / "results";
  sf::SolutionState s;
  const sf::RunSummary summary = sf::run_explicit(model, options, &s);
  ASSERT_TRUE(summary.springback.has_value());
  const Flatness f = flatness(model, s.x);
  // It stays bent (a permanent set of the order of the stroke) but springs back by a part of it.
  EXPECT_GT(f.out_of_plane, 0.5);
  EXPECT_GT(summary.springback->max_displacement, 0.05);
  // Results: 4 forming frames + the initial one, then one per converged springback increment,
  // each with springback_displacement; the last one equals x - x_formed.
  sf::h5::File file(options.output_directory / "results.h5", sf::h5::FileMode::read_only);
  const int increments = summary.springback->implicit->report.converged_increments;
  const auto frame = [](int k) { return fmt::format("/parts/blank/frames/{:06d}/", k); };
  const std::vector<double> d =
      file.read_doubles(frame(4 + increments) + "springback_displacement");
  ASSERT_EQ(d.size(), static_cast<std::size_t>(3 * s.x.cols()));
  double largest = 0.0;
  for (std::size_t i = 0; i < d.size() / 3; ++i) {
    largest = std::max(largest, std::sqrt(d[3 * i] * d[3 * i] + d[3 * i + 1] * d[3 * i + 1] +
                                          d[3 * i + 2] * d[3 * i + 2]));
  }
  EXPECT_NEAR(largest, summary.springback->max_displacement, 1e-12);
  const std::vector<double> formed = file.read_doubles(frame(4) + "springback_displacement");
  for (double v : formed) {
    ASSERT_EQ(v, 0.0);
  }
}

}  // namespace
