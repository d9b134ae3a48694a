// What check and the run banner say about the tools' meshes: nothing but the clearance for the
// bundled cases' real tools (no false finding on their radii), and lines that name the tool, the
// counts and the positions for a tool with defects.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "casefile/case_config.hpp"
#include "model/build_model.hpp"
#include "solver/tool_mesh_report.hpp"
#include "support/surface_builder.hpp"

namespace fs = std::filesystem;

namespace sf {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The bundled cases' tools: meshed from their .geo files as a run meshes them.
TEST(ToolMeshReport, BundledToolsHaveNoFindingsAndTheirDesignedClearances) {
  struct Expected {
    const char* folder;
    double clearance;  ///< mm, of every tool
    double tolerance;  ///< mm
  };
  // The forming cases place every tool on the blank's surfaces (0 mm); the bounce's floor is 0.1
  // mm below the 1 mm plate; the hemisphere's die touches the blank along its torus's top circle,
  // which its facets reach only at their nodes (1.2e-5 mm below it at the nearest).
  for (const Expected& e :
       {Expected{"square_cup_aluminium", 0.0, 1e-12}, Expected{"cylindrical_cup", 0.0, 1e-12},
        Expected{"u_channel_bhf_2450N", 0.0, 1e-12}, Expected{"verify_bounce", 0.1, 1e-12},
        Expected{"hemisphere_stretching", 0.0, 2e-5}}) {
    const Model model =
        build_model(read_case(fs::path(SF_SOURCE_DIR) / "cases" / e.folder / "case.toml"));
    const std::vector<ToolMeshReport> reports = diagnose_tool_meshes(model);
    ASSERT_EQ(reports.size(), model.tools.size());
    for (const ToolMeshReport& r : reports) {
      EXPECT_TRUE(r.diagnosis.clean()) << e.folder << ", " << r.tool;
      EXPECT_NEAR(r.clearance, e.clearance, e.tolerance) << e.folder << ", " << r.tool;
      EXPECT_GT(r.approach.facing, 0.99) << e.folder << ", " << r.tool;
      const ToolMeshLines lines = describe_tool_mesh(r, model.initial.thickness, "mm");
      EXPECT_TRUE(lines.warnings.empty()) << e.folder << ", " << r.tool;
    }
  }
}

ToolMeshReport report_of(const TriangleSurface& surface, double thickness, double distance) {
  ToolMeshReport r;
  r.tool = "lid";
  r.triangles = surface.num_triangles();
  r.diagnosis = diagnose_tool(surface, thickness);
  r.approach.distance = distance;
  r.approach.tool_point = Vec3(1, 2, 3);
  r.approach.facing = 1.0;
  r.clearance = distance - 0.5 * thickness;
  return r;
}

TEST(ToolMeshReport, GapIsNamedWithItsWidthsAndPositions) {
  test::SurfaceBuilder b;
  b.add_patch(4, 4, test::rectangle(0, 4, 0, 4, 0));
  b.add_patch(4, 4, test::rectangle(4.05, 8.05, 0, 4, 0));
  TriangleSurface surface = b.build();
  const SurfaceOrientation orientation = orient_surface(surface, Matrix3X(Vec3(4, 2, 1.7)));
  ToolMeshReport report = report_of(surface, 1.0, 1.7);
  report.orientation = orientation;
  const ToolMeshLines lines = describe_tool_mesh(report, 1.0, "mm");
  ASSERT_EQ(lines.info.size(), 3u);
  EXPECT_EQ(
      lines.info[0],
      "Tool mesh   'lid': 64 triangles: 8 gap edges (0 between faces oriented opposite ways), "
      "0 overlapping triangles, 0 of near-zero area, 0 folds (warnings)\n");
  EXPECT_EQ(lines.info[2],
            "Clearance   'lid' clears the blank by 1.2 mm at (1, 2, 3) on the tool\n");
  // Two 4 x 4 mm patches of 16 free edges each, normals (+z) already towards the blank.
  EXPECT_EQ(lines.info[1],
            "Surface     'lid': open: 2 boundaries, 32 free edges (32 mm in all); 2 components; "
            "orientation as read\n");
  ASSERT_EQ(lines.warnings.size(), 1u);
  const std::string& w = lines.warnings[0];
  EXPECT_TRUE(contains(w, "tool 'lid': 8 free edges run beside another free edge")) << w;
  EXPECT_TRUE(contains(w, "widest gap 0.05 mm at (4.025, ")) << w;
  EXPECT_TRUE(contains(w, "narrowest 0.05 mm at (4.025, ")) << w;
  EXPECT_TRUE(contains(w, "blank's thickness (1 mm)")) << w;
}

TEST(ToolMeshReport, EachKindOfFindingHasItsWarningAndAtMostThreePositions) {
  test::SurfaceBuilder b;
  b.add_patch(4, 4, test::rectangle(0, 4, 0, 4, 0));
  b.add_patch(4, 4, test::rectangle(4.05, 8.05, 0, 4, 0), true);  // flipped across the gap
  b.add_patch(2, 2, test::rectangle(20, 22, 0, 2, 0));
  b.add_patch(2, 2, test::rectangle(20, 22, 0, 2, 0));  // given twice
  const int p = b.add_node({30, 0, 0}), q = b.add_node({31, 0, 0}), s = b.add_node({30.5, 1e-3, 0});
  b.add_triangle(p, q, s);  // a sliver
  const ToolMeshLines lines = describe_tool_mesh(report_of(b.build(), 1.0, 0.5), 1.0, "mm");
  ASSERT_EQ(lines.warnings.size(), 4u);
  EXPECT_TRUE(contains(lines.warnings[0], "8 free edges run beside")) << lines.warnings[0];
  EXPECT_TRUE(contains(lines.warnings[1],
                       "the faces on the two sides of 8 gap edges are oriented "
                       "opposite ways (normals 180 deg apart at (4.025, "))
      << lines.warnings[1];
  EXPECT_TRUE(contains(lines.warnings[1], ", ...)")) << lines.warnings[1];  // 3 of 8 named
  EXPECT_TRUE(contains(lines.warnings[2], "tool 'lid': 16 triangles lie on or cross triangles"))
      << lines.warnings[2];
  EXPECT_TRUE(contains(lines.warnings[3], "tool 'lid': 1 triangle of near-zero area"))
      << lines.warnings[3];
  EXPECT_TRUE(contains(lines.warnings[3], "0.0005 mm^2 at (30.5, 0.0003333, 0)"))
      << lines.warnings[3];
  EXPECT_EQ(lines.info[2], "Clearance   'lid' touches the blank (0 mm) at (1, 2, 3) on the tool\n");
}

TEST(ToolMeshReport, ClearanceInsideTheThicknessAndAToolFacingAway) {
  test::SurfaceBuilder b;
  b.add_patch(2, 2, test::rectangle(0, 2, 0, 2, 0), true);  // normals -z, the blank above
  TriangleSurface surface = b.build();
  const SurfaceOrientation orientation = orient_surface(surface, Matrix3X(Vec3(1, 1, 0.3)));
  ToolMeshReport r = report_of(surface, 1.0, 0.3);
  r.orientation = orientation;
  r.approach.facing = -0.8;
  const ToolMeshLines lines = describe_tool_mesh(r, 1.0, "mm");
  EXPECT_EQ(lines.info[0],
            "Tool mesh   'lid': 8 triangles: no gaps, overlaps, near-zero-area triangles or "
            "folds\n");
  EXPECT_EQ(lines.info[2],
            "Clearance   'lid' is inside the blank's thickness at (1, 2, 3) on the tool: 0.3 mm "
            "from the mid-surface, less than half the thickness\n");
  EXPECT_EQ(lines.info[1],
            "Surface     'lid': open: 1 boundary, 8 free edges (8 mm in all); 1 component; "
            "triangles turned over: 0 to agree with their neighbours, 8 with their component to "
            "face the blank\n");
  ASSERT_EQ(lines.warnings.size(), 1u);
  EXPECT_TRUE(contains(lines.warnings[0],
                       "tool 'lid' faces away from the blank where it comes "
                       "closest, at (1, 2, 3)"))
      << lines.warnings[0];
}

}  // namespace
}  // namespace sf
