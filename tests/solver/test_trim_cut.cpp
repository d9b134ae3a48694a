// Trimming by clean cuts (solver/trim_cut.hpp, issue 32 item 3) on parts made here: a flat and a
// tilted plate of distorted quads, and a spherical cap. What the cut must give is known exactly:
// - the part's edge is the line: every node the cut makes or moves lies on it (to the bisection's
//   round-off), and the kept region is bounded by the mesh's outer edge and the line alone (no
//   crack, no overlap: every edge has one or two elements, every free edge lies on one of them);
// - the kept area is the area on the kept side (a straight line: the rectangle; a circle: the
//   polygon of the edge's nodes, which lie on it);
// - the state follows: a node field linear in the coordinates stays linear (its values at the
//   made nodes are interpolated on their edge), a uniform stress, back stress and transverse
//   shear read in each piece's own frame are the same tensor and vector, hourglass resultants
//   of pieces start at zero and whole elements keep theirs, directors stay unit;
// - no piece below the sliver fraction unless a node group forbids the move that would avoid it.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "core/errors.hpp"
#include "element/element_block.hpp"
#include "element/shell_geometry.hpp"
#include "element/shell_triangle_geometry.hpp"
#include "part_measures.hpp"
#include "solver/part_remap.hpp"
#include "solver/trim_cut.hpp"

