// Tests of the gmsh reader: small data files under tests/data, and the square-cup demo geometry.
#include "meshing/gmsh_reader.hpp"

#include <gmsh.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <string>

#include "core/errors.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;

const fs::path data_dir = SF_TEST_DATA_DIR;
const fs::path cup_dir = fs::path(SF_SOURCE_DIR) / "cases" / "square_cup_aluminium";
constexpr double t_half = 0.81 / 2;  // mm, half the blank thickness (REFERENCES.md, grade A)

/// A fresh, empty folder for files a test writes, under the test's own name: ctest runs the tests
/// side by side, and two tests asking for the same `name` would empty each other's folder.
fs::path scratch_dir(const std::string& name) {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(SF_BINARY_DIR) / "test_scratch" / "gmsh_reader" /
                       test->test_suite_name() / test->name() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Runs `f`, expects an InputError, and returns its message.
template <typename F>
std::string input_error_message(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InputError, got another exception: " << e.what();
    return {};
  }
  ADD_FAILURE() << "expected InputError, nothing was thrown";
  return {};
}

std::set<std::string> group_names(const GmshModel& model, int dim = -1) {
  std::set<std::string> names;
  for (const auto& g : model.groups) {
    if (dim < 0 || g.dim == dim) {
      names.insert(g.name);
    }
  }
  return names;
}

/// Normal (not normalised) of a planar polygon given by its node coordinates (Newell's method).
Vec3 polygon_normal(const PartMesh& part, const std::vector<int>& nodes) {
  Vec3 n = Vec3::Zero();
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const Vec3 a = part.nodes.col(nodes[k]);
    const Vec3 b = part.nodes.col(nodes[(k + 1) % nodes.size()]);
    n += a.cross(b);
  }
  return n;
}

std::vector<std::vector<int>> all_elements(const PartMesh& part) {
  std::vector<std::vector<int>> elements;
  for (Eigen::Index e = 0; e < part.quads.cols(); ++e) {
    elements.push_back({part.quads(0, e), part.quads(1, e), part.quads(2, e), part.quads(3, e)});
  }
  for (Eigen::Index e = 0; e < part.triangles.cols(); ++e) {
    elements.push_back({part.triangles(0, e), part.triangles(1, e), part.triangles(2, e)});
  }
  return elements;
}

/// Consistent orientation, checked independently of the reader: no directed edge is used twice
/// (two neighbours agreeing run their shared edge in opposite directions).
bool orientation_is_consistent(const PartMesh& part) {
  std::set<std::pair<int, int>> directed;
  for (const auto& el : all_elements(part)) {
    for (std::size_t k = 0; k < el.size(); ++k) {
      if (!directed.insert({el[k], el[(k + 1) % el.size()]}).second) {
        return false;
      }
    }
  }
  return true;
}

double total_area(const PartMesh& part) {
  double area = 0.0;
  for (const auto& el : all_elements(part)) {
    area += 0.5 * polygon_normal(part, el).norm();
  }
  return area;
}

struct Box3 {
  Vec3 min, max;
};
Box3 bounding_box(const PartMesh& part) {
  return {part.nodes.rowwise().minCoeff(), part.nodes.rowwise().maxCoeff()};
}

/// Number of triangles whose three nodes all have coordinate `axis` equal to `value` (within tol).
int triangles_in_plane(const PartMesh& part, int axis, double value, double tol = 1e-6) {
  int count = 0;
  for (Eigen::Index e = 0; e < part.triangles.cols(); ++e) {
    bool all = true;
    for (int k = 0; k < 3; ++k) {
      all = all && std::abs(part.nodes(axis, part.triangles(k, e)) - value) < tol;
    }
    count += all ? 1 : 0;
  }
  return count;
}

/// True if (x, y) lies strictly inside (by more than tol) the quarter of a rounded square of half
/// width `half` and plan corner radius `r`, centred on the z axis.
bool inside_rounded_square(double x, double y, double half, double r, double tol = 1e-6) {
  if (x >= half - tol || y >= half - tol) {
    return false;
  }
  const double c = half - r;  // corner centre
  if (x > c && y > c) {
    return std::hypot(x - c, y - c) < r - tol;
  }
  return true;
}

/// Nodes lying on the profile arc in the plane y = 0: circle of radius `r` about (cx, 0, cz).
int nodes_on_arc(const PartMesh& part, double cx, double cz, double r) {
  int count = 0;
  for (Eigen::Index i = 0; i < part.nodes.cols(); ++i) {
    const Vec3 p = part.nodes.col(i);
    if (std::abs(p.y()) < 1e-6 && std::abs(std::hypot(p.x() - cx, p.z() - cz) - r) < 1e-6) {
      ++count;
    }
  }
  return count;
}

