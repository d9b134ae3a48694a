// A trim line from a file's curves (meshing/curve_loop.hpp through load_gmsh_model with
// curves_only): line elements given in any order and orientation joined into one closed line,
// ends apart by less than the tolerance made one, and the errors (not closed, a branch, two loops,
// no such group); then the same from a .geo's Physical Curve (a rounded rectangle of known area),
// the .msh gmsh makes of it, and a STEP file's curves (tests/data/cad/plate.step, 60 x 40 mm).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "core/errors.hpp"
#include "meshing/curve_loop.hpp"
#include "meshing/gmsh_reader.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

// Area enclosed by the points seen along z (shoelace), mm^2.
double enclosed_area(const std::vector<Vec3>& p) {
  double twice = 0.0;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    twice += p[j].x() * p[i].y() - p[i].x() * p[j].y();
  }
  return std::abs(0.5 * twice);
}

// A model of the given points and one 1-D group "trim" of 2-node lines (pairs of point indices).
GmshModel lines(const std::vector<Vec3>& points, const std::vector<std::array<int, 2>>& pairs) {
  GmshModel m;
  m.file = "lines.msh";
  m.node_coords.resize(3, static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    m.node_tags.push_back(100 + i);
    m.node_coords.col(static_cast<Eigen::Index>(i)) = points[i];
    m.node_index[100 + i] = static_cast<int>(i);
  }
  GmshElementBlock block{.type = 1,
                         .type_name = "Line 2",
                         .nodes_per_element = 2,
                         .element_tags = {},
                         .node_tags = {}};
  for (std::size_t e = 0; e < pairs.size(); ++e) {
    block.element_tags.push_back(e + 1);
    block.node_tags.push_back(100 + static_cast<std::size_t>(pairs[e][0]));
    block.node_tags.push_back(100 + static_cast<std::size_t>(pairs[e][1]));
  }
  m.groups.push_back(
      GmshPhysicalGroup{.name = "trim", .dim = 1, .tag = 1, .elements = {block}, .node_tags = {}});
  return m;
}

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(CurveLoop, LinesInAnyOrderAndOrientationJoinIntoOneClosedLine) {
  // A unit square's four sides, shuffled and two reversed; its corner (1, 1) given twice, the
  // second copy 1e-5 mm off (two CAD curves meeting within their tolerance).
  const std::vector<Vec3> p{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
                            Vec3(1, 1 + 1e-5, 0)};
  const std::vector<Vec3> loop =
      closed_curve_points(lines(p, {{2, 1}, {3, 0}, {4, 3}, {0, 1}}), "trim", 1e-3);
  ASSERT_EQ(loop.size(), 4u);
  EXPECT_DOUBLE_EQ(enclosed_area(loop), 1.0);
  for (std::size_t i = 0; i < 4; ++i) {  // neighbours along the loop are a side apart
    EXPECT_DOUBLE_EQ((loop[i] - loop[(i + 1) % 4]).norm(), 1.0) << i;
  }
  // Without the tolerance the two copies do not meet: the line is open there.
  EXPECT_NE(error_of([&] {
              closed_curve_points(lines(p, {{2, 1}, {3, 0}, {4, 3}, {0, 1}}), "trim", 1e-7);
            }).find("not closed: an end meets no other"),
            std::string::npos);
}

TEST(CurveLoop, ALineNotClosedBranchedOrInTwoLoopsIsAnErrorNamingTheFileAndGroup) {
  const std::vector<Vec3> p{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
                            Vec3(5, 0, 0), Vec3(6, 0, 0), Vec3(6, 1, 0), Vec3(2, 2, 0)};
  const std::string open = error_of([&] {
    closed_curve_points(lines(p, {{0, 1}, {1, 2}, {2, 3}}), "trim", 1e-6);
  });
  EXPECT_NE(open.find("'lines.msh': curve group 'trim'"), std::string::npos) << open;
  EXPECT_NE(open.find("at (0, 0, 0) mm"), std::string::npos) << open;
  const std::string branch = error_of([&] {
    closed_curve_points(lines(p, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {2, 7}}), "trim", 1e-6);
  });
  EXPECT_NE(branch.find("3 lines meet"), std::string::npos) << branch;
  const std::string two = error_of([&] {
    closed_curve_points(lines(p, {{0, 1}, {1, 2}, {2, 0}, {4, 5}, {5, 6}, {6, 4}}), "trim", 1e-6);
  });
  EXPECT_NE(two.find("more than one closed line (3 of its 6"), std::string::npos) << two;
  const std::string missing = error_of([&] {
    closed_curve_points(lines(p, {{0, 1}}), "cut", 1e-6);
  });
  EXPECT_NE(missing.find("no 1-D physical group 'cut'"), std::string::npos) << missing;
  EXPECT_NE(missing.find("its groups: trim (1-D)"), std::string::npos) << missing;
}