namespace sf {
namespace {

using Place = std::function<Vec3(const Vec3&)>;

// A uniform in-plane stress (MPa) and transverse shear (MPa) of a plate in the plane z = 0.3 X +
// 0.1 Y, in global components.
Mat3 plane_basis() {
  const Vec3 e1 = Vec3(1.0, 0.0, 0.3).normalized();
  const Vec3 e3 = Vec3(1.0, 0.0, 0.3).cross(Vec3(0.0, 1.0, 0.1)).normalized();
  Mat3 b;
  b << e1, e3.cross(e1), e3;
  return b;
}
Mat3 global_stress() {
  Mat3 in_plane = Mat3::Zero();
  in_plane(0, 0) = 120.0;
  in_plane(1, 1) = -45.0;
  in_plane(0, 1) = in_plane(1, 0) = 33.0;
  const Mat3 b = plane_basis();
  return b * in_plane * b.transpose();
}
Vec3 global_shear() {
  return plane_basis() * Vec3(7.0, -3.0, 0.0);
}

// The frame of element e of the part at its current coordinates.
Mat3 frame_of(const FormedPart& p, int e) {
  const std::vector<double>& x = p.fields.at("x");
  const std::vector<int> nodes = part_element_nodes(p, e);
  auto at = [&](int n) { return Vec3(x[3 * n], x[3 * n + 1], x[3 * n + 2]); };
  if (nodes.size() == 4) {
    Quad3 q;
    for (int a = 0; a < 4; ++a)
      q.col(a) = at(nodes[a]);
    ShellGeometry g;
    EXPECT_TRUE(compute_shell_geometry(q, g)) << "element " << e;
    return g.frame;
  }
  Tri3 t;
  for (int a = 0; a < 3; ++a)
    t.col(a) = at(nodes[a]);
  TriangleGeometry g;
  EXPECT_TRUE(compute_triangle_geometry(t, g)) << "element " << e;
  return g.frame;
}

Vec3 linear_velocity(const Vec3& x) {
  return Vec3(3.0 * x(0) - x(1) + 2.0, 0.5 * x(2) + 7.0, x(0) + x(1) - 4.0 * x(2));
}

// An n x n grid of quads over [x0, x0 + n]^2 (reference, z = 0), interior nodes shifted by up
// to `distortion` mm, standing at place(reference); groups "bottom" (Y = y0) and "left" (X = x0).
FormedPart grid(int n, double x0, double distortion, const Place& place) {
  FormedPart p;
  p.file = "grid.h5";
  const int side = n + 1;
  p.reference_nodes.resize(3, side * side);
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) {
      const bool interior = i > 0 && j > 0 && i < n && j < n;
      const double dx = interior ? distortion * std::sin(1.7 * i + 2.3 * j) : 0.0;
      const double dy = interior ? distortion * std::cos(1.3 * i - 0.7 * j) : 0.0;
      p.reference_nodes.col(j * side + i) = Vec3(x0 + i + dx, x0 + j + dy, 0.0);
      p.node_tags.push_back(1000 + j * side + i);
      if (j == 0)
        p.groups["bottom"].push_back(j * side + i);
      if (i == 0)
        p.groups["left"].push_back(j * side + i);
    }
  }
  p.quads.resize(4, n * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * side + i;
      p.quads.col(j * n + i) << a, a + 1, a + side + 1, a + side;
    }
  }
  p.triangles.resize(3, 0);
  p.n_points = 2;
  p.rule = "gauss";
  p.law = "armstrong_frederick";
  std::vector<double> x, v;
  for (int k = 0; k < side * side; ++k) {
    const Vec3 at = place(p.reference_nodes.col(k));
    const Vec3 vel = linear_velocity(at);
    for (int c = 0; c < 3; ++c) {
      x.push_back(at(c));
      v.push_back(vel(c));
    }
  }
  p.fields = {{"time", {2e-3}}, {"x", x}, {"v", v}, {"tools/0/travel", {40.0}}};
  const int elements = n * n;
  std::vector<double> sxx, syy, sxy, back, sxz, syz, thickness, hourglass, director;
  const Mat3 sigma = global_stress();
  const Vec3 q = global_shear();
  for (int e = 0; e < elements; ++e) {
    const Mat3 f = frame_of(p, e);
    const Mat3 local = f.transpose() * sigma * f;
    for (int k = 0; k < p.n_points; ++k) {
      sxx.push_back(local(0, 0) * (1 + k));
      syy.push_back(local(1, 1) * (1 + k));
      sxy.push_back(local(0, 1) * (1 + k));
      back.insert(back.end(), {0.5 * local(0, 0), 0.5 * local(1, 1), 0.5 * local(0, 1)});
    }
    sxz.push_back(q.dot(f.col(0)));
    syz.push_back(q.dot(f.col(1)));
    thickness.push_back(0.9 + 0.001 * e);
    hourglass.insert(hourglass.end(), 6, e + 1.0);
    for (int a = 0; a < 4; ++a) {
      director.insert(director.end(), {f(0, 2), f(1, 2), f(2, 2)});
    }
  }
  p.initial_thickness.assign(static_cast<std::size_t>(elements), 1.0);
  p.fields["shell/sxx"] = sxx;
  p.fields["shell/syy"] = syy;
  p.fields["shell/sxy"] = sxy;
  p.fields["shell/back_stress"] = back;
  p.fields["shell/sxz"] = sxz;
  p.fields["shell/syz"] = syz;
  p.fields["shell/thickness"] = thickness;
  p.fields["shell/hourglass"] = hourglass;
  p.fields["shell/director"] = director;
  return p;
}

Vec3 tilt(const Vec3& r) {
  return Vec3(r(0), r(1), 0.3 * r(0) + 0.1 * r(1));
}

// Keep what projects (along -z) on the side x < at (or x > at).
TrimOutline half_plane_x(double at, bool keep_below) {
  return TrimOutline::polyline(
      {Vec3(-100, -100, 0), Vec3(at, -100, 0), Vec3(at, 100, 0), Vec3(-100, 100, 0)},
      Vec3(0, 0, -1), keep_below);
}

using test::free_edges;
using test::projected_area;
Vec3 node(const FormedPart& p, int n) {
  return test::node_at(p, n);
}