/// Number of triangles lying in the plane z = `z` whose normal is not along `sign` * z.
int flat_triangles_facing_wrong_way(const PartMesh& part, double z, double sign) {
  int wrong = 0;
  for (Eigen::Index e = 0; e < part.triangles.cols(); ++e) {
    const std::vector<int> el = {part.triangles(0, e), part.triangles(1, e), part.triangles(2, e)};
    bool flat = true;
    for (const int n : el) {
      flat = flat && std::abs(part.nodes(2, n) - z) < 1e-9;
    }
    if (flat && !(sign * polygon_normal(part, el).z() > 0.0)) {
      ++wrong;
    }
  }
  return wrong;
}

// ----- small data files --------------------------------------------------------------------------

TEST(GmshReader, UnitSquareQuadsCountsGroupsAndOrientation) {
  const GmshModel model = load_gmsh_model(data_dir / "unit_square_quads.geo", 0.0, false);
  // Source: the .geo's transfinite 3 x 3 nodes: 9 nodes, 2 x 2 quads.
  EXPECT_EQ(model.node_tags.size(), 9u);
  EXPECT_EQ(group_names(model), (std::set<std::string>{"plate", "left", "origin"}));
  ASSERT_NE(model.find_group("plate", 2), nullptr);
  EXPECT_EQ(model.find_group("plate", 1), nullptr);

  const PartMesh part = extract_part_mesh(model, "plate", "sheet");
  EXPECT_EQ(part.name, "sheet");
  EXPECT_EQ(part.nodes.cols(), 9);
  EXPECT_EQ(part.quads.cols(), 4);
  EXPECT_EQ(part.triangles.cols(), 0);
  EXPECT_EQ(part.gmsh_node_tags.size(), 9u);
  EXPECT_TRUE(std::is_sorted(part.gmsh_node_tags.begin(), part.gmsh_node_tags.end()));
  EXPECT_NEAR(total_area(part), 1.0, 1e-12);  // unit square

  // Every quad's normal along z, all the same sign.
  const double first = polygon_normal(part, all_elements(part)[0]).z();
  EXPECT_NE(first, 0.0);
  for (const auto& el : all_elements(part)) {
    const Vec3 n = polygon_normal(part, el);
    EXPECT_NEAR(n.x(), 0.0, 1e-12);
    EXPECT_NEAR(n.y(), 0.0, 1e-12);
    EXPECT_GT(n.z() * first, 0.0);
  }
  EXPECT_TRUE(orientation_is_consistent(part));

  // Curve "left" (x = 0): 3 nodes; point "origin": the node at (0, 0, 0).
  const NodeGroup left = extract_node_group(model, part, "left");
  EXPECT_EQ(left.name, "left");
  ASSERT_EQ(left.nodes.size(), 3u);
  for (const int n : left.nodes) {
    EXPECT_EQ(part.nodes(0, n), 0.0);
  }
  EXPECT_TRUE(std::is_sorted(left.nodes.begin(), left.nodes.end()));
  const NodeGroup origin = extract_node_group(model, part, "origin");
  ASSERT_EQ(origin.nodes.size(), 1u);
  EXPECT_EQ(part.nodes.col(origin.nodes[0]), Vec3(0, 0, 0));
  // The local index maps back to the gmsh tag of the same node in the model.
  const std::size_t tag = part.gmsh_node_tags[origin.nodes[0]];
  EXPECT_EQ(model.node_coords.col(model.node_index.at(tag)), Vec3(0, 0, 0));
}

TEST(GmshReader, UnitSquareTriangles) {
  const GmshModel model = load_gmsh_model(data_dir / "unit_square_triangles.geo", 0.0, false);
  const PartMesh part = extract_part_mesh(model, "plate", "plate");
  // Source: the .geo's transfinite 3 x 3 nodes, two triangles per cell.
  EXPECT_EQ(part.nodes.cols(), 9);
  EXPECT_EQ(part.triangles.cols(), 8);
  EXPECT_EQ(part.quads.cols(), 0);
  EXPECT_TRUE(orientation_is_consistent(part));
  EXPECT_NEAR(total_area(part), 1.0, 1e-12);
  const NodeGroup bottom = extract_node_group(model, part, "bottom");
  ASSERT_EQ(bottom.nodes.size(), 3u);
  for (const int n : bottom.nodes) {
    EXPECT_EQ(part.nodes(1, n), 0.0);
  }
}

