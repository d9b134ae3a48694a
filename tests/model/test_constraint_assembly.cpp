// assemble_constraints (src/model/constraint_assembly.hpp) on a 10 x 10 mm plate of 2 x 2 quads:
// which degrees of freedom each node holds or has prescribed, in which axes, where entries meet at
// a node (a global symmetry plane and a diagonal one at the centre of a one-eighth model), and the
// errors for a direction held and prescribed, prescribed twice or at a skew angle, or a missing
// group (each naming the case file, the entries' lines and keys, and the node). The expected
// masks and axes follow from the definitions in docs/case-file.md by hand.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "core/errors.hpp"
#include "model/build_model.hpp"

namespace {

namespace fs = std::filesystem;

constexpr unsigned ux = 1, uy = 2, uz = 4, rx = 8, ry = 16, rz = 32;

// Points 1-4 at (0,0), (10,0), (10,10), (0,10); 2 x 2 quads, nodes 5 mm apart.
const char* const kPlateGeo = R"(
Point(1) = {0, 0, 0}; Point(2) = {10, 0, 0}; Point(3) = {10, 10, 0}; Point(4) = {0, 10, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 3;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("blank") = {1};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Point("diagonal") = {1, 3};
)";

const char* const kHeader = R"([blank]
mesh = "plate.geo"
thickness = 1.0
material = "steel"
[materials.steel]
type = "elastic"
density = 7.85e-9
young = 210000.0
poisson = 0.3
[control]
end_time = 0.001
)";

/// The case text: the header and `constraints`.
std::string case_text(const std::string& constraints) {
  return std::string(kHeader) + constraints;
}

fs::path write_plate_case(const std::string& name, const std::string& constraints) {
  const fs::path folder = fs::path(SF_BINARY_DIR) / "test_output" / "constraint_assembly" / name;
  fs::create_directories(folder);
  std::ofstream(folder / "plate.geo") << kPlateGeo;
  std::ofstream(folder / "case.toml") << case_text(constraints);
  return folder / "case.toml";
}

sf::Model build(const std::string& name, const std::string& constraints) {
  return sf::build_model(sf::read_case(write_plate_case(name, constraints)));
}