TEST(TrimCut, AStraightLineBecomesThePartsEdgeOnATiltedDistortedPlate) {
  const FormedPart part = grid(6, 0.0, 0.2, tilt);
  TrimSummary s;
  const FormedPart cut = trim_by_cutting(part, half_plane_x(3.37, true), 0.1, &s);
  EXPECT_GT(s.elements_cut, 0);
  EXPECT_GT(s.nodes_made, 0);
  EXPECT_GE(s.smallest_fraction, 0.1);
  EXPECT_EQ(s.piece_elements.size(), 1u);
  // Kept area: the rectangle 3.37 x 6 seen along z (the cut's round-off: ~1e-15 per node).
  EXPECT_NEAR(projected_area(cut), 3.37 * 6.0, 1e-9);
  for (int n = 0; n < cut.reference_nodes.cols(); ++n) {
    EXPECT_LE(node(cut, n)(0), 3.37 + 1e-12) << "node " << n;
    // The current coordinates still lie on the plate and follow from the reference ones.
    EXPECT_NEAR((node(cut, n) - tilt(cut.reference_nodes.col(n))).norm(), 0.0, 1e-12);
  }
  for (const auto& [a, b] : free_edges(cut)) {
    const Vec3 mid = 0.5 * (node(cut, a) + node(cut, b));
    const bool outer =
        std::abs(mid(0)) < 1e-12 || std::abs(mid(1)) < 1e-12 || std::abs(mid(1) - 6.0) < 1e-12;
    const bool on_line =
        std::abs(node(cut, a)(0) - 3.37) < 1e-12 && std::abs(node(cut, b)(0) - 3.37) < 1e-12;
    EXPECT_TRUE(outer || on_line) << "free edge " << a << "-" << b << " at " << mid.transpose();
  }
  // The bottom edge's group gains the node made on it; its nodes stay on Y = 0.
  for (int n : cut.groups.at("bottom")) {
    EXPECT_EQ(cut.reference_nodes(1, n), 0.0);
  }
  EXPECT_EQ(cut.groups.at("bottom").size(), 5u);  // X = 0, 1, 2, 3 and the line's
}

TEST(TrimCut, TheStateIsTurnedIntoEachPiecesFrame) {
  const FormedPart part = grid(6, 0.0, 0.2, tilt);
  TrimSummary s;
  // A line across the elements' diagonals makes pieces whose e1 differs from their parent's.
  const FormedPart cut =
      trim_by_cutting(part,
                      TrimOutline::polyline({Vec3(-1, -1, 0), Vec3(7.3, -1, 0), Vec3(-1, 7.1, 0)},
                                            Vec3(0, 0, -1), true),
                      0.1, &s);
  ASSERT_GT(s.pieces_made, 0);
  EXPECT_GT(cut.triangles.cols(), 0);
  const Mat3 sigma = global_stress();
  const Vec3 q = global_shear();
  const ElementBlocks blocks = element_blocks(cut.quads, cut.triangles);
  const int elements = blocks.element_count();
  const std::size_t points = 2;
  int turned = 0;
  for (int e = 0; e < elements; ++e) {
    const Mat3 f = frame_of(cut, e);
    const auto at = [&](const char* key, std::size_t i) { return cut.fields.at(key)[i]; };
    for (std::size_t k = 0; k < points; ++k) {
      const std::size_t i = static_cast<std::size_t>(e) * points + k;
      Mat3 local = Mat3::Zero();
      local(0, 0) = at("shell/sxx", i);
      local(1, 1) = at("shell/syy", i);
      local(0, 1) = local(1, 0) = at("shell/sxy", i);
      EXPECT_LT((f * local * f.transpose() - (1.0 + k) * sigma).norm(), 1e-9) << "element " << e;
      Mat3 back = Mat3::Zero();
      back(0, 0) = at("shell/back_stress", 3 * i);
      back(1, 1) = at("shell/back_stress", 3 * i + 1);
      back(0, 1) = back(1, 0) = at("shell/back_stress", 3 * i + 2);
      EXPECT_LT((f * back * f.transpose() - 0.5 * sigma).norm(), 1e-9) << "element " << e;
    }
    const Vec3 shear = at("shell/sxz", e) * f.col(0) + at("shell/syz", e) * f.col(1);
    EXPECT_LT((shear - q).norm(), 1e-9) << "element " << e;
    const double hourglass = at("shell/hourglass", 6 * static_cast<std::size_t>(e));
    turned += hourglass == 0.0 ? 1 : 0;
    for (int a = 0; a < blocks.of(e).nodes_per_element(); ++a) {
      const Vec3 d(at("shell/director", 12 * e + 3 * a), at("shell/director", 12 * e + 3 * a + 1),
                   at("shell/director", 12 * e + 3 * a + 2));
      EXPECT_NEAR(d.norm(), 1.0, 1e-12);
      EXPECT_GT(d.dot(f.col(2)), 0.999) << "element " << e;
    }
  }
  // The hourglass resultants of the pieces and of the elements a moved node reshaped start at
  // zero; every element kept as it was keeps its own.
  EXPECT_EQ(turned, s.pieces_made + s.elements_reshaped);
  // A node field linear in the coordinates stays linear.
  const std::vector<double>& v = cut.fields.at("v");
  for (int n = 0; n < cut.reference_nodes.cols(); ++n) {
    const Vec3 expected = linear_velocity(node(cut, n));
    EXPECT_LT((Vec3(v[3 * n], v[3 * n + 1], v[3 * n + 2]) - expected).norm(), 1e-9);
  }
  EXPECT_EQ(cut.fields.at("tools/0/travel"), std::vector<double>{40.0});
  EXPECT_EQ(cut.fields.at("time"), std::vector<double>{2e-3});
}