TEST(GmshReader, RecombineGivesQuads) {
  const GmshModel model = load_gmsh_model(data_dir / "unit_square_triangles.geo", 0.0, true);
  const PartMesh part = extract_part_mesh(model, "plate", "plate");
  // Source: recombining the 8 transfinite triangles pairs them into the 4 cells.
  EXPECT_EQ(part.quads.cols(), 4);
  EXPECT_EQ(part.triangles.cols(), 0);
}

TEST(GmshReader, WrittenMshReadsBackTheSame) {
  const fs::path dir = scratch_dir("written_msh");
  for (const bool recombine : {false, true}) {
    const fs::path msh = dir / (recombine ? "quads.msh" : "triangles.msh");
    write_msh(data_dir / "unit_square_triangles.geo", 0.0, recombine, msh);
    ASSERT_TRUE(fs::is_regular_file(msh));
    std::ifstream in(msh);
    std::string line;
    std::getline(in, line);
    std::getline(in, line);
    EXPECT_EQ(line.rfind("4.1 0", 0), 0u) << line;  // format 4.1, ASCII (gmsh's MSH header)

    const GmshModel from_geo =
        load_gmsh_model(data_dir / "unit_square_triangles.geo", 0.0, recombine);
    const GmshModel from_msh = load_gmsh_model(msh, 5.0, false);  // size ignored for a .msh
    const PartMesh a = extract_part_mesh(from_geo, "plate", "a");
    const PartMesh b = extract_part_mesh(from_msh, "plate", "b");
    EXPECT_EQ(a.nodes.cols(), b.nodes.cols());
    EXPECT_EQ(a.quads.cols(), b.quads.cols());
    EXPECT_EQ(a.triangles.cols(), b.triangles.cols());
    EXPECT_EQ(a.nodes, b.nodes);
    EXPECT_EQ(a.gmsh_node_tags, b.gmsh_node_tags);
    EXPECT_EQ(group_names(from_geo), group_names(from_msh));
    EXPECT_EQ(extract_node_group(from_msh, b, "bottom").nodes.size(), 3u);
  }
}

TEST(GmshReader, UnwritableMshIsAnInputError) {
  const fs::path out = scratch_dir("unwritable") / "no_such_folder" / "out.msh";
  const std::string message =
      input_error_message([&] { write_msh(data_dir / "unit_square_quads.geo", 0.0, false, out); });
  EXPECT_NE(message.find("out.msh"), std::string::npos) << message;
}

TEST(GmshReader, ElementSizeControlsTheMesh) {
  // The file asks for 0.1 at its points; element_size > 0 replaces that (Mesh.MeshSizeFromPoints =
  // 0, Mesh.MeshSizeMax = element_size). Source: a unit square meshed with size h has at least
  // 4 / h boundary segments, so >= 4 / h boundary nodes (gmsh rounds the count up).
  const fs::path dir = scratch_dir("element_size");
  const fs::path geo = dir / "square.geo";
  std::ofstream(geo) << "SetFactory(\"OpenCASCADE\");\nRectangle(1) = {0, 0, 0, 1, 1};\n"
                        "MeshSize{ PointsOf{ Surface{1}; } } = 0.1;\n"
                        "Physical Surface(\"plate\") = {1};\n";
  const auto nodes = [&](double h) {
    return extract_part_mesh(load_gmsh_model(geo, h, false), "plate", "p").nodes.cols();
  };
  const auto own = nodes(0.0), quarter = nodes(0.25), half = nodes(0.5);
  EXPECT_GE(own, 40);  // 4 / 0.1 boundary nodes alone
  EXPECT_LT(quarter, own);
  EXPECT_LT(half, quarter);
  EXPECT_GE(quarter, 16);
  EXPECT_GE(half, 8);
  EXPECT_LT(half, 40);
}

TEST(GmshReader, MissingGroupNamesFileAndListsGroups) {
  const GmshModel model = load_gmsh_model(data_dir / "unit_square_quads.geo", 0.0, false);
  const std::string message =
      input_error_message([&] { extract_part_mesh(model, "punch", "punch"); });
  EXPECT_NE(message.find("unit_square_quads.geo"), std::string::npos) << message;
  EXPECT_NE(message.find("'punch'"), std::string::npos) << message;
  EXPECT_NE(message.find("plate (2-D)"), std::string::npos) << message;
  EXPECT_NE(message.find("left (1-D)"), std::string::npos) << message;
  EXPECT_NE(message.find("origin (0-D)"), std::string::npos) << message;

  // A 1-D group is not a part.
  const std::string wrong_dim =
      input_error_message([&] { extract_part_mesh(model, "left", "left"); });
  EXPECT_NE(wrong_dim.find("dimension 1"), std::string::npos) << wrong_dim;

  const PartMesh part = extract_part_mesh(model, "plate", "plate");
  const std::string node_group =
      input_error_message([&] { extract_node_group(model, part, "sym"); });
  EXPECT_NE(node_group.find("unit_square_quads.geo"), std::string::npos) << node_group;
  EXPECT_NE(node_group.find("'sym'"), std::string::npos) << node_group;
  EXPECT_NE(node_group.find("plate (2-D)"), std::string::npos) << node_group;
}

