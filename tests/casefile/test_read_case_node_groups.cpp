// [[node_group]]: blank nodes chosen by position (a plane, a box, the outline, the node nearest a
// point) for a blank from a file without physical groups. Reading, the resolved case written and
// read back bit for bit, and the errors, each naming the table's key.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "casefile/case_config.hpp"
#include "read_case_fixture.hpp"

namespace {

using sf_test::kMinimal;
using sf_test::ReadCase;

constexpr std::string_view kGroups = R"toml(
[[node_group]]
name = "sym_x"
normal = [3.0, 0.0, 0.0]

[[node_group]]
name = "flange_edge"
box = [-1.0, 40.0, -1.0, 70.0, 60.0, 1.0]
outline = true
tolerance = 0.05

[[node_group]]
name = "tip"
point = [65.0, 50.0, 0.0]

[[node_group]]
name = "tilted"
point = [1.0, 2.0, 3.0]
normal = [1.0, 1.0, 0.0]
)toml";

TEST_F(ReadCase, NodeGroupsAreReadWithTheirNormalsNormalised) {
  const sf::CaseConfig c = sf::read_case(write_case(std::string(kMinimal) + std::string(kGroups)));
  ASSERT_EQ(c.node_groups.size(), 4u);
  const sf::NodeGroupConfig& sym = c.node_groups[0];
  EXPECT_EQ(sym.name, "sym_x");
  EXPECT_EQ(sym.normal, (std::vector<double>{1.0, 0.0, 0.0}));
  EXPECT_TRUE(sym.point.empty());
  EXPECT_EQ(sym.tolerance, 0.0);  // the default: 1 % of the shortest element edge
  EXPECT_FALSE(sym.nearest());
  const sf::NodeGroupConfig& edge = c.node_groups[1];
  EXPECT_EQ(edge.box, (std::vector<double>{-1.0, 40.0, -1.0, 70.0, 60.0, 1.0}));
  EXPECT_TRUE(edge.outline);
  EXPECT_EQ(edge.tolerance, 0.05);
  EXPECT_TRUE(c.node_groups[2].nearest());
  EXPECT_DOUBLE_EQ(c.node_groups[3].normal[0], std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(c.node_groups[3].normal[1], std::sqrt(0.5));
  EXPECT_GT(c.node_groups[0].line, 0);
}

TEST_F(ReadCase, ResolvedCaseWritesNodeGroupsBackBitForBit) {
  const sf::CaseConfig c = sf::read_case(write_case(std::string(kMinimal) + std::string(kGroups)));
  const std::string resolved = sf::format_resolved_case(c);
  sf_test::expect_contains(resolved, "[[node_group]]\nname = \"tip\"\npoint = [65.0, 50.0, 0.0]");
  const sf::CaseConfig again = sf::read_case(write_case(resolved, "resolved/case.toml"));
  ASSERT_EQ(again.node_groups.size(), c.node_groups.size());
  for (std::size_t i = 0; i < c.node_groups.size(); ++i) {
    SCOPED_TRACE(c.node_groups[i].name);
    EXPECT_EQ(again.node_groups[i].name, c.node_groups[i].name);
    EXPECT_EQ(again.node_groups[i].point, c.node_groups[i].point);
    EXPECT_EQ(again.node_groups[i].normal, c.node_groups[i].normal);
    EXPECT_EQ(again.node_groups[i].box, c.node_groups[i].box);
    EXPECT_EQ(again.node_groups[i].outline, c.node_groups[i].outline);
    EXPECT_EQ(again.node_groups[i].tolerance, c.node_groups[i].tolerance);
  }
}

TEST_F(ReadCase, BadNodeGroupsAreRefusedNamingTheKey) {
  const auto message = [&](const std::string& table) -> std::string {
    try {
      sf::read_case(write_case(std::string(kMinimal) + "\n[[node_group]]\n" + table));
    } catch (const sf::InputError& e) {
      return e.what();
    }
    return "no error";
  };
  sf_test::expect_contains(message("name = \"a\"\n"),
                           "node_group[0].normal: missing required key in [node_group[0]] "
                           "(expected at least one of point, normal, box, outline = true");
  sf_test::expect_contains(message("normal = [1, 0, 0]\n"), "node_group[0].name");
  sf_test::expect_contains(message("name = \"a\"\nnormal = [0, 0, 0]\n"), "node_group[0].normal");
  sf_test::expect_contains(message("name = \"a\"\nnormal = [0, 0, 0]\n"), "not all zero");
  sf_test::expect_contains(message("name = \"a\"\nbox = [0, 0, 0, 1, -1, 1]\n"),
                           "(y min 0 > max -1)");
  sf_test::expect_contains(message("name = \"a\"\nbox = [0, 0, 0, 1, 1]\n"), "node_group[0].box");
  sf_test::expect_contains(message("name = \"a\"\npoint = [0, 0, 0]\noutline = true\n"),
                           "not with box or outline");
  sf_test::expect_contains(message("name = \"a b\"\noutline = true\n"), "node_group[0].name");
  sf_test::expect_contains(message("name = \"a\"\noutline = true\nplane = [0, 0, 1]\n"), "plane");
  sf_test::expect_contains(
      message("name = \"a\"\noutline = true\n[[node_group]]\nname = \"a\"\nnormal = [0, 0, 1]\n"),
      "node group \"a\" is already defined by node_group[0]");
}

}  // namespace
