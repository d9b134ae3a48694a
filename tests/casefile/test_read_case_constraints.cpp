// Case-file keys of general constraints: [[boundary]] of every type (fixed, symmetry, diaphragm,
// hold; an axis of the global axes or of `axes`, or a `normal` vector), [[prescribed_motion]],
// the checks that need the analysis type, every error with its file, line and key, and the
// resolved-case round trip of the new keys (bit for bit).
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "casefile/case_config.hpp"
#include "casefile/read_case_fixture.hpp"
#include "core/errors.hpp"

namespace {

using namespace sf_test;
using Vector = std::array<double, 3>;

/// kMinimal with `extra` appended (sections after [control]).
std::string with(std::string_view extra) {
  return std::string(kMinimal) + std::string(extra);
}

constexpr std::string_view kConstraints = R"toml(
[[boundary]]
group = "end"
type = "diaphragm"
axis = "x"

[[boundary]]
group = "skew_end"
type = "diaphragm"
normal = [3, 4, 0]

[[boundary]]
group = "diagonal"
type = "symmetry"
normal = [1, -1, 0]

[[boundary]]
group = "edge"
hold = ["uz", "rx"]
axes = [[2, 0, 0], [1, 1, 0]]

[[boundary]]
group = "tilted"
type = "symmetry"
axis = "y"
axes = [[1, 1, 0], [-1, 1, 0]]

[[prescribed_motion]]
group = "tip"
dof = "uz"
curve = [[0.0, 0.0], [0.001, -2.5]]

[[prescribed_motion]]
group = "hub"
type = "velocity"
dof = "ry"
value = 3.0
axes = [[0, 0, 1], [1, 0, 0]]
)toml";