TEST(GmshReader, NodeGroupOutsideThePartIsAnError) {
  const GmshModel model = load_gmsh_model(data_dir / "unit_square_quads.geo", 0.0, false);
  PartMesh part = extract_part_mesh(model, "plate", "plate");
  // Drop the origin node from the part: the group "origin" now names a node outside it.
  const auto origin = extract_node_group(model, part, "origin").nodes[0];
  part.gmsh_node_tags[origin] = 999999;
  const std::string message =
      input_error_message([&] { extract_node_group(model, part, "origin"); });
  EXPECT_NE(message.find("not a node of part 'plate'"), std::string::npos) << message;
}

TEST(GmshReader, MissingFileIsAnInputError) {
  const fs::path missing = data_dir / "no_such_file.geo";
  const std::string message = input_error_message([&] { load_gmsh_model(missing, 0.0, false); });
  EXPECT_NE(message.find("no_such_file.geo"), std::string::npos) << message;
  EXPECT_NE(message.find("not found"), std::string::npos) << message;
}

TEST(GmshReader, UnknownExtensionIsAnInputError) {
  const fs::path file = scratch_dir("extension") / "tool.obj";
  std::ofstream(file) << "v 0 0 0\n";
  const std::string message = input_error_message([&] { load_gmsh_model(file, 0.0, false); });
  EXPECT_NE(message.find("tool.obj"), std::string::npos) << message;
  EXPECT_NE(message.find("'.obj'"), std::string::npos) << message;
}

TEST(GmshReader, AnEmptyStlIsAnInputError) {
  const fs::path file = scratch_dir("extension") / "tool.stl";
  std::ofstream(file) << "solid empty\nendsolid empty\n";
  const std::string message = input_error_message([&] { load_gmsh_model(file, 0.0, false); });
  EXPECT_NE(message.find("tool.stl"), std::string::npos) << message;
}

TEST(GmshReader, GeoSyntaxErrorIsAnInputErrorWithGmshsMessage) {
  const std::string message =
      input_error_message([&] { load_gmsh_model(data_dir / "syntax_error.geo", 0.0, false); });
  EXPECT_NE(message.find("syntax_error.geo"), std::string::npos) << message;
  // gmsh's own message names the line (source: the data file's comment, line 4).
  EXPECT_NE(message.find("line 4"), std::string::npos) << message;
  EXPECT_NE(message.find("syntax error"), std::string::npos) << message;
}

TEST(GmshReader, EmptyModelIsAnInputError) {
  const fs::path geo = scratch_dir("empty") / "empty.geo";
  std::ofstream(geo) << "// nothing\n";
  const std::string message = input_error_message([&] { load_gmsh_model(geo, 0.0, false); });
  EXPECT_NE(message.find("empty.geo"), std::string::npos) << message;
  EXPECT_NE(message.find("empty"), std::string::npos) << message;
}

TEST(GmshReader, SecondOrderElementsAreAnInputError) {
  const GmshModel model = load_gmsh_model(data_dir / "second_order.geo", 0.0, false);
  const std::string message =
      input_error_message([&] { extract_part_mesh(model, "plate", "plate"); });
  EXPECT_NE(message.find("Triangle 6"), std::string::npos) << message;  // gmsh's type name
  EXPECT_NE(message.find("second_order.geo"), std::string::npos) << message;
}

// ----- orientation, on hand-made models ----------------------------------------------------------