MeshImportOptions curves_of(const std::string& group, std::vector<int> tags = {}) {
  MeshImportOptions import;
  import.group = group;
  import.curves_only = true;
  import.curves = std::move(tags);
  return import;
}

TEST(CurveLoop, APhysicalCurveOfAGeoAndOfItsMshIsTheLine) {
  const fs::path geo = fs::path(SF_TEST_DATA_DIR) / "trim_line.geo";
  const double exact = 50.0 * 30.0 - (100.0 - std::numbers::pi * 100.0 / 4.0);
  const std::vector<Vec3> loop =
      closed_curve_points(load_gmsh_model(geo, 1.0, false, {}, curves_of("trim")), "trim", 0.01);
  // 50 + 20 + 40 + 30 = 140 mm of lines 1 mm apart, and a 15.7 mm arc in chords of at most 1 mm.
  EXPECT_GE(loop.size(), 140u + 16u);
  // Chords of at most 1 mm (θ <= 2 asin(0.05) = 0.1 on the radius 10) cut the arc's area by at
  // most (π/2 / 0.1) x (10^2 / 2)(0.1 - sin 0.1) = 0.131 mm^2, and by something.
  const double theta = 2.0 * std::asin(0.05);
  const double most_cut = std::numbers::pi / 2.0 / theta * 50.0 * (theta - std::sin(theta));
  EXPECT_LT(enclosed_area(loop), exact);
  EXPECT_GT(enclosed_area(loop), exact - most_cut);
  for (std::size_t i = 0; i < loop.size(); ++i) {
    EXPECT_LE((loop[i] - loop[(i + 1) % loop.size()]).norm(), 1.0 + 1e-9) << i;
  }
  for (const char* group : {"open", "branch", "two"}) {
    const std::string message = error_of([&] {
      closed_curve_points(load_gmsh_model(geo, 1.0, false, {}, curves_of(group)), group, 0.01);
    });
    EXPECT_NE(message.find(fmt::format("curve group '{}'", group)), std::string::npos) << message;
  }
  // The .msh gmsh writes of it holds the same line.
  const fs::path msh = fs::path(SF_BINARY_DIR) / "test_output" / "curve_loop" / "trim_line.msh";
  fs::create_directories(msh.parent_path());
  write_msh(geo, 1.0, false, msh);
  const std::vector<Vec3> again =
      closed_curve_points(load_gmsh_model(msh, 0.0, false, {}, curves_of("trim")), "trim", 0.01);
  EXPECT_EQ(again.size(), loop.size());
  EXPECT_NEAR(enclosed_area(again), enclosed_area(loop), 1e-9);
}

TEST(CurveLoop, ACadFilesCurvesAreTheLine) {
  const fs::path step = fs::path(SF_TEST_DATA_DIR) / "cad" / "plate.step";
  const std::vector<Vec3> loop =
      closed_curve_points(load_gmsh_model(step, 1.0, false, {}, curves_of("trim")), "trim", 0.01);
  EXPECT_EQ(loop.size(), 200u);  // 2 x (60 + 40) mm, 1 mm apart
  EXPECT_NEAR(enclosed_area(loop), 2400.0, 1e-9);
  const std::string message = error_of([&] {
    load_gmsh_model(step, 1.0, false, {}, curves_of("trim", {1, 99}));
  });
  EXPECT_NE(message.find("curve 99 is not in the file (its curves: 1, 2, 3, 4)"), std::string::npos)
      << message;
  // One side alone is not closed.
  EXPECT_NE(error_of([&] {
              closed_curve_points(load_gmsh_model(step, 1.0, false, {}, curves_of("trim", {1})),
                                  "trim", 0.01);
            }).find("not closed"),
            std::string::npos);
}

}  // namespace
}  // namespace sf
