// A drawn part trimmed and drawn on (issue 32, item 3, work in progress): the square cup drawn to
// 2 mm, its flange's outer ring trimmed off (solver/trim.hpp), the model built from the trimmed
// part's own mesh (build_model with a BlankMesh) and the draw continued from the trimmed part's
// state to 3 mm.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include "casefile/case_config.hpp"
#include "model/build_model.hpp"
#include "solver/explicit_driver.hpp"
#include "solver/formed_part.hpp"
#include "solver/trim.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

fs::path output_folder(const std::string& name) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / "trim_chain" / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

CaseConfig cup(double stroke) {
  // The draw-in probes sit on the blank's outer edge, which the trim takes away.
  return read_case(
      fs::path(SF_SOURCE_DIR) / "cases/square_cup_aluminium/case.toml",
      CaseOptions{.set = {"draw_in=[]"}, .stroke = stroke, .end_time = {}, .search = {}});
}

BlankMesh mesh_of(const FormedPart& part) {
  BlankMesh b;
  b.mesh.name = "blank";
  b.mesh.nodes = part.reference_nodes;
  for (double tag : part.node_tags) {
    b.mesh.gmsh_node_tags.push_back(static_cast<std::size_t>(tag));
  }
  b.mesh.quads = part.quads;
  b.mesh.triangles = part.triangles;
  for (const auto& [name, nodes] : part.groups) {
    b.groups.push_back({name, nodes});
  }
  b.source = part.file;
  return b;
}

TEST(TrimChain, ADrawTrimmedAndDrawnOn) {
  const fs::path first = output_folder("draw");
  RunOptions options;
  options.output_directory = first;
  options.checkpoints = false;
  const Model drawn = build_model(cup(2.0));
  run_explicit(drawn, options);
  const FormedPart part = read_formed_part(formed_part_path(first));

  // Keep what lies within 60 mm of the symmetry planes (the blank reaches 75 mm).
  TrimSummary summary;
  const TrimOutline keep{
      {Vec3(-1.0, -1.0, 0.0), Vec3(60.0, -1.0, 0.0), Vec3(60.0, 60.0, 0.0), Vec3(-1.0, 60.0, 0.0)},
      Vec3(0.0, 0.0, -1.0),
      true};
  auto trimmed = std::make_shared<const FormedPart>(trim_by_removal(part, keep, &summary));
  EXPECT_GT(summary.elements_removed, 0);
  EXPECT_EQ(summary.piece_elements.size(), 1u);
  const BlankMesh mesh = mesh_of(*trimmed);
  const Model model = build_model(cup(3.0), &mesh);
  EXPECT_EQ(model.blank.mesh.nodes.cols(), trimmed->reference_nodes.cols());
  // Uniform sheet: the mass goes with the area kept.
  EXPECT_LT(model.blank.physical_mass, drawn.blank.physical_mass);

  RunOptions on;
  on.output_directory = output_folder("drawn_on");
  on.checkpoints = false;
  on.start_part = trimmed;
  SolutionState s;
  run_explicit(model, on, &s);
  EXPECT_NEAR(s.tools[0].travel, 3.0, 1e-9);
  EXPECT_GT(s.time, trimmed->fields.at("time")[0]);
  // Every kept element's plastic strain came with it and only grew.
  const std::vector<double>& before = trimmed->fields.at("shell/eps_p");
  ASSERT_EQ(before.size(), s.shell.eps_p.size());
  for (std::size_t k = 0; k < before.size(); ++k) {
    ASSERT_GE(s.shell.eps_p[k], before[k]) << k;
  }
}

}  // namespace
}  // namespace sf