/// A model of `n` x 1 unit quads along x (nodes 1..2n+2, bottom row then top row), whose
/// element `e` runs clockwise when flipped[e].
GmshModel strip_model(int n, const std::vector<bool>& flipped, bool twist_last = false) {
  GmshModel model;
  model.file = "strip.msh";
  const int columns = n + 1;
  model.node_coords.resize(3, 2 * columns);
  for (int i = 0; i < 2 * columns; ++i) {
    model.node_tags.push_back(static_cast<std::size_t>(i + 1));
    model.node_coords.col(i) = Vec3(i % columns, i / columns, 0.0);
    model.node_index[static_cast<std::size_t>(i + 1)] = i;
  }
  GmshPhysicalGroup group{"strip", 2, 1, {}, {}};
  GmshElementBlock block{3, "Quadrilateral 4", 4, {}, {}};
  for (int e = 0; e < n; ++e) {
    std::size_t a = e + 1, b = e + 2, c = columns + e + 2, d = columns + e + 1;
    if (twist_last && e == n - 1) {
      // Close the strip into a Moebius band: the last quad joins its right edge to the first
      // quad's left edge, top to bottom.
      b = static_cast<std::size_t>(columns + 1);
      c = 1;
    }
    std::vector<std::size_t> nodes = {a, b, c, d};
    if (flipped[e]) {
      std::reverse(nodes.begin() + 1, nodes.end());
    }
    block.element_tags.push_back(e + 1);
    block.node_tags.insert(block.node_tags.end(), nodes.begin(), nodes.end());
    group.node_tags.insert(group.node_tags.end(), nodes.begin(), nodes.end());
  }
  std::sort(group.node_tags.begin(), group.node_tags.end());
  group.node_tags.erase(std::unique(group.node_tags.begin(), group.node_tags.end()),
                        group.node_tags.end());
  group.elements.push_back(block);
  model.groups.push_back(group);
  return model;
}

TEST(GmshReaderOrientation, MixedQuadsTakeTheMajorityOrientation) {
  // 5 quads, 2 of them reversed: all end up counter-clockwise seen from +z (the majority).
  const PartMesh a =
      extract_part_mesh(strip_model(5, {false, true, false, true, false}), "strip", "a");
  EXPECT_TRUE(orientation_is_consistent(a));
  for (const auto& el : all_elements(a)) {
    EXPECT_GT(polygon_normal(a, el).z(), 0.0);
  }
  // 5 quads, 3 reversed: all end up clockwise (normal -z), the majority.
  const PartMesh b =
      extract_part_mesh(strip_model(5, {true, true, false, true, false}), "strip", "b");
  EXPECT_TRUE(orientation_is_consistent(b));
  for (const auto& el : all_elements(b)) {
    EXPECT_LT(polygon_normal(b, el).z(), 0.0);
  }
}

TEST(GmshReaderOrientation, MoebiusBandIsNotOrientable) {
  const GmshModel model = strip_model(6, std::vector<bool>(6, false), /*twist_last=*/true);
  const std::string message = input_error_message([&] { extract_part_mesh(model, "strip", "m"); });
  EXPECT_NE(message.find("not orientable"), std::string::npos) << message;
  EXPECT_NE(message.find("strip.msh"), std::string::npos) << message;
}

TEST(GmshReaderOrientation, NonManifoldEdgeIsAnError) {
  GmshModel model = strip_model(2, {false, false});
  // A third quad on the edge between nodes 2 and 5 (shared by both strip quads), sticking up in z.
  model.node_coords.conservativeResize(3, 8);
  model.node_coords.col(6) = Vec3(1, 0, 1);
  model.node_coords.col(7) = Vec3(1, 1, 1);
  model.node_tags.insert(model.node_tags.end(), {7, 8});
  model.node_index[7] = 6;
  model.node_index[8] = 7;
  auto& block = model.groups[0].elements[0];
  block.element_tags.push_back(3);
  block.node_tags.insert(block.node_tags.end(), {2, 7, 8, 5});
  const std::string message = input_error_message([&] { extract_part_mesh(model, "strip", "n"); });
  EXPECT_NE(message.find("shared by 3 elements"), std::string::npos) << message;
}

// ----- OpenMP thread count -----------------------------------------------------------------------

TEST(GmshReaderThreads, GmshInitializeChangesTheThreadCount) {
  // The pitfall the reader guards against (DESIGN.md section 5): shows this test set can fail.
  omp_set_num_threads(3);
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  const int inside = omp_get_max_threads();
  gmsh::finalize();
  EXPECT_NE(inside, 3);
  omp_set_num_threads(3);
}

TEST(GmshReaderThreads, ThreadCountIsRestored) {
  omp_set_num_threads(3);
  load_gmsh_model(data_dir / "unit_square_quads.geo", 0.0, false);
  EXPECT_EQ(omp_get_max_threads(), 3);
  write_msh(data_dir / "unit_square_quads.geo", 0.0, false, scratch_dir("threads") / "q.msh");
  EXPECT_EQ(omp_get_max_threads(), 3);
  // Also on the error path.
  EXPECT_THROW(load_gmsh_model(data_dir / "syntax_error.geo", 0.0, false), InputError);
  EXPECT_EQ(omp_get_max_threads(), 3);
  omp_set_num_threads(2);
  load_gmsh_model(data_dir / "unit_square_quads.geo", 0.0, false);
  EXPECT_EQ(omp_get_max_threads(), 2);
}

