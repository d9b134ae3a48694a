// select_nodes ([[node_group]]): blank nodes chosen by position. On the rectangular cup's quarter
// blank (cases/rectangular_cup_cad/blank.msh) the planes and points choose exactly the nodes of
// the physical groups its .geo script makes (the reference); on a curved blank (a cylindrical
// sheet, as a pre-bent or CAD blank is) the counts follow from its structured grid.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "core/errors.hpp"
#include "meshing/gmsh_reader.hpp"
#include "model/node_selection.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

NodeGroupConfig group(std::vector<double> point, std::vector<double> normal,
                      std::vector<double> box = {}, bool outline = false) {
  NodeGroupConfig c;
  c.name = "g";
  c.point = std::move(point);
  c.normal = std::move(normal);
  c.box = std::move(box);
  c.outline = outline;
  return c;
}

TEST(NodeSelection, PlanesAndPointsChooseTheScriptsPhysicalGroups) {
  const fs::path file = fs::path(SF_SOURCE_DIR) / "cases" / "rectangular_cup_cad" / "blank.msh";
  const GmshModel model = load_gmsh_model(file, 0.0, false);
  const PartMesh blank = extract_part_mesh(model, "blank", "blank");
  const auto physical = [&](const std::string& name) {
    return extract_node_group(model, blank, name).nodes;
  };
  EXPECT_EQ(select_nodes(group({}, {1, 0, 0}), blank, "t").nodes, physical("sym_x"));
  EXPECT_EQ(select_nodes(group({}, {0, 1, 0}), blank, "t").nodes, physical("sym_y"));
  EXPECT_EQ(select_nodes(group({65, 0, 0}, {}), blank, "t").nodes, physical("edge_mid_x"));
  EXPECT_EQ(select_nodes(group({0, 50, 0}, {}), blank, "t").nodes, physical("edge_mid_y"));
  // Nearest: a point off the blank still finds its corner.
  EXPECT_EQ(select_nodes(group({70, 55, 3}, {}), blank, "t").nodes, physical("corner"));
  // The outline is the four sides: x = 0, y = 0 (the groups) and x = 65, y = 50.
  const std::vector<int> outline =
      select_nodes(group({}, {}, {}, /*outline=*/true), blank, "t").nodes;
  const auto far_x = select_nodes(group({65, 0, 0}, {1, 0, 0}), blank, "t").nodes;
  const auto far_y = select_nodes(group({0, 50, 0}, {0, 1, 0}), blank, "t").nodes;
  EXPECT_EQ(outline.size(), physical("sym_x").size() + physical("sym_y").size() + far_x.size() +
                                far_y.size() - 4);  // each corner on two sides
  // A box around the far edge x = 65 and the outline within it: that edge alone.
  EXPECT_EQ(select_nodes(group({}, {}, {64, -1, -1, 66, 51, 1}, true), blank, "t").nodes, far_x);
}

// A cylindrical sheet: 10 x 6 quads, x = R sin(theta), z = R (1 - cos theta), theta in
// [-0.5, 0.5] rad in steps of 0.1, y = 0 .. 12 mm in steps of 2.
PartMesh curved_blank() {
  PartMesh blank;
  const int ni = 10, nj = 6;
  const double radius = 50.0;
  blank.nodes.resize(3, (ni + 1) * (nj + 1));
  for (int j = 0; j <= nj; ++j) {
    for (int i = 0; i <= ni; ++i) {
      const double theta = -0.5 + 0.1 * i;
      blank.nodes.col(j * (ni + 1) + i) =
          Vec3(radius * std::sin(theta), 2.0 * j, radius * (1.0 - std::cos(theta)));
    }
  }
  blank.quads.resize(4, ni * nj);
  for (int j = 0; j < nj; ++j) {
    for (int i = 0; i < ni; ++i) {
      const int a = j * (ni + 1) + i;
      blank.quads.col(j * ni + i) << a, a + 1, a + ni + 2, a + ni + 1;
    }
  }
  return blank;
}

TEST(NodeSelection, CurvedBlankPlaneBoxOutlineAndNearestNode) {
  const PartMesh blank = curved_blank();
  // The default tolerance: 1 % of the shortest edge (the 2 mm along y).
  EXPECT_NEAR(default_node_tolerance(blank), 0.02, 1e-15);
  // The plane x = 0 holds the column theta = 0 (i = 5): 7 nodes; the next column is 5 mm off.
  const std::vector<int> crown = select_nodes(group({}, {1, 0, 0}), blank, "t").nodes;
  ASSERT_EQ(crown.size(), 7u);
  for (std::size_t j = 0; j < crown.size(); ++j) {
    EXPECT_EQ(crown[j], static_cast<int>(j) * 11 + 5);
  }
  // A plane that cuts the curved sheet obliquely: z = R (1 - cos 0.3) holds the columns theta =
  // +-0.3 (the nodes off it by more than 0.02 mm are the others: the nearest, theta = 0.2 and
  // 0.4, are 1.2 mm and 1.7 mm away).
  const double z3 = 50.0 * (1.0 - std::cos(0.3));
  EXPECT_EQ(select_nodes(group({0, 0, z3}, {0, 0, 1}), blank, "t").nodes.size(), 14u);
  // The box y in [0, 4]: rows j = 0, 1, 2.
  EXPECT_EQ(select_nodes(group({}, {}, {-100, 0, -100, 100, 4, 100}), blank, "t").nodes.size(),
            33u);
  // The outline: 2 (10 + 6) nodes; with the plane x = 0, its two ends.
  EXPECT_EQ(select_nodes(group({}, {}, {}, true), blank, "t").nodes.size(), 32u);
  EXPECT_EQ(select_nodes(group({}, {1, 0, 0}, {}, true), blank, "t").nodes,
            (std::vector<int>{5, 6 * 11 + 5}));
  // The node nearest to a point above the crown's far end.
  EXPECT_EQ(select_nodes(group({0.3, 13, 5}, {}), blank, "t").nodes, std::vector<int>{6 * 11 + 5});
}

TEST(NodeSelection, AnEmptySelectionIsRefusedSayingWhereTheBlankIs) {
  const PartMesh blank = curved_blank();
  NodeGroupConfig off = group({200, 0, 0}, {1, 0, 0});
  off.name = "far_edge";
  try {
    select_nodes(off, blank, "case.toml:40: node_group[2]");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("case.toml:40: node_group[2]: node group 'far_edge' chooses no blank "
                           "node (within 0.02 mm of the plane through (200, 0, 0) with normal "
                           "(1, 0, 0)); the blank's nodes span (-23.9713, 0, 0) - (23.9713, 12, "
                           "6.12087) mm"),
              std::string::npos)
        << message;
  }
}

}  // namespace
}  // namespace sf