TEST(TrimCut, ACircleOnASphericalCapIsTheEdgeThroughTheMadeNodes) {
  const double radius = 20.0;
  const Place sphere = [&](const Vec3& r) {
    return Vec3(r(0), r(1), std::sqrt(radius * radius - r(0) * r(0) - r(1) * r(1)) - radius);
  };
  const FormedPart part = grid(10, -5.0, 0.25, sphere);
  const double r = 3.3;
  std::vector<Vec3> circle;
  for (int k = 0; k < 720; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 720.0;
    circle.emplace_back(r * std::cos(a), r * std::sin(a), 5.0);
  }
  TrimSummary s;
  const FormedPart cut =
      trim_by_cutting(part, TrimOutline::polyline(circle, Vec3(0, 0, -1), true), 0.1, &s);
  EXPECT_GE(s.smallest_fraction, 0.1);
  EXPECT_EQ(s.piece_elements.size(), 1u);
  // Every free edge joins two nodes on the circle (the 720-gon: radius within its sagitta).
  const double sagitta = r * (1.0 - std::cos(std::numbers::pi / 720.0));
  std::vector<std::pair<double, Vec2>> edge_nodes;
  for (const auto& [a, b] : free_edges(cut)) {
    for (int n : {a, b}) {
      const double rn = node(cut, n).head<2>().norm();
      EXPECT_GE(rn, r - sagitta - 1e-12) << "node " << n;
      EXPECT_LE(rn, r + 1e-12) << "node " << n;
      edge_nodes.emplace_back(std::atan2(node(cut, n)(1), node(cut, n)(0)), node(cut, n).head<2>());
    }
  }
  // The kept area is the polygon of those nodes (each appears twice: once per free edge).
  std::sort(edge_nodes.begin(), edge_nodes.end(),
            [](const auto& p, const auto& q) { return p.first < q.first; });
  double polygon = 0.0;
  for (std::size_t k = 0; k < edge_nodes.size(); k += 2) {
    const Vec2& p = edge_nodes[k].second;
    const Vec2& q = edge_nodes[(k + 2) % edge_nodes.size()].second;
    polygon += 0.5 * (p(0) * q(1) - p(1) * q(0));
  }
  EXPECT_NEAR(projected_area(cut), polygon, 1e-9);
  EXPECT_LT(polygon, std::numbers::pi * r * r);
  const std::vector<double>& v = cut.fields.at("v");
  for (int n = 0; n < cut.reference_nodes.cols(); ++n) {
    const Vec3 expected = linear_velocity(node(cut, n));
    EXPECT_LT((Vec3(v[3 * n], v[3 * n + 1], v[3 * n + 2]) - expected).norm(), 1e-9);
  }
}