// ----- the square-cup demo geometry (quarter model) ----------------------------------------------
// Dimensions: NUMISHEET'93 (REFERENCES.md): blank 150 x 150 x 0.81 (grade A); punch 70 x 70, plan
// corner radius 10, profile radius 8; die opening 74 x 74, plan corner radius 12, profile radius 8
// (grade C). Tool extents (z = +-60, x, y = 90) and the holder's 1 mm offset: the brief.

constexpr double pi = std::numbers::pi;

TEST(SquareCupGeometry, Blank) {
  const GmshModel model = load_gmsh_model(cup_dir / "blank.geo", 2.5, true);
  EXPECT_EQ(group_names(model, 2), (std::set<std::string>{"blank"}));
  EXPECT_EQ(group_names(model), (std::set<std::string>{"blank", "sym_x", "sym_y", "edge_mid_x",
                                                       "edge_mid_y", "corner"}));
  const PartMesh blank = extract_part_mesh(model, "blank", "blank");
  // 75 / 2.5 = 30 elements per edge: 31 x 31 nodes, 30 x 30 quads, no triangles.
  EXPECT_EQ(blank.nodes.cols(), 31 * 31);
  EXPECT_EQ(blank.quads.cols(), 30 * 30);
  EXPECT_EQ(blank.triangles.cols(), 0);
  const Box3 box = bounding_box(blank);
  EXPECT_EQ(box.min, Vec3(0, 0, 0));
  EXPECT_NEAR(box.max.x(), 75.0, 1e-9);
  EXPECT_NEAR(box.max.y(), 75.0, 1e-9);
  EXPECT_EQ(box.max.z(), 0.0);
  EXPECT_NEAR(total_area(blank), 75.0 * 75.0, 1e-6);
  EXPECT_TRUE(orientation_is_consistent(blank));

  const NodeGroup sym_x = extract_node_group(model, blank, "sym_x");
  EXPECT_EQ(sym_x.nodes.size(), 31u);
  for (const int n : sym_x.nodes) {
    EXPECT_EQ(blank.nodes(0, n), 0.0);
  }
  const NodeGroup sym_y = extract_node_group(model, blank, "sym_y");
  EXPECT_EQ(sym_y.nodes.size(), 31u);
  for (const int n : sym_y.nodes) {
    EXPECT_EQ(blank.nodes(1, n), 0.0);
  }
  const NodeGroup mid = extract_node_group(model, blank, "edge_mid_x");
  ASSERT_EQ(mid.nodes.size(), 1u);
  EXPECT_TRUE(blank.nodes.col(mid.nodes[0]).isApprox(Vec3(75, 0, 0)));
  const NodeGroup mid_y = extract_node_group(model, blank, "edge_mid_y");
  ASSERT_EQ(mid_y.nodes.size(), 1u);
  EXPECT_TRUE(blank.nodes.col(mid_y.nodes[0]).isApprox(Vec3(0, 75, 0)));
  const NodeGroup corner = extract_node_group(model, blank, "corner");
  ASSERT_EQ(corner.nodes.size(), 1u);
  EXPECT_TRUE(blank.nodes.col(corner.nodes[0]).isApprox(Vec3(75, 75, 0)));

  // The element size follows element_size: 75 / 5 = 15 quads per edge; 0 keeps the 2.5 default.
  EXPECT_EQ(extract_part_mesh(load_gmsh_model(cup_dir / "blank.geo", 5.0, true), "blank", "b")
                .quads.cols(),
            15 * 15);
  EXPECT_EQ(extract_part_mesh(load_gmsh_model(cup_dir / "blank.geo", 0.0, true), "blank", "b")
                .quads.cols(),
            30 * 30);
}

