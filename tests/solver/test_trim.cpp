// Trimming a formed part by removal (solver/trim.hpp, issue 32 item 3), on a part made here: a
// strip of three unit quads along x, with a field of every kind. What each field becomes is
// known exactly: the kept nodes' and elements' values in their order, the recomputed fields and
// the contact history left out, the run's and the tools' numbers as they were.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.hpp"
#include "solver/trim.hpp"

namespace sf {
namespace {

// Nodes 0..3 at (i, 0, 0), 4..7 at (i - 4, 1, 0); quads e: (e, e + 1, e + 5, e + 4).
FormedPart strip() {
  FormedPart p;
  p.file = "strip.h5";
  p.reference_nodes.resize(3, 8);
  for (int i = 0; i < 8; ++i) {
    p.reference_nodes.col(i) = Vec3(i % 4, i / 4, 0.0);
  }
  p.node_tags = {11, 12, 13, 14, 15, 16, 17, 18};
  p.quads.resize(4, 3);
  for (int e = 0; e < 3; ++e) {
    p.quads.col(e) << e, e + 1, e + 5, e + 4;
  }
  p.triangles.resize(3, 0);
  p.initial_thickness = {1.0, 1.0, 1.0};
  p.groups = {{"left", {0, 4}}, {"right", {3, 7}}};
  p.n_points = 2;
  p.rule = "gauss";
  p.law = "von_mises";
  p.tools = {"punch"};
  p.contact_tools = {"punch"};
  std::vector<double> x, v;
  for (int i = 0; i < 8; ++i) {
    for (int c = 0; c < 3; ++c) {
      x.push_back(p.reference_nodes(c, i) + (c == 2 ? 0.1 * i : 0.0));  // as it stands
      v.push_back(100.0 * i + c);
    }
  }
  p.fields = {{"time", {1e-3}},
              {"x", x},
              {"v", v},
              {"mass", std::vector<double>(8, 2.5)},
              {"shell/thickness", {0.8, 0.9, 1.0}},
              {"shell/sxx", {10.0, 11.0, 20.0, 21.0, 30.0, 31.0}},
              {"tools/0/travel", {5.0}},
              {"contacts/0/stick_force", std::vector<double>(24, 1.0)}};
  return p;
}

TrimOutline box(double x0, double x1, bool keep_inside) {
  return TrimOutline::polyline(
      {Vec3(x0, -1.0, 0.0), Vec3(x1, -1.0, 0.0), Vec3(x1, 2.0, 0.0), Vec3(x0, 2.0, 0.0)},
      Vec3(0.0, 0.0, -1.0), keep_inside);
}

TEST(Trim, RemovesTheScrapAndRenumbersWithTheStateFollowing) {
  TrimSummary summary;
  const FormedPart t = trim_by_removal(strip(), box(-1.0, 2.2, true), &summary);
  EXPECT_EQ(summary.elements_before, 3);
  EXPECT_EQ(summary.elements_removed, 1);
  EXPECT_EQ(summary.nodes_removed, 2);
  EXPECT_EQ(summary.piece_elements, std::vector<int>{2});
  // Kept nodes 0, 1, 2, 4, 5, 6 become 0..5.
  ASSERT_EQ(t.reference_nodes.cols(), 6);
  EXPECT_EQ(t.reference_nodes.col(3), Vec3(0.0, 1.0, 0.0));
  EXPECT_EQ(t.node_tags, (std::vector<double>{11, 12, 13, 15, 16, 17}));
  QuadConn quads(4, 2);
  quads.col(0) << 0, 1, 4, 3;
  quads.col(1) << 1, 2, 5, 4;
  EXPECT_EQ(t.quads, quads);
  EXPECT_EQ(t.groups.at("left"), (std::vector<int>{0, 3}));
  EXPECT_TRUE(t.groups.at("right").empty());
  EXPECT_EQ(t.initial_thickness, (std::vector<double>{1.0, 1.0}));
  // Node fields that interpolate: the kept nodes' values in order.
  const std::vector<double>& v = t.fields.at("v");
  ASSERT_EQ(v.size(), 18u);
  EXPECT_EQ(v[9], 400.0);  // new node 3 is old node 4
  EXPECT_EQ(v[17], 602.0);
  // Element and point fields: the kept elements' values whole.
  EXPECT_EQ(t.fields.at("shell/thickness"), (std::vector<double>{0.8, 0.9}));
  EXPECT_EQ(t.fields.at("shell/sxx"), (std::vector<double>{10.0, 11.0, 20.0, 21.0}));
  // The run's and the tools' numbers as they were; masses and contact history left out.
  EXPECT_EQ(t.fields.at("time"), std::vector<double>{1e-3});
  EXPECT_EQ(t.fields.at("tools/0/travel"), std::vector<double>{5.0});
  EXPECT_FALSE(t.fields.contains("mass"));
  EXPECT_FALSE(t.fields.contains("contacts/0/stick_force"));
}

TEST(Trim, APieceLeftApartIsCounted) {
  TrimSummary summary;
  const FormedPart t = trim_by_removal(strip(), box(1.2, 1.8, false), &summary);
  EXPECT_EQ(summary.elements_removed, 1);
  EXPECT_EQ(summary.nodes_removed, 0);  // every node still belongs to a kept element
  EXPECT_EQ(summary.piece_elements, (std::vector<int>{1, 1}));
  EXPECT_EQ(t.quads.cols(), 2);
}

TEST(Trim, ALineThatMissesOrLeavesNothingIsAnError) {
  const auto message = [](const TrimOutline& o) {
    try {
      trim_by_removal(strip(), o);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(message(box(-1.0, 5.0, true)).find("strip.h5: the trim line misses the part"),
            std::string::npos);
  EXPECT_NE(message(box(-1.0, 5.0, false)).find("leaves no part"), std::string::npos);
  EXPECT_NE(message(TrimOutline::polyline({Vec3(0, 0, 0), Vec3(1, 0, 0)}, Vec3(0, 0, -1), true))
                .find("at least 3"),
            std::string::npos);
  // Seen along x, the box in the xy plane has no area.
  TrimOutline edge_on = box(-1.0, 2.2, true);
  edge_on.direction = Vec3(1.0, 0.0, 0.0);
  EXPECT_NE(message(edge_on).find("encloses no area"), std::string::npos);
}

}  // namespace
}  // namespace sf