TEST_F(ReadCase, ReadsEveryBoundaryTypeAndFrame) {
  const std::string text = with(kConstraints);
  const sf::CaseConfig c = sf::read_case(write_case(text));
  using Type = sf::BoundaryConfig::Type;
  ASSERT_EQ(c.boundaries.size(), 5u);

  EXPECT_EQ(c.boundaries[0].type, Type::diaphragm);
  EXPECT_EQ(c.boundaries[0].axis, 0);
  EXPECT_FALSE(c.boundaries[0].normal.has_value());
  EXPECT_FALSE(c.boundaries[0].axes.has_value());
  EXPECT_EQ(c.boundaries[0].line, line_of(text, "[[boundary]]\ngroup = \"end\""));

  // A normal is normalised: (3, 4, 0) / 5 exactly in binary to within one rounding.
  ASSERT_TRUE(c.boundaries[1].normal.has_value());
  EXPECT_DOUBLE_EQ((*c.boundaries[1].normal)[0], 0.6);
  EXPECT_DOUBLE_EQ((*c.boundaries[1].normal)[1], 0.8);
  EXPECT_EQ((*c.boundaries[1].normal)[2], 0.0);

  EXPECT_EQ(c.boundaries[2].type, Type::symmetry);
  ASSERT_TRUE(c.boundaries[2].normal.has_value());
  EXPECT_DOUBLE_EQ((*c.boundaries[2].normal)[0], std::sqrt(0.5));
  EXPECT_DOUBLE_EQ((*c.boundaries[2].normal)[1], -std::sqrt(0.5));

  // `hold` without `type` is type = "hold"; the axes are normalised and y made perpendicular to
  // x: (2, 0, 0) -> (1, 0, 0), (1, 1, 0) -> (0, 1, 0), both exact.
  EXPECT_EQ(c.boundaries[3].type, Type::hold);
  EXPECT_EQ(c.boundaries[3].hold, (std::array<bool, 6>{false, false, true, true, false, false}));
  ASSERT_TRUE(c.boundaries[3].axes.has_value());
  EXPECT_EQ(c.boundaries[3].axes->x, (Vector{1.0, 0.0, 0.0}));
  EXPECT_EQ(c.boundaries[3].axes->y, (Vector{0.0, 1.0, 0.0}));

  // Perpendicular axes of any length: only normalised (1/sqrt(2) to one rounding).
  EXPECT_EQ(c.boundaries[4].axis, 1);
  ASSERT_TRUE(c.boundaries[4].axes.has_value());
  EXPECT_DOUBLE_EQ(c.boundaries[4].axes->x[0], std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(c.boundaries[4].axes->y[0], -std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(c.boundaries[4].axes->y[1], std::sqrt(0.5));
}

TEST_F(ReadCase, AxesAreMadePerpendicularInTheirPlane) {
  // x = (1, 1, 0) / sqrt(2); the second vector (0, 1, 0) keeps its part perpendicular to x:
  // (-1/2, 1/2, 0), normalised (-1, 1, 0) / sqrt(2).
  const sf::CaseConfig c = sf::read_case(
      write_case(with("[[boundary]]\ngroup = \"e\"\nhold = [\"ux\"]\naxes = [[1, 1, 0], [0, 1, "
                      "0]]\n")));
  const sf::AxesConfig& a = *c.boundaries[0].axes;
  // To a few roundings (4.4e-16: 4 ulps of 0.7).
  const double h = std::sqrt(0.5);
  EXPECT_NEAR(a.x[0], h, 4.4e-16);
  EXPECT_NEAR(a.x[1], h, 4.4e-16);
  EXPECT_NEAR(a.y[0], -h, 4.4e-16);
  EXPECT_NEAR(a.y[1], h, 4.4e-16);
  EXPECT_EQ(a.y[2], 0.0);
  EXPECT_NEAR(a.x[0] * a.y[0] + a.x[1] * a.y[1], 0.0, 4.4e-16);
}

TEST_F(ReadCase, ReadsPrescribedMotions) {
  const std::string text = with(kConstraints);
  const sf::CaseConfig c = sf::read_case(write_case(text));
  ASSERT_EQ(c.prescribed_motions.size(), 2u);
  const sf::PrescribedMotionConfig& a = c.prescribed_motions[0];
  EXPECT_EQ(a.group, "tip");
  EXPECT_EQ(a.type, sf::PrescribedMotionConfig::Type::displacement);  // the default
  EXPECT_EQ(a.dof, 2);
  EXPECT_EQ(a.curve.times, (std::vector<double>{0.0, 0.001}));
  EXPECT_EQ(a.curve.values, (std::vector<double>{0.0, -2.5}));
  EXPECT_FALSE(a.axes.has_value());
  EXPECT_EQ(a.line, line_of(text, "[[prescribed_motion]]\ngroup = \"tip\""));
  const sf::PrescribedMotionConfig& b = c.prescribed_motions[1];
  EXPECT_EQ(b.type, sf::PrescribedMotionConfig::Type::velocity);
  EXPECT_EQ(b.dof, 4);
  EXPECT_EQ(b.value, 3.0);
  EXPECT_TRUE(b.curve.times.empty());
  ASSERT_TRUE(b.axes.has_value());
  EXPECT_EQ(b.axes->x, (Vector{0.0, 0.0, 1.0}));
  EXPECT_EQ(b.axes->y, (Vector{1.0, 0.0, 0.0}));
}

TEST_F(ReadCase, StaticAnalysisTakesAConstantPrescribedDisplacement) {
  const sf::CaseConfig c = sf::read_case(
      write_case(with("[[prescribed_motion]]\ngroup = \"tip\"\ndof = \"rx\"\nvalue = 0.25\n"
                      "[analysis]\ntype = \"static\"\n")));
  ASSERT_EQ(c.prescribed_motions.size(), 1u);
  EXPECT_EQ(c.prescribed_motions[0].value, 0.25);
  EXPECT_EQ(c.prescribed_motions[0].dof, 3);
}

TEST_F(ReadCase, BoundaryErrorsNameFileLineAndKey) {
  const std::string hold = "[[boundary]]\ngroup = \"e\"\nhold = [\"ux\", \"uw\"]\n";
  std::string text = with(hold);
  expect_error(text, line_of(text, "hold ="),
               {"boundary[0].hold[1]", R"(one of "ux", "uy", "uz", "rx", "ry", "rz")", "\"uw\""});

  text = with("[[boundary]]\ngroup = \"e\"\nhold = [\"ux\", \"rz\", \"ux\"]\n");
  expect_error(text, line_of(text, "hold ="), {"boundary[0].hold[2]", "\"ux\" is listed twice"});

  text = with("[[boundary]]\ngroup = \"e\"\nhold = []\n");
  expect_error(text, line_of(text, "hold ="), {"boundary[0].hold", "non-empty array"});

  text = with("[[boundary]]\ngroup = \"e\"\ntype = \"hold\"\n");
  expect_error(text, line_of(text, "[[boundary]]"), {"boundary[0].hold", "missing"});

  text = with("[[boundary]]\ngroup = \"e\"\nhold = [\"ux\"]\naxes = [[0, 0, 0], [0, 1, 0]]\n");
  expect_error(text, line_of(text, "axes ="), {"boundary[0].axes[0]", "not all zero", "local x"});

  text = with("[[boundary]]\ngroup = \"e\"\nhold = [\"ux\"]\naxes = [[1, 0, 0], [0, 1]]\n");
  expect_error(text, line_of(text, "axes ="), {"boundary[0].axes[1]", "local y", "3 finite"});

  text = with("[[boundary]]\ngroup = \"e\"\nhold = [\"ux\"]\naxes = [[1, 0, 0]]\n");
  expect_error(text, line_of(text, "axes ="), {"boundary[0].axes", "[[x1, x2, x3], [y1, y2, y3]]"});

  // 0.573 degrees apart: near-parallel, refused (not silently turned into a frame).
  text = with("[[boundary]]\ngroup = \"e\"\nhold = [\"ux\"]\naxes = [[1, 0, 0], [-1, 0.01, 0]]\n");
  expect_error(text, line_of(text, "axes ="),
               {"boundary[0].axes", "at least 5.7 degrees apart", "0.573 degrees"});

  text = with("[[boundary]]\ngroup = \"e\"\ntype = \"diaphragm\"\n");
  expect_error(text, line_of(text, "[[boundary]]"),
               {"boundary[0].axis", "missing", R"("x", "y", "z")", "normal"});

  text = with("[[boundary]]\ngroup = \"e\"\ntype = \"diaphragm\"\naxis = \"w\"\n");
  expect_error(text, line_of(text, "axis ="), {"boundary[0].axis", R"("x", "y", "z")"});

  text =
      with("[[boundary]]\ngroup = \"e\"\ntype = \"symmetry\"\naxis = \"x\"\nnormal = [1, 1, 0]\n");
  expect_error(text, line_of(text, "axis ="), {"boundary[0].axis", "not allowed", "not both"});

  text = with(
      "[[boundary]]\ngroup = \"e\"\ntype = \"symmetry\"\nnormal = [1, 1, 0]\n"
      "axes = [[1, 0, 0], [0, 1, 0]]\n");
  expect_error(text, line_of(text, "axes ="), {"boundary[0].axes", "not allowed"});

  text = with("[[boundary]]\ngroup = \"e\"\ntype = \"symmetry\"\nnormal = [0, 0, 0]\n");
  expect_error(text, line_of(text, "normal ="), {"boundary[0].normal", "not all zero"});

  text = with("[[boundary]]\ngroup = \"e\"\ntype = \"fixed\"\naxes = [[1, 0, 0], [0, 1, 0]]\n");
  expect_error(text, line_of(text, "axes ="), {"boundary[0].axes", "not allowed"});

  text = with("[[boundary]]\ngroup = \"e\"\ntype = \"symmetry\"\naxis = \"x\"\nhold = [\"uz\"]\n");
  expect_error(text, line_of(text, "hold ="), {"boundary[0].hold", "not allowed"});

  text = with("[[boundary]]\ngroup = \"e\"\nhold = [\"uz\"]\naxis = \"x\"\n");
  expect_error(text, line_of(text, "axis ="), {"boundary[0].axis", "not allowed"});

  text = with("[[boundary]]\ngroup = \"e\"\nhold = [\"uz\"]\nframe = 1\n");
  expect_error(text, line_of(text, "frame ="), {"boundary[0].frame", "unknown key", "axes"});
}

TEST_F(ReadCase, PrescribedMotionErrorsNameFileLineAndKey) {
  std::string text = with("[[prescribed_motion]]\ngroup = \"t\"\ndof = \"uw\"\nvalue = 1.0\n");
  expect_error(text, line_of(text, "dof ="), {"prescribed_motion[0].dof", "\"ux\"", "\"rz\""});

  text = with("[[prescribed_motion]]\ngroup = \"t\"\nvalue = 1.0\n");
  expect_error(text, line_of(text, "[[prescribed_motion]]"),
               {"prescribed_motion[0].dof", "missing"});

  text = with(
      "[[prescribed_motion]]\ngroup = \"t\"\ndof = \"uz\"\nvalue = 1.0\n"
      "curve = [[0, 0], [1, 1]]\n");
  expect_error(text, line_of(text, "value ="), {"prescribed_motion[0].value", "not both"});

  text = with("[[prescribed_motion]]\ngroup = \"t\"\ndof = \"uz\"\n");
  expect_error(text, line_of(text, "[[prescribed_motion]]"),
               {"prescribed_motion[0].curve", "missing", "value (mm)"});

  text = with("[[prescribed_motion]]\ngroup = \"t\"\ndof = \"ry\"\ncurve = [[0, 0.1], [1, 1]]\n");
  expect_error(text, line_of(text, "curve ="),
               {"prescribed_motion[0].curve[0]", "starts at 0 rad", "got 0.1"});

  text = with(
      "[[prescribed_motion]]\ngroup = \"t\"\ndof = \"uz\"\ntype = \"speed\"\n"
      "value = 1.0\n");
  expect_error(text, line_of(text, "type ="),
               {"prescribed_motion[0].type", R"("displacement", "velocity")"});

  text = with(
      "[[prescribed_motion]]\ngroup = \"t\"\ndof = \"uz\"\nvalue = 1.0\n"
      "axes = [[1, 0, 0], [1, 0, 1e-3]]\n");
  expect_error(text, line_of(text, "axes ="), {"prescribed_motion[0].axes", "5.7 degrees"});

  // A constant displacement is a jump at t = 0 in an explicit run (the default analysis).
  text = with("[[prescribed_motion]]\ngroup = \"t\"\ndof = \"uz\"\nvalue = 1.0\n");
  expect_error(text, line_of(text, "value ="),
               {"prescribed_motion[0].value", "explicit run needs a `curve`"});

  // A static analysis has no velocities.
  text = with(
      "[[prescribed_motion]]\ngroup = \"t\"\ntype = \"velocity\"\ndof = \"uz\"\n"
      "value = 1.0\n[analysis]\ntype = \"static\"\n");
  expect_error(text, line_of(text, "type = \"velocity\""),
               {"prescribed_motion[0].type", "static analysis prescribes displacements"});

  // [[prescribed_velocity]] stays refused in a static analysis, and the message points at it.
  text = with(
      "[[prescribed_velocity]]\ngroup = \"t\"\nvelocity = [1, 0, 0]\n"
      "[analysis]\ntype = \"static\"\n");
  expect_error(text, line_of(text, "[[prescribed_velocity]]"),
               {"prescribed_velocity[0]", "explicit runs", "[[prescribed_motion]]"});
}

TEST_F(ReadCase, ResolvedCaseWritesTheConstraintKeysBackBitForBit) {
  // Axes that need normalising and making perpendicular; a normal that needs normalising.
  const std::string extra = std::string(kConstraints) + R"toml(
[[boundary]]
group = "odd"
hold = ["ux", "ry", "rz"]
axes = [[0.3, 0.2, 0.9], [0.1, 0.7, -0.2]]

[[prescribed_motion]]
group = "odd"
dof = "uy"
curve = [[0.0, 0.0], [0.0005, 0.125], [0.002, 0.125]]
axes = [[0.3, 0.2, 0.9], [0.1, 0.7, -0.2]]
)toml";
  const sf::CaseConfig a = sf::read_case(write_case(with(extra)));
  const std::string resolved = sf::format_resolved_case(a);
  SCOPED_TRACE(resolved);
  expect_contains(resolved, "type = \"diaphragm\"\naxis = \"x\"\n");
  expect_contains(resolved, "hold = [\"uz\", \"rx\"]\naxes = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]");
  expect_contains(resolved, "normal = [0.6");
  const sf::CaseConfig b = sf::read_case(write_case(resolved, "results/resolved.toml"));
  ASSERT_EQ(b.boundaries.size(), a.boundaries.size());
  for (std::size_t i = 0; i < a.boundaries.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(b.boundaries[i].group, a.boundaries[i].group);
    EXPECT_EQ(b.boundaries[i].type, a.boundaries[i].type);
    EXPECT_EQ(b.boundaries[i].axis, a.boundaries[i].axis);
    EXPECT_EQ(b.boundaries[i].normal, a.boundaries[i].normal);  // bit for bit
    EXPECT_EQ(b.boundaries[i].hold, a.boundaries[i].hold);
    ASSERT_EQ(b.boundaries[i].axes.has_value(), a.boundaries[i].axes.has_value());
    if (a.boundaries[i].axes) {
      EXPECT_EQ(b.boundaries[i].axes->x, a.boundaries[i].axes->x);  // bit for bit
      EXPECT_EQ(b.boundaries[i].axes->y, a.boundaries[i].axes->y);
    }
  }
  ASSERT_EQ(b.prescribed_motions.size(), a.prescribed_motions.size());
  for (std::size_t i = 0; i < a.prescribed_motions.size(); ++i) {
    SCOPED_TRACE(i);
    const sf::PrescribedMotionConfig& p = a.prescribed_motions[i];
    const sf::PrescribedMotionConfig& q = b.prescribed_motions[i];
    EXPECT_EQ(q.group, p.group);
    EXPECT_EQ(q.type, p.type);
    EXPECT_EQ(q.dof, p.dof);
    EXPECT_EQ(q.value, p.value);
    EXPECT_EQ(q.curve.times, p.curve.times);
    EXPECT_EQ(q.curve.values, p.curve.values);
    ASSERT_EQ(q.axes.has_value(), p.axes.has_value());
    if (p.axes) {
      EXPECT_EQ(q.axes->x, p.axes->x);
      EXPECT_EQ(q.axes->y, p.axes->y);
    }
  }
  // The odd axes really were changed on reading (so the bit-for-bit check above means something):
  // unit length, perpendicular.
  const sf::AxesConfig& odd = *a.boundaries[5].axes;
  EXPECT_NE(odd.x[0], 0.3);
  EXPECT_NEAR(odd.x[0] * odd.x[0] + odd.x[1] * odd.x[1] + odd.x[2] * odd.x[2], 1.0, 1e-15);
  EXPECT_NEAR(odd.x[0] * odd.y[0] + odd.x[1] * odd.y[1] + odd.x[2] * odd.y[2], 0.0, 1e-15);
}

TEST_F(ReadCase, OldBoundaryTypesReadUnchanged) {
  const sf::CaseConfig c = sf::read_case(write_case(kFull));
  ASSERT_EQ(c.boundaries.size(), 3u);
  EXPECT_EQ(c.boundaries[0].type, sf::BoundaryConfig::Type::symmetry);
  EXPECT_EQ(c.boundaries[0].axis, 0);
  EXPECT_EQ(c.boundaries[1].axis, 1);
  EXPECT_EQ(c.boundaries[2].type, sf::BoundaryConfig::Type::fixed);
  for (const sf::BoundaryConfig& b : c.boundaries) {
    EXPECT_FALSE(b.axes.has_value());
    EXPECT_FALSE(b.normal.has_value());
    EXPECT_EQ(b.hold, (std::array<bool, 6>{}));
  }
  // Written back as before: no axes, normal or hold keys.
  const std::string resolved = sf::format_resolved_case(c);
  EXPECT_EQ(resolved.find("axes ="), std::string::npos);
  EXPECT_EQ(resolved.find("hold ="), std::string::npos);
}

}  // namespace