TEST(TrimCut, ALineNearNodesMovesThemOntoItInsteadOfMakingSlivers) {
  // Near the kept nodes at X = 3: they move 0.02 mm onto the line, and their column goes.
  TrimSummary s;
  FormedPart cut = trim_by_cutting(grid(6, 0.0, 0.0, tilt), half_plane_x(3.02, true), 0.1, &s);
  EXPECT_EQ(s.nodes_made, 0);
  EXPECT_EQ(s.nodes_moved, 7);
  EXPECT_NEAR(s.largest_move, 0.02 * std::sqrt(1.0 + 0.09), 1e-12);
  EXPECT_EQ(s.elements_removed, 18);
  EXPECT_NEAR(projected_area(cut), 3.02 * 6.0, 1e-12);
  // Near the scrap nodes at X = 4: they move onto the line, their elements stay whole.
  cut = trim_by_cutting(grid(6, 0.0, 0.0, tilt), half_plane_x(3.95, true), 0.1, &s);
  EXPECT_EQ(s.nodes_made, 0);
  EXPECT_EQ(s.nodes_moved, 7);
  EXPECT_EQ(s.elements_removed, 12);
  EXPECT_NEAR(s.smallest_fraction, 0.95, 1e-12);
  EXPECT_NEAR(projected_area(cut), 3.95 * 6.0, 1e-12);
  // Midway: the line makes nodes and halves the elements.
  cut = trim_by_cutting(grid(6, 0.0, 0.0, tilt), half_plane_x(3.5, true), 0.1, &s);
  EXPECT_EQ(s.nodes_made, 7);
  EXPECT_EQ(s.elements_cut, 6);
  EXPECT_EQ(s.pieces_made, 6);
  EXPECT_NEAR(s.smallest_fraction, 0.5, 1e-12);
}

TEST(TrimCut, ANodeOnAGroupsEdgeIsNotMovedOffIt) {
  // Keep a 0.04 mm strip above the bottom edge: moving the bottom nodes up would take them off
  // Y = 0 (the group "bottom"), so the strip stays a sliver, reported.
  TrimSummary s;
  const TrimOutline strip = TrimOutline::polyline(
      {Vec3(-1, -1, 0), Vec3(7, -1, 0), Vec3(7, 0.04, 0), Vec3(-1, 0.04, 0)}, Vec3(0, 0, -1), true);
  const FormedPart cut = trim_by_cutting(grid(6, 0.0, 0.0, tilt), strip, 0.1, &s);
  EXPECT_EQ(s.nodes_moved, 0);
  EXPECT_EQ(s.nodes_made, 7);
  EXPECT_NEAR(s.smallest_fraction, 0.04, 1e-12);
  for (int n : cut.groups.at("bottom")) {
    EXPECT_EQ(node(cut, n)(1), 0.0);
  }
  // Without the group the bottom nodes move onto the line, and nothing is left.
  FormedPart free = grid(6, 0.0, 0.0, tilt);
  free.groups.clear();
  EXPECT_THROW(
      {
        try {
          trim_by_cutting(free, strip, 0.1, &s);
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("leaves no part"), std::string::npos) << e.what();
          throw;
        }
      },
      InputError);
}

TEST(TrimCut, ALineThatMissesOrAFractionOutOfRangeIsAnError) {
  const FormedPart part = grid(4, 0.0, 0.1, tilt);
  EXPECT_THROW(trim_by_cutting(part, half_plane_x(50.0, true)), InputError);
  EXPECT_THROW(trim_by_cutting(part, half_plane_x(-50.0, true)), InputError);
  EXPECT_THROW(trim_by_cutting(part, half_plane_x(2.5, true), 0.5), InputError);
  EXPECT_THROW(trim_by_cutting(part, half_plane_x(2.5, true), -0.1), InputError);
}

}  // namespace
}  // namespace sf