/// The message of the InputError building the case throws (empty if none).
std::string build_error(const std::string& name, const std::string& constraints) {
  try {
    build(name, constraints);
  } catch (const sf::InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for:\n" << constraints;
  return {};
}

/// The 1-based line of `needle` in the case text.
int line_of(const std::string& constraints, const std::string& needle) {
  const std::string text = case_text(constraints);
  const auto at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

/// The blank node at (x, y, 0).
int node_at(const sf::Model& model, double x, double y) {
  for (Eigen::Index i = 0; i < model.blank.mesh.nodes.cols(); ++i) {
    if ((model.blank.mesh.nodes.col(i) - sf::Vec3(x, y, 0.0)).norm() < 1e-9) {
      return static_cast<int>(i);
    }
  }
  ADD_FAILURE() << "no node at " << x << ", " << y;
  return 0;
}

void expect_contains(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << "message: " << message << "\nlacks: " << part;
}

TEST(ConstraintAssembly, GlobalEntriesCombineWithoutFrames) {
  // Symmetry about x on the left edge: ux, ry, rz. A diaphragm normal to y on the bottom edge:
  // the in-plane translations ux, uz. Their corner holds both.
  const sf::Model model = build("global", R"(
[[boundary]]
group = "left"
type = "symmetry"
axis = "x"
[[boundary]]
group = "bottom"
type = "diaphragm"
axis = "y"
)");
  const auto& mask = model.constraints.mask;
  EXPECT_EQ(mask[node_at(model, 0, 5)], ux | ry | rz);
  EXPECT_EQ(mask[node_at(model, 5, 0)], ux | uz);
  EXPECT_EQ(mask[node_at(model, 0, 0)], ux | uz | ry | rz);
  EXPECT_EQ(mask[node_at(model, 5, 5)], 0u);
  EXPECT_EQ(model.constraints.frames.count(), 0);
}

TEST(ConstraintAssembly, DiagonalSymmetryPlaneGetsAFrameAndMeetsAGlobalOneInGlobalAxes) {
  // A one-eighth model's planes: y = 0 (global) and the diagonal x = y (normal (1, -1, 0)). At
  // the far corner (10, 10) only the diagonal acts: its own axes, the normal translation and the
  // two in-plane rotations held. At the origin both act: translations along y and along the
  // diagonal's normal span the x-y plane (ux, uy held); rotations about x and z (from y = 0) and
  // about z and (1, 1, 0) (the diagonal's in-plane axes) span all three: global axes suffice.
  const sf::Model model = build("diagonal", R"(
[[boundary]]
group = "bottom"
type = "symmetry"
axis = "y"
[[boundary]]
group = "diagonal"
type = "symmetry"
normal = [1, -1, 0]
)");
  const sf::NodalConstraints& c = model.constraints;
  const int origin = node_at(model, 0, 0);
  const int corner = node_at(model, 10, 10);
  EXPECT_FALSE(c.frames.has(origin));
  EXPECT_EQ(c.mask[origin], ux | uy | rx | ry | rz);
  ASSERT_TRUE(c.frames.has(corner));
  EXPECT_EQ(c.frames.count(), 1);
  const sf::Vec3 n = sf::Vec3(1.0, -1.0, 0.0).normalized();
  EXPECT_NEAR(std::abs(c.frames.axis(corner, 0).dot(n)), 1.0, 1e-15);
  EXPECT_EQ(c.mask[corner], ux | ry | rz);
  // The held rotation axes are the plane's in-plane directions: perpendicular to n.
  EXPECT_NEAR(c.frames.axis(corner, 4).dot(n), 0.0, 1e-15);
  EXPECT_NEAR(c.frames.axis(corner, 5).dot(n), 0.0, 1e-15);
  // A velocity loses exactly its normal part, an angular velocity its in-plane part.
  sf::Vec3 v(3.0, 1.0, 2.0), omega(1.0, 2.0, 3.0);
  c.zero_components(corner, c.mask[corner], v, omega);
  EXPECT_NEAR(v.dot(n), 0.0, 1e-14);
  EXPECT_NEAR(v.x() + v.y(), 4.0, 1e-14);  // the in-plane part (1, 1, 0) . (3, 1, 2) kept
  EXPECT_NEAR(v.z(), 2.0, 1e-14);
  EXPECT_NEAR((omega - omega.dot(n) * n).norm(), 0.0, 1e-14);  // only the normal part kept
  EXPECT_NEAR(omega.dot(n), (1.0 - 2.0) / std::sqrt(2.0), 1e-14);
}

TEST(ConstraintAssembly, HoldInRotatedAxesUsesThem) {
  const double c = std::cos(std::numbers::pi / 6.0), s = std::sin(std::numbers::pi / 6.0);
  const sf::Model model = build("rotated", fmt::format(R"(
[[boundary]]
group = "right"
hold = ["uy", "rz"]
axes = [[{0}, {1}, 0.0], [{2}, {0}, 0.0]]
)",
                                                       c, s, -s));
  const int node = node_at(model, 10, 5);
  ASSERT_TRUE(model.constraints.frames.has(node));
  EXPECT_EQ(model.constraints.mask[node], uy | rz);
  EXPECT_NEAR((model.constraints.frames.axis(node, 1) - sf::Vec3(-s, c, 0.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((model.constraints.frames.axis(node, 5) - sf::Vec3::UnitZ()).norm(), 0.0, 1e-15);
  // apply() zeroes the held local components only: a velocity along the local x stays.
  sf::Matrix3X v = sf::Matrix3X::Zero(3, model.blank.mesh.nodes.cols());
  sf::Matrix3X omega = v;
  v.col(node) = 2.0 * sf::Vec3(c, s, 0.0) + 5.0 * sf::Vec3(-s, c, 0.0);
  omega.col(node) = sf::Vec3(0.0, 0.0, 7.0);
  model.constraints.apply(v, omega);
  EXPECT_NEAR((v.col(node) - 2.0 * sf::Vec3(c, s, 0.0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(omega.col(node).norm(), 0.0, 1e-14);
}

TEST(ConstraintAssembly, PrescribedDirectionPerpendicularToAHoldTakesACommonFrame) {
  // uz held in global axes, and a displacement along (cos 30, sin 30, 0): the prescription's axes
  // hold both (their z axis is the global z), so the node takes them: prescribed component 0 (ux
  // of the axes), held component 2.
  const double c = std::cos(std::numbers::pi / 6.0), s = std::sin(std::numbers::pi / 6.0);
  const sf::Model model = build("prescribed_frame", fmt::format(R"(
[[boundary]]
group = "right"
hold = ["uz"]
[[prescribed_motion]]
group = "right"
dof = "ux"
curve = [[0.0, 0.0], [0.001, 0.5]]
axes = [[{0}, {1}, 0.0], [{2}, {0}, 0.0]]
)",
                                                                c, s, -s));
  const int node = node_at(model, 10, 5);
  ASSERT_EQ(model.prescribed_motions.size(), 1u);
  const sf::PrescribedMotion& p = model.prescribed_motions[0];
  EXPECT_EQ(p.kind, sf::PrescribedMotion::Kind::displacement);
  EXPECT_EQ(p.nodes.size(), 3u);
  const auto k = std::find(p.nodes.begin(), p.nodes.end(), node) - p.nodes.begin();
  EXPECT_EQ(p.component[static_cast<std::size_t>(k)], 0);
  EXPECT_EQ(p.sign[static_cast<std::size_t>(k)], 1.0);
  EXPECT_EQ(model.constraints.mask[node], uz);
  EXPECT_EQ(model.constraints.prescribed[node], ux);
  ASSERT_TRUE(model.constraints.frames.has(node));
  EXPECT_NEAR((model.constraints.frames.axis(node, 0) - sf::Vec3(c, s, 0.0)).norm(), 0.0, 1e-15);
  // A global prescription on a global axis needs no frame, and a negative axis gives sign -1.
  const sf::Model global = build("prescribed_global", R"(
[[prescribed_motion]]
group = "top"
dof = "ry"
curve = [[0.0, 0.0], [0.001, 0.1]]
axes = [[-1, 0, 0], [0, -1, 0]]
)");
  const sf::PrescribedMotion& q = global.prescribed_motions[0];
  EXPECT_EQ(global.constraints.frames.count(), 0);
  EXPECT_EQ(q.component[0], 4);
  EXPECT_EQ(q.sign[0], -1.0);
  EXPECT_EQ(global.constraints.prescribed[q.nodes[0]], ry);
}

TEST(ConstraintAssembly, HeldAndPrescribedAtANodeIsAnErrorNamingBothEntries) {
  // The top edge's uz prescribed, the left edge fixed: they share the corner (0, 10).
  const std::string constraints = R"(
[[boundary]]
group = "left"
type = "fixed"
[[prescribed_motion]]
group = "top"
dof = "uz"
curve = [[0.0, 0.0], [0.001, 0.5]]
)";
  const std::string message = build_error("held_and_prescribed", constraints);
  const fs::path file = write_plate_case("held_and_prescribed", constraints);
  expect_contains(message,
                  fmt::format("{}:{}: prescribed_motion[0]: prescribes uz of node", file.string(),
                              line_of(constraints, "[[prescribed_motion]]")));
  expect_contains(message, "(gmsh 4)");  // point 4 at (0, 10)
  expect_contains(message, fmt::format("which boundary[0] (line {}, group 'left') holds",
                                       line_of(constraints, "[[boundary]]")));
}

TEST(ConstraintAssembly, PrescribedTwiceOrAtASkewAngleIsAnErrorNamingBothEntries) {
  const std::string twice = R"(
[[prescribed_motion]]
group = "top"
dof = "uz"
curve = [[0.0, 0.0], [0.001, 0.5]]
[[prescribed_motion]]
group = "right"
type = "velocity"
dof = "uz"
value = 10.0
)";
  std::string message = build_error("prescribed_twice", twice);
  expect_contains(message, "prescribed_motion[1]: prescribes uz of node");
  expect_contains(message, fmt::format("which prescribed_motion[0] (line {}, group 'top') "
                                       "prescribes too",
                                       line_of(twice, "[[prescribed_motion]]\ngroup = \"top\"")));
  // ux held, and a displacement along (1, 1, 0) / sqrt(2): 45 degrees to it.
  const std::string skew = R"(
[[boundary]]
group = "right"
hold = ["ux"]
[[prescribed_motion]]
group = "right"
dof = "ux"
curve = [[0.0, 0.0], [0.001, 0.5]]
axes = [[1, 1, 0], [-1, 1, 0]]
)";
  message = build_error("prescribed_skew", skew);
  expect_contains(message, "prescribed_motion[0]: prescribes ux of node");
  expect_contains(message, "at 45 degrees to a direction boundary[0]");
  expect_contains(message, "along or perpendicular");
}

TEST(ConstraintAssembly, MissingGroupNamesTheEntryLineAndKey) {
  const std::string constraints = R"(
[[boundary]]
group = "left"
type = "fixed"
[[boundary]]
group = "nowhere"
type = "diaphragm"
axis = "x"
)";
  const std::string message = build_error("missing_group", constraints);
  const fs::path file = write_plate_case("missing_group", constraints);
  expect_contains(message, fmt::format("{}:{}: boundary[1].group:", file.string(),
                                       line_of(constraints, "[[boundary]]\ngroup = \"nowhere\"")));
  expect_contains(message, "no physical group 'nowhere'");
  expect_contains(message, "left");  // the groups the mesh has are listed
}

}  // namespace