TEST(SquareCupGeometry, Punch) {
  const GmshModel model = load_gmsh_model(cup_dir / "punch.geo", 0.0, false);
  EXPECT_EQ(group_names(model), (std::set<std::string>{"punch"}));
  const PartMesh punch = extract_part_mesh(model, "punch", "punch");
  EXPECT_EQ(punch.quads.cols(), 0);
  EXPECT_GT(punch.triangles.cols(), 0);
  EXPECT_TRUE(orientation_is_consistent(punch));
  const Box3 box = bounding_box(punch);
  EXPECT_NEAR(box.min.z(), t_half, 1e-9);  // touches the blank's top surface
  EXPECT_NEAR(box.max.z(), 60.0, 1e-9);
  EXPECT_NEAR(box.min.x(), 0.0, 1e-9);
  EXPECT_NEAR(box.min.y(), 0.0, 1e-9);
  EXPECT_NEAR(box.max.x(), 35.0, 1e-9);
  EXPECT_NEAR(box.max.y(), 35.0, 1e-9);
  // No faces in the symmetry planes, no top face.
  EXPECT_EQ(triangles_in_plane(punch, 0, 0.0), 0);
  EXPECT_EQ(triangles_in_plane(punch, 1, 0.0), 0);
  EXPECT_EQ(triangles_in_plane(punch, 2, 60.0), 0);
  // The profile is below: the flat bottom ends where the 8 mm radius starts (27 = 35 - 8, plan
  // radius 2 = 10 - 8), so no bottom node lies outside that rounded square.
  for (Eigen::Index i = 0; i < punch.nodes.cols(); ++i) {
    const Vec3 p = punch.nodes.col(i);
    if (std::abs(p.z() - t_half) < 1e-9) {
      EXPECT_TRUE(p.x() <= 27 + 1e-6 && p.y() <= 27 + 1e-6 &&
                  !(p.x() > 25 && p.y() > 25 && std::hypot(p.x() - 25, p.y() - 25) > 2 + 1e-6))
          << p.transpose();
    }
  }
  // Area: bottom 27^2 - (4 - pi) 2^2 / 4; profile 2 x 25 x 4 pi + (pi / 2) 8 (2 pi / 2 + 8)
  // (Pappus); walls (2 x 25 + 10 pi / 2) (60 - 8.405). Facets cut corners: within 0.5 %.
  const double wall = 60.0 - (t_half + 8.0);
  const double area =
      27.0 * 27.0 - (4 - pi) + 2 * 25 * 4 * pi + 4 * pi * (pi + 8) + (2 * 25 + 5 * pi) * wall;
  EXPECT_NEAR(total_area(punch), area, 0.005 * area);
  // The 8 mm profile arc (in y = 0, centre (27, 0, 8.405)) has >= 6 elements: >= 7 nodes.
  EXPECT_GE(nodes_on_arc(punch, 27.0, t_half + 8.0, 8.0), 7);
  // Only the punch's entities are meshed (no stray curves or points left by the deleted faces).
  EXPECT_EQ(model.node_tags.size(), static_cast<std::size_t>(punch.nodes.cols()));
  // Normals point out of the punch, towards the blank (punch.geo's comment): -z on the bottom.
  EXPECT_GT(triangles_in_plane(punch, 2, t_half), 0);
  EXPECT_EQ(flat_triangles_facing_wrong_way(punch, t_half, -1.0), 0);
  // The curvature refinement keeps >= 6 elements on the arc when the size is coarser (4 mm).
  const PartMesh coarse =
      extract_part_mesh(load_gmsh_model(cup_dir / "punch.geo", 4.0, false), "punch", "punch");
  EXPECT_GE(nodes_on_arc(coarse, 27.0, t_half + 8.0, 8.0), 7);
  EXPECT_LT(coarse.triangles.cols(), punch.triangles.cols());
}

