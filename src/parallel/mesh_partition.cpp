#include "parallel/mesh_partition.hpp"

#include <metis.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

namespace sf {

namespace {

const char* metis_status_name(int status) {
  switch (status) {
    case METIS_OK:
      return "METIS_OK";
    case METIS_ERROR_INPUT:
      return "METIS_ERROR_INPUT";
    case METIS_ERROR_MEMORY:
      return "METIS_ERROR_MEMORY";
    case METIS_ERROR:
      return "METIS_ERROR";
    default:
      return "an unknown METIS status";
  }
}

// Union-find root with path halving.
int find_root(std::vector<int>& parent, int i) {
  while (parent[static_cast<std::size_t>(i)] != i) {
    auto& p = parent[static_cast<std::size_t>(i)];
    p = parent[static_cast<std::size_t>(p)];
    i = p;
  }
  return i;
}

// Whether every element reaches every other through shared edges. METIS 5.1 stops with an error
// (and prints) when contiguous parts are asked of a disconnected graph, so contiguity is asked
// only when this holds; its ncommon = 2 graph has at least these edges.
bool edge_connected(const BlankTopology& t) {
  const int ne = t.n_elements();
  std::vector<std::pair<std::int64_t, int>> edges;  // (edge key, element)
  edges.reserve(static_cast<std::size_t>(t.n_corners()));
  for (int e = 0; e < ne; ++e) {
    const int first = t.first_slot(e);
    const int n = t.corner_count(e);
    for (int a = 0; a < n; ++a) {
      const std::int64_t i = t.node_of_slot(first + a);
      const std::int64_t j = t.node_of_slot(first + (a + 1) % n);
      edges.emplace_back(std::min(i, j) * t.n_nodes + std::max(i, j), e);
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<int> parent(static_cast<std::size_t>(ne));
  std::iota(parent.begin(), parent.end(), 0);
  int components = ne;
  for (std::size_t k = 1; k < edges.size(); ++k) {
    if (edges[k].first != edges[k - 1].first) {
      continue;
    }
    const int a = find_root(parent, edges[k].second);
    const int b = find_root(parent, edges[k - 1].second);
    if (a != b) {
      parent[static_cast<std::size_t>(a)] = b;
      --components;
    }
  }
  return components <= 1;
}

// Integer METIS vertex weights: round(100 w / min w), at least 1, scaled down further if the
// total would come near METIS's integer range. Empty weights give an empty vector (all equal).
std::vector<idx_t> vertex_weights(std::span<const double> w, int n_elements) {
  if (w.empty()) {
    return {};
  }
  if (w.size() != static_cast<std::size_t>(n_elements)) {
    throw std::invalid_argument("partition_elements: " + std::to_string(w.size()) +
                                " element weights for " + std::to_string(n_elements) +
                                " elements (give one per element, or none)");
  }
  double total = 0.0;
  for (std::size_t e = 0; e < w.size(); ++e) {
    if (!std::isfinite(w[e]) || w[e] <= 0.0) {
      throw std::invalid_argument("partition_elements: element " + std::to_string(e) +
                                  " has weight " + std::to_string(w[e]) +
                                  " (weights must be finite and positive)");
    }
    total += w[e];
  }
  const double min_w = *std::min_element(w.begin(), w.end());
  constexpr double kMaxTotal = 1e9;  // below 2^31 for a 32-bit idx_t
  const double scale = std::min(100.0 / min_w, kMaxTotal / total);
  std::vector<idx_t> result(w.size());
  for (std::size_t e = 0; e < w.size(); ++e) {
    result[e] = std::max<idx_t>(1, static_cast<idx_t>(std::llround(w[e] * scale)));
  }
  return result;
}

// METIS's mesh arrays: element e's nodes at eind[eptr[e], eptr[e+1]) (quads then triangles).
void mesh_arrays(const BlankTopology& t, std::vector<idx_t>& eptr, std::vector<idx_t>& eind) {
  const int ne = t.n_elements();
  eptr.resize(static_cast<std::size_t>(ne) + 1);
  eind.resize(static_cast<std::size_t>(t.n_corners()));
  for (int e = 0; e <= ne; ++e) {
    eptr[static_cast<std::size_t>(e)] = e < ne ? t.first_slot(e) : t.n_corners();
  }
  for (int s = 0; s < t.n_corners(); ++s) {
    eind[static_cast<std::size_t>(s)] = t.node_of_slot(s);
  }
}

// k-way (METIS's default for meshes too), 0-based, the caller's seed: METIS draws its random
// numbers from this seed only, so the same inputs give the same parts.
std::array<idx_t, METIS_NOPTIONS> metis_options(int seed, bool contiguous) {
  std::array<idx_t, METIS_NOPTIONS> options{};
  METIS_SetDefaultOptions(options.data());
  options[METIS_OPTION_PTYPE] = METIS_PTYPE_KWAY;
  options[METIS_OPTION_SEED] = seed;
  options[METIS_OPTION_NUMBERING] = 0;
  options[METIS_OPTION_CONTIG] = contiguous ? 1 : 0;
  return options;
}

void check_parts(const BlankTopology& t, int parts) {
  if (parts < 1) {
    throw std::invalid_argument("partition_elements: " + std::to_string(parts) +
                                " parts requested (at least 1)");
  }
  if (parts > t.n_elements()) {
    throw std::invalid_argument("partition_elements: " + std::to_string(parts) +
                                " parts requested for only " + std::to_string(t.n_elements()) +
                                " elements (parts must not exceed the elements)");
  }
}

}  // namespace

BlankTopology blank_topology(const QuadConn& quads, const TriConn& triangles, int n_nodes) {
  return BlankTopology{
      std::span<const int>(quads.data(), static_cast<std::size_t>(quads.size())),
      std::span<const int>(triangles.data(), static_cast<std::size_t>(triangles.size())), n_nodes};
}

void check_topology(const BlankTopology& t) {
  if (t.quads.size() % 4 != 0 || t.triangles.size() % 3 != 0) {
    throw std::invalid_argument("blank topology: " + std::to_string(t.quads.size()) + " quad and " +
                                std::to_string(t.triangles.size()) +
                                " triangle node ids are not multiples of 4 and 3");
  }
  if (t.quads.size() + t.triangles.size() > static_cast<std::size_t>(INT_MAX)) {
    throw std::invalid_argument("blank topology: more corners than an int can count");
  }
  if (t.n_nodes < 0) {
    throw std::invalid_argument("blank topology: negative node count");
  }
  for (int s = 0; s < t.n_corners(); ++s) {
    const int node = t.node_of_slot(s);
    if (node < 0 || node >= t.n_nodes) {
      throw std::invalid_argument(
          "blank topology: element " + std::to_string(t.element_of_slot(s)) + " has node id " +
          std::to_string(node) + " outside [0, " + std::to_string(t.n_nodes) + ")");
    }
  }
}

std::vector<int> partition_elements(const BlankTopology& t, std::span<const double> element_weights,
                                    int parts, int seed) {
  check_topology(t);
  check_parts(t, parts);
  std::vector<idx_t> vwgt = vertex_weights(element_weights, t.n_elements());
  if (parts == 1) {
    return std::vector<int>(static_cast<std::size_t>(t.n_elements()), 0);
  }
  std::vector<idx_t> eptr;
  std::vector<idx_t> eind;
  mesh_arrays(t, eptr, eind);
  std::array<idx_t, METIS_NOPTIONS> options = metis_options(seed, edge_connected(t));
  idx_t ne = t.n_elements();
  idx_t nn = t.n_nodes;
  idx_t ncommon = 2;  // two shared nodes: an edge, for quads and triangles alike
  idx_t nparts = parts;
  idx_t objval = 0;
  std::vector<idx_t> epart(static_cast<std::size_t>(ne));
  std::vector<idx_t> npart(static_cast<std::size_t>(nn));
  const int status = METIS_PartMeshDual(
      &ne, &nn, eptr.data(), eind.data(), vwgt.empty() ? nullptr : vwgt.data(), nullptr, &ncommon,
      &nparts, nullptr, options.data(), &objval, epart.data(), npart.data());
  if (status != METIS_OK) {
    throw std::runtime_error(std::string("partition_elements: METIS_PartMeshDual returned ") +
                             metis_status_name(status) + " for " + std::to_string(ne) +
                             " elements in " + std::to_string(parts) + " parts");
  }
  return std::vector<int>(epart.begin(), epart.end());
}

}  // namespace sf
