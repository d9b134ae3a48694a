// Rank plans (issue 17): on a small mixed mesh partitioned 1 to 4 ways, by METIS and by hand,
// every rank's node gather lists must name exactly the serial assembly order (all corners of the
// node, ascending global slot), with remote corners resolved through the neighbours' send lists.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "parallel/mesh_partition.hpp"
#include "parallel/rank_plan.hpp"

namespace sf {
namespace {

// A 6 x 5 grid of quads with a strip of 10 triangles along its right side (48 nodes, 40
// elements), node ids scrambled so that node order and element order differ.
struct Mesh {
  std::vector<int> quads;
  std::vector<int> triangles;
  int n_nodes = 48;

  BlankTopology topology() const { return BlankTopology{quads, triangles, n_nodes}; }
};

Mesh mixed_mesh() {
  Mesh m;
  const auto id = [](int i, int j) { return (11 * (i < 7 ? j * 7 + i : 42 + j)) % 48; };
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 6; ++i) {
      m.quads.insert(m.quads.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  for (int j = 0; j < 5; ++j) {
    m.triangles.insert(m.triangles.end(), {id(6, j), id(7, j), id(7, j + 1)});
    m.triangles.insert(m.triangles.end(), {id(6, j), id(7, j + 1), id(6, j + 1)});
  }
  return m;
}

// The serial order by brute force: every slot, ascending, at the node it names.
std::vector<std::vector<int>> serial_lists(const BlankTopology& t) {
  std::vector<std::vector<int>> lists(static_cast<std::size_t>(t.n_nodes));
  for (int s = 0; s < t.n_corners(); ++s) {
    lists[static_cast<std::size_t>(t.node_of_slot(s))].push_back(s);
  }
  return lists;
}

std::vector<int> stripes(const BlankTopology& t, int parts) {
  std::vector<int> part;
  for (int e = 0; e < t.n_elements(); ++e) {
    const bool quad = t.blocks.of(e).shape == ElementShape::quad;
    const int column = quad ? e % 6 : 6;  // the triangles are column 6
    part.push_back(column * parts / 7);
  }
  return part;
}

std::vector<int> scattered(const BlankTopology& t, int parts) {
  std::vector<int> part;
  for (int e = 0; e < t.n_elements(); ++e) {
    part.push_back((5 * e + e / 3) % parts);  // no contiguity at all: many neighbours
  }
  return part;
}

std::vector<int> metis(const BlankTopology& t, int parts) {
  return partition_elements(t, {}, parts, 17);
}

std::vector<RankPlan> all_plans(const BlankTopology& t, const std::vector<int>& part, int ranks) {
  std::vector<RankPlan> plans;
  for (int r = 0; r < ranks; ++r) {
    plans.push_back(build_rank_plan(t, part, r, ranks));
  }
  return plans;
}

const RankNeighbour* find_neighbour(const RankPlan& plan, int rank) {
  for (const RankNeighbour& k : plan.neighbours) {
    if (k.rank == rank) {
      return &k;
    }
  }
  return nullptr;
}

// The global slot an entry of `plan` names: its own slot, or the sender's send slot.
int global_slot(const std::vector<RankPlan>& plans, const RankPlan& plan, int entry) {
  if (entry >= 0) {
    return entry;
  }
  const int j = -1 - entry;
  for (const RankNeighbour& k : plan.neighbours) {
    if (j >= k.receive_offset && j < k.receive_offset + k.receive_count) {
      const RankNeighbour* back =
          find_neighbour(plans[static_cast<std::size_t>(k.rank)], plan.rank);
      EXPECT_NE(back, nullptr);
      return back ? back->send_slots[static_cast<std::size_t>(j - k.receive_offset)] : -1;
    }
  }
  ADD_FAILURE() << "receive index " << j << " in no neighbour's range";
  return -1;
}

void expect_elements_shared_out(const BlankTopology& t, const std::vector<int>& part,
                                const std::vector<RankPlan>& plans) {
  std::vector<int> seen(static_cast<std::size_t>(t.n_elements()), 0);
  for (const RankPlan& plan : plans) {
    EXPECT_TRUE(std::is_sorted(plan.elements.begin(), plan.elements.end()));
    for (const int e : plan.elements) {
      ++seen[static_cast<std::size_t>(e)];
      EXPECT_EQ(part[static_cast<std::size_t>(e)], plan.rank);
    }
  }
  EXPECT_EQ(seen, std::vector<int>(seen.size(), 1));
}

void expect_nodes_owned_once(const BlankTopology& t, const std::vector<RankPlan>& plans) {
  std::vector<int> owners(static_cast<std::size_t>(t.n_nodes), 0);
  for (const RankPlan& plan : plans) {
    EXPECT_TRUE(std::is_sorted(plan.nodes.begin(), plan.nodes.end()));
    EXPECT_TRUE(std::includes(plan.nodes.begin(), plan.nodes.end(), plan.owned_nodes.begin(),
                              plan.owned_nodes.end()));
    for (const int n : plan.owned_nodes) {
      ++owners[static_cast<std::size_t>(n)];
    }
  }
  EXPECT_EQ(owners, std::vector<int>(owners.size(), 1));
}

// Held = touched by the rank's elements; the lowest holder owns.
void expect_held_nodes(const BlankTopology& t, const std::vector<RankPlan>& plans) {
  std::vector<std::set<int>> holders(static_cast<std::size_t>(t.n_nodes));
  for (const RankPlan& plan : plans) {
    std::set<int> touched;
    for (const int e : plan.elements) {
      for (int a = 0; a < t.corner_count(e); ++a) {
        touched.insert(t.node_of_slot(t.first_slot(e) + a));
        holders[static_cast<std::size_t>(t.node_of_slot(t.first_slot(e) + a))].insert(plan.rank);
      }
    }
    EXPECT_EQ(plan.nodes, std::vector<int>(touched.begin(), touched.end()));
  }
  for (const RankPlan& plan : plans) {
    for (const int n : plan.owned_nodes) {
      EXPECT_EQ(*holders[static_cast<std::size_t>(n)].begin(), plan.rank) << "node " << n;
    }
  }
}

void expect_neighbours_consistent(const std::vector<RankPlan>& plans) {
  for (const RankPlan& plan : plans) {
    int offset = 0;
    int previous = -1;
    for (const RankNeighbour& k : plan.neighbours) {
      EXPECT_GT(k.rank, previous);
      EXPECT_NE(k.rank, plan.rank);
      previous = k.rank;
      EXPECT_EQ(k.receive_offset, offset);
      EXPECT_TRUE(std::is_sorted(k.send_slots.begin(), k.send_slots.end()));
      const RankNeighbour* back =
          find_neighbour(plans[static_cast<std::size_t>(k.rank)], plan.rank);
      ASSERT_NE(back, nullptr) << "rank " << k.rank << " does not know rank " << plan.rank;
      EXPECT_EQ(static_cast<std::size_t>(k.receive_count), back->send_slots.size());
      offset += k.receive_count;
    }
    EXPECT_EQ(plan.receive_size, offset);
  }
}

void expect_serial_order(const BlankTopology& t, const std::vector<RankPlan>& plans) {
  const auto serial = serial_lists(t);
  for (const RankPlan& plan : plans) {
    ASSERT_EQ(plan.gather_offsets.size(), plan.nodes.size() + 1);
    for (std::size_t i = 0; i < plan.nodes.size(); ++i) {
      std::vector<int> slots;
      for (int k = plan.gather_offsets[i]; k < plan.gather_offsets[i + 1]; ++k) {
        const int entry = plan.gather_entries[static_cast<std::size_t>(k)];
        if (entry >= 0) {  // a local entry is one of this rank's own slots
          EXPECT_TRUE(std::binary_search(plan.elements.begin(), plan.elements.end(),
                                         t.element_of_slot(entry)));
        }
        slots.push_back(global_slot(plans, plan, entry));
      }
      EXPECT_EQ(slots, serial[static_cast<std::size_t>(plan.nodes[i])])
          << "rank " << plan.rank << " node " << plan.nodes[i];
    }
  }
}

void expect_valid_plans(const BlankTopology& t, const std::vector<int>& part, int ranks) {
  SCOPED_TRACE(std::to_string(ranks) + " ranks");
  const std::vector<RankPlan> plans = all_plans(t, part, ranks);
  expect_elements_shared_out(t, part, plans);
  expect_nodes_owned_once(t, plans);
  expect_held_nodes(t, plans);
  expect_neighbours_consistent(plans);
  expect_serial_order(t, plans);
}

TEST(RankPlan, EveryPartitionReproducesTheSerialOrder) {
  const Mesh mesh = mixed_mesh();
  const BlankTopology t = mesh.topology();
  using Partitioner = std::function<std::vector<int>(const BlankTopology&, int)>;
  const std::vector<std::pair<std::string, Partitioner>> partitioners = {
      {"metis", metis}, {"stripes", stripes}, {"scattered", scattered}};
  for (const auto& [name, partition] : partitioners) {
    SCOPED_TRACE(name);
    for (int ranks = 1; ranks <= 4; ++ranks) {
      expect_valid_plans(t, partition(t, ranks), ranks);
    }
  }
}

TEST(RankPlan, NodeCornersAreTheSerialOrder) {
  const Mesh mesh = mixed_mesh();
  const NodeCorners nc = node_corner_lists(mesh.topology());
  const auto serial = serial_lists(mesh.topology());
  for (std::size_t n = 0; n < serial.size(); ++n) {
    const std::vector<int> slots(nc.slots.begin() + nc.offsets[n],
                                 nc.slots.begin() + nc.offsets[n + 1]);
    EXPECT_EQ(slots, serial[n]) << "node " << n;
  }
}

TEST(RankPlan, OneRankIsTheIdentity) {
  const Mesh mesh = mixed_mesh();
  const BlankTopology t = mesh.topology();
  const RankPlan plan = build_rank_plan(t, std::vector<int>(40, 0), 0, 1);
  std::vector<int> all_nodes(48);
  std::iota(all_nodes.begin(), all_nodes.end(), 0);
  std::vector<int> all_elements(40);
  std::iota(all_elements.begin(), all_elements.end(), 0);
  EXPECT_EQ(plan.elements, all_elements);
  EXPECT_EQ(plan.nodes, all_nodes);
  EXPECT_EQ(plan.owned_nodes, all_nodes);
  EXPECT_TRUE(plan.neighbours.empty());
  EXPECT_EQ(plan.receive_size, 0);
  const NodeCorners nc = node_corner_lists(t);
  EXPECT_EQ(plan.gather_offsets, nc.offsets);
  EXPECT_EQ(plan.gather_entries, nc.slots);
}

TEST(RankPlan, NodesOfNoElementBelongToRankZero) {
  Mesh mesh = mixed_mesh();
  mesh.n_nodes = 50;  // nodes 48 and 49 are in no element
  const BlankTopology t = mesh.topology();
  const std::vector<RankPlan> plans = all_plans(t, stripes(t, 3), 3);
  EXPECT_EQ(plans[0].nodes.back(), 49);
  EXPECT_EQ(plans[0].owned_nodes.back(), 49);
  EXPECT_EQ(plans[0].gather_offsets.back(), plans[0].gather_offsets[plans[0].nodes.size() - 2]);
  expect_nodes_owned_once(t, plans);
  expect_serial_order(t, plans);
}

TEST(RankPlan, ARankWithoutElementsHoldsNothing) {
  const Mesh mesh = mixed_mesh();
  const BlankTopology t = mesh.topology();
  std::vector<int> part = stripes(t, 2);  // parts 0 and 1 of 3: rank 2 gets nothing
  const std::vector<RankPlan> plans = all_plans(t, part, 3);
  EXPECT_TRUE(plans[2].elements.empty());
  EXPECT_TRUE(plans[2].nodes.empty());
  EXPECT_TRUE(plans[2].neighbours.empty());
  expect_nodes_owned_once(t, plans);
  expect_serial_order(t, plans);
}

TEST(MeshPartition, MetisIsDeterministicAndBalanced) {
  const Mesh mesh = mixed_mesh();
  const BlankTopology t = mesh.topology();
  std::vector<double> weights(40, 1.0);
  std::fill(weights.begin() + 30, weights.end(), 0.7);  // triangles cheaper than quads
  for (int parts = 2; parts <= 4; ++parts) {
    const std::vector<int> first = partition_elements(t, weights, parts, 5);
    EXPECT_EQ(first, partition_elements(t, weights, parts, 5));
    EXPECT_EQ(metis(t, parts), metis(t, parts));
    std::vector<int> sizes(static_cast<std::size_t>(parts), 0);
    for (const int p : metis(t, parts)) {
      ASSERT_GE(p, 0);
      ASSERT_LT(p, parts);
      ++sizes[static_cast<std::size_t>(p)];
    }
    for (const int size : sizes) {  // 40 elements: about 40 / parts each
      EXPECT_GE(size, 40 / parts - 3) << parts << " parts";
    }
  }
  EXPECT_EQ(partition_elements(t, {}, 1, 5), std::vector<int>(40, 0));
}

// METIS 5.1 fails (METIS_ERROR) when asked for contiguous parts of a disconnected mesh:
// partition_elements asks only when the mesh is edge-connected.
TEST(MeshPartition, DisconnectedBlankIsPartitioned) {
  const Mesh one = mixed_mesh();
  Mesh two;  // two copies, 30 quads then 30 more, 10 triangles then 10 more
  two.n_nodes = 2 * one.n_nodes;
  for (const int copy : {0, 1}) {
    for (const int n : one.quads) {
      two.quads.push_back(n + copy * one.n_nodes);
    }
    for (const int n : one.triangles) {
      two.triangles.push_back(n + copy * one.n_nodes);
    }
  }
  const BlankTopology t = two.topology();
  for (int parts = 2; parts <= 3; ++parts) {
    const std::vector<int> part = metis(t, parts);
    EXPECT_EQ(part, metis(t, parts));
    expect_valid_plans(t, part, parts);
  }
}

template <class F>
void expect_invalid(F f, const std::string& words) {
  try {
    f();
    ADD_FAILURE() << "no exception; expected one saying \"" << words << "\"";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(MeshPartition, BadInputIsNamed) {
  const Mesh mesh = mixed_mesh();
  const BlankTopology t = mesh.topology();
  expect_invalid([&] { partition_elements(t, {}, 41, 1); }, "41 parts requested for only 40");
  expect_invalid([&] { partition_elements(t, {}, 0, 1); }, "0 parts requested");
  const std::vector<double> few(39, 1.0);
  expect_invalid([&] { partition_elements(t, few, 2, 1); }, "39 element weights for 40");
  std::vector<double> negative(40, 1.0);
  negative[7] = -1.0;
  expect_invalid([&] { partition_elements(t, negative, 2, 1); }, "element 7 has weight");
  Mesh broken = mixed_mesh();
  broken.quads[9] = 48;  // quad 2, corner 1
  expect_invalid([&] { partition_elements(broken.topology(), {}, 2, 1); },
                 "element 2 has node id 48 outside [0, 48)");
}

TEST(RankPlan, BadInputIsNamed) {
  const Mesh mesh = mixed_mesh();
  const BlankTopology t = mesh.topology();
  std::vector<int> part = stripes(t, 3);
  expect_invalid([&] { build_rank_plan(t, part, 3, 3); }, "rank 3 of 3 ranks");
  expect_invalid([&] { build_rank_plan(t, part, 0, 0); }, "rank 0 of 0 ranks");
  expect_invalid([&] { build_rank_plan(t, std::span(part).first(39), 0, 3); },
                 "39 part ids for 40 elements");
  part[12] = 3;
  expect_invalid([&] { build_rank_plan(t, part, 0, 3); },
                 "element 12 has part id 3 outside [0, 3)");
  part[12] = -1;
  expect_invalid([&] { build_rank_plan(t, part, 0, 3); }, "element 12 has part id -1");
}

}  // namespace
}  // namespace sf
