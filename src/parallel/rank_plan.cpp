#include "parallel/rank_plan.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sf {

namespace {

// The distinct ranks holding each node (CSR, ascending; the first is the owner). A node that no
// element touches is given to rank 0.
struct NodeRanks {
  std::vector<int> offsets;
  std::vector<int> ranks;

  std::span<const int> of(int node) const {
    const auto n = static_cast<std::size_t>(node);
    return std::span<const int>(ranks).subspan(
        static_cast<std::size_t>(offsets[n]),
        static_cast<std::size_t>(offsets[n + 1] - offsets[n]));
  }
};

std::span<const int> corners_at(const NodeCorners& nc, int node) {
  const auto n = static_cast<std::size_t>(node);
  return std::span<const int>(nc.slots).subspan(
      static_cast<std::size_t>(nc.offsets[n]),
      static_cast<std::size_t>(nc.offsets[n + 1] - nc.offsets[n]));
}

void check_partition(const BlankTopology& t, std::span<const int> part, int rank, int ranks) {
  if (ranks < 1 || rank < 0 || rank >= ranks) {
    throw std::invalid_argument("build_rank_plan: rank " + std::to_string(rank) + " of " +
                                std::to_string(ranks) + " ranks (need 0 <= rank < ranks)");
  }
  if (part.size() != static_cast<std::size_t>(t.n_elements())) {
    throw std::invalid_argument("build_rank_plan: " + std::to_string(part.size()) +
                                " part ids for " + std::to_string(t.n_elements()) + " elements");
  }
  for (std::size_t e = 0; e < part.size(); ++e) {
    if (part[e] < 0 || part[e] >= ranks) {
      throw std::invalid_argument("build_rank_plan: element " + std::to_string(e) +
                                  " has part id " + std::to_string(part[e]) + " outside [0, " +
                                  std::to_string(ranks) + ")");
    }
  }
}

NodeRanks node_ranks(const BlankTopology& t, const NodeCorners& nc, std::span<const int> part) {
  NodeRanks nr;
  nr.offsets.reserve(static_cast<std::size_t>(t.n_nodes) + 1);
  nr.offsets.push_back(0);
  std::vector<int> here;
  for (int n = 0; n < t.n_nodes; ++n) {
    here.clear();
    for (const int s : corners_at(nc, n)) {
      here.push_back(part[static_cast<std::size_t>(t.element_of_slot(s))]);
    }
    if (here.empty()) {
      here.push_back(0);  // a node of no element: rank 0's, so that every node has an owner
    }
    std::sort(here.begin(), here.end());
    here.erase(std::unique(here.begin(), here.end()), here.end());
    nr.ranks.insert(nr.ranks.end(), here.begin(), here.end());
    nr.offsets.push_back(static_cast<int>(nr.ranks.size()));
  }
  return nr;
}

void collect_elements(RankPlan& plan, std::span<const int> part) {
  for (std::size_t e = 0; e < part.size(); ++e) {
    if (part[e] == plan.rank) {
      plan.elements.push_back(static_cast<int>(e));
    }
  }
}

void collect_nodes(RankPlan& plan, const NodeRanks& nr) {
  for (int n = 0; n < plan.n_nodes; ++n) {
    const std::span<const int> holders = nr.of(n);
    if (std::binary_search(holders.begin(), holders.end(), plan.rank)) {
      plan.nodes.push_back(n);
      if (holders.front() == plan.rank) {
        plan.owned_nodes.push_back(n);
      }
    }
  }
}

// Slots of this rank's elements at nodes each other rank also holds, ascending (own elements
// ascending give ascending slots).
std::vector<std::vector<int>> send_lists(const RankPlan& plan, const BlankTopology& t,
                                         const NodeRanks& nr) {
  std::vector<std::vector<int>> send(static_cast<std::size_t>(plan.ranks));
  for (const int e : plan.elements) {
    const int first = t.first_slot(e);
    for (int s = first; s < first + t.corner_count(e); ++s) {
      for (const int q : nr.of(t.node_of_slot(s))) {
        if (q != plan.rank) {
          send[static_cast<std::size_t>(q)].push_back(s);
        }
      }
    }
  }
  return send;
}

// Slots of other ranks' elements at nodes this rank holds, per rank, ascending: each is that
// rank's send list to this one, by the same rule seen from the other side.
std::vector<std::vector<int>> receive_lists(const RankPlan& plan, const BlankTopology& t,
                                            std::span<const int> part) {
  std::vector<char> held(static_cast<std::size_t>(plan.n_nodes), 0);
  for (const int n : plan.nodes) {
    held[static_cast<std::size_t>(n)] = 1;
  }
  std::vector<std::vector<int>> receive(static_cast<std::size_t>(plan.ranks));
  for (int s = 0; s < t.n_corners(); ++s) {
    const int p = part[static_cast<std::size_t>(t.element_of_slot(s))];
    if (p != plan.rank && held[static_cast<std::size_t>(t.node_of_slot(s))]) {
      receive[static_cast<std::size_t>(p)].push_back(s);
    }
  }
  return receive;
}

// Fills plan.neighbours and plan.receive_size; returns each received slot's index in the receive
// buffer (-1 for slots not received).
std::vector<int> collect_neighbours(RankPlan& plan, const BlankTopology& t, const NodeRanks& nr,
                                    std::span<const int> part) {
  std::vector<std::vector<int>> send = send_lists(plan, t, nr);
  const std::vector<std::vector<int>> receive = receive_lists(plan, t, part);
  std::vector<int> receive_index(static_cast<std::size_t>(t.n_corners()), -1);
  int offset = 0;
  for (int q = 0; q < plan.ranks; ++q) {
    const auto& in = receive[static_cast<std::size_t>(q)];
    auto& out = send[static_cast<std::size_t>(q)];
    if (in.empty() != out.empty()) {  // sharing a node means a corner there on either side
      throw std::logic_error("build_rank_plan: ranks " + std::to_string(plan.rank) + " and " +
                             std::to_string(q) + " disagree on sharing nodes");
    }
    if (out.empty()) {
      continue;
    }
    for (std::size_t i = 0; i < in.size(); ++i) {
      receive_index[static_cast<std::size_t>(in[i])] = offset + static_cast<int>(i);
    }
    plan.neighbours.push_back({q, std::move(out), offset, static_cast<int>(in.size())});
    offset += static_cast<int>(in.size());
  }
  plan.receive_size = offset;
  return receive_index;
}

void collect_gather_lists(RankPlan& plan, const BlankTopology& t, const NodeCorners& nc,
                          std::span<const int> part, const std::vector<int>& receive_index) {
  plan.gather_offsets.reserve(plan.nodes.size() + 1);
  plan.gather_offsets.push_back(0);
  for (const int n : plan.nodes) {
    for (const int s : corners_at(nc, n)) {
      const bool own = part[static_cast<std::size_t>(t.element_of_slot(s))] == plan.rank;
      plan.gather_entries.push_back(own ? s : -(1 + receive_index[static_cast<std::size_t>(s)]));
    }
    plan.gather_offsets.push_back(static_cast<int>(plan.gather_entries.size()));
  }
}

}  // namespace

NodeCorners node_corner_lists(const BlankTopology& t) {
  check_topology(t);
  return build_node_corners(t.blocks, t.n_nodes);
}

RankPlan build_rank_plan(const BlankTopology& t, std::span<const int> part_of_element, int rank,
                         int ranks) {
  check_topology(t);
  check_partition(t, part_of_element, rank, ranks);
  const NodeCorners nc = build_node_corners(t.blocks, t.n_nodes);
  const NodeRanks nr = node_ranks(t, nc, part_of_element);
  RankPlan plan;
  plan.rank = rank;
  plan.ranks = ranks;
  plan.n_nodes = t.n_nodes;
  plan.n_corners = t.n_corners();
  collect_elements(plan, part_of_element);
  collect_nodes(plan, nr);
  const std::vector<int> receive_index = collect_neighbours(plan, t, nr, part_of_element);
  collect_gather_lists(plan, t, nc, part_of_element, receive_index);
  return plan;
}

}  // namespace sf