TEST(SquareCupGeometry, Die) {
  const GmshModel model = load_gmsh_model(cup_dir / "die.geo", 0.0, false);
  EXPECT_EQ(group_names(model), (std::set<std::string>{"die"}));
  const PartMesh die = extract_part_mesh(model, "die", "die");
  EXPECT_EQ(die.quads.cols(), 0);
  EXPECT_TRUE(orientation_is_consistent(die));
  const Box3 box = bounding_box(die);
  EXPECT_NEAR(box.max.z(), -t_half, 1e-9);  // top face touches the blank's bottom surface
  EXPECT_NEAR(box.min.z(), -60.0, 1e-9);
  EXPECT_NEAR(box.min.x(), 0.0, 1e-9);
  EXPECT_NEAR(box.min.y(), 0.0, 1e-9);
  EXPECT_NEAR(box.max.x(), 90.0, 1e-9);
  EXPECT_NEAR(box.max.y(), 90.0, 1e-9);
  EXPECT_EQ(triangles_in_plane(die, 0, 0.0), 0);
  EXPECT_EQ(triangles_in_plane(die, 1, 0.0), 0);
  EXPECT_EQ(triangles_in_plane(die, 0, 90.0), 0);
  EXPECT_EQ(triangles_in_plane(die, 1, 90.0), 0);
  EXPECT_EQ(triangles_in_plane(die, 2, -60.0), 0);
  EXPECT_GT(triangles_in_plane(die, 2, -t_half), 0);
  // The profile is at the opening: the flat top starts 8 mm outside the opening (45 = 37 + 8, plan
  // radius 20 = 12 + 8); no top node inside that outline.
  for (Eigen::Index i = 0; i < die.nodes.cols(); ++i) {
    const Vec3 p = die.nodes.col(i);
    if (std::abs(p.z() + t_half) < 1e-9) {
      EXPECT_FALSE(inside_rounded_square(p.x(), p.y(), 45.0, 20.0)) << p.transpose();
    }
    // Nothing inside the opening (37, plan radius 12) at any height.
    EXPECT_FALSE(inside_rounded_square(p.x(), p.y(), 37.0, 12.0)) << p.transpose();
  }
  // Area: top 90^2 - (45^2 - (4 - pi) 20^2 / 4); profile 2 x 25 x 4 pi + (pi / 2) 8 (20 pi / 2 - 8)
  // (Pappus); walls (2 x 25 + 12 pi / 2) (60 - 8.405). Within 0.5 %.
  const double wall = 60.0 - (t_half + 8.0);
  const double area = 90.0 * 90.0 - (45.0 * 45.0 - (4 - pi) * 100) + 2 * 25 * 4 * pi +
                      4 * pi * (10 * pi - 8) + (2 * 25 + 6 * pi) * wall;
  EXPECT_NEAR(total_area(die), area, 0.005 * area);
  // The 8 mm profile arc (in y = 0, centre (45, 0, -8.405)) has >= 6 elements: >= 7 nodes.
  EXPECT_GE(nodes_on_arc(die, 45.0, -(t_half + 8.0), 8.0), 7);
  EXPECT_EQ(model.node_tags.size(), static_cast<std::size_t>(die.nodes.cols()));  // no strays
  // Normals point out of the die, towards the blank (die.geo's comment): +z on the top face.
  EXPECT_EQ(flat_triangles_facing_wrong_way(die, -t_half, 1.0), 0);
  const PartMesh coarse =
      extract_part_mesh(load_gmsh_model(cup_dir / "die.geo", 4.0, false), "die", "die");
  EXPECT_GE(nodes_on_arc(coarse, 45.0, -(t_half + 8.0), 8.0), 7);
}

TEST(SquareCupGeometry, Holder) {
  const GmshModel model = load_gmsh_model(cup_dir / "holder.geo", 0.0, false);
  EXPECT_EQ(group_names(model), (std::set<std::string>{"holder"}));
  const PartMesh holder = extract_part_mesh(model, "holder", "holder");
  EXPECT_EQ(holder.quads.cols(), 0);
  EXPECT_TRUE(orientation_is_consistent(holder));
  const Box3 box = bounding_box(holder);
  EXPECT_NEAR(box.min.z(), t_half, 1e-9);
  EXPECT_NEAR(box.max.z(), t_half, 1e-9);
  EXPECT_NEAR(box.min.x(), 0.0, 1e-9);
  EXPECT_NEAR(box.min.y(), 0.0, 1e-9);
  EXPECT_NEAR(box.max.x(), 90.0, 1e-9);
  EXPECT_NEAR(box.max.y(), 90.0, 1e-9);
  for (Eigen::Index i = 0; i < holder.nodes.cols(); ++i) {
    EXPECT_FALSE(inside_rounded_square(holder.nodes(0, i), holder.nodes(1, i), 38.0, 13.0));
  }
  // Area: 90^2 - (38^2 - (4 - pi) 13^2 / 4); the plan arc is faceted: within 0.1 %.
  const double area = 90.0 * 90.0 - (38.0 * 38.0 - (4 - pi) * 169.0 / 4);
  EXPECT_NEAR(total_area(holder), area, 0.001 * area);
  EXPECT_EQ(model.node_tags.size(), static_cast<std::size_t>(holder.nodes.cols()));  // no strays
  // Normals point out of the holder, towards the blank (-z; holder.geo's ReverseMesh).
  EXPECT_EQ(flat_triangles_facing_wrong_way(holder, t_half, -1.0), 0);
}

TEST(SquareCupGeometry, ToolSizeFollowsElementSize) {
  // Halving the size roughly quadruples the triangles (area / h^2); at least doubles them.
  const auto coarse =
      extract_part_mesh(load_gmsh_model(cup_dir / "holder.geo", 4.0, false), "holder", "holder");
  const auto fine =
      extract_part_mesh(load_gmsh_model(cup_dir / "holder.geo", 2.0, false), "holder", "holder");
  EXPECT_GT(fine.triangles.cols(), 2 * coarse.triangles.cols());
}

}  // namespace
}  // namespace sf
