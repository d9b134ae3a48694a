#include "mesh/consistent_orientation.hpp"

#include <algorithm>
#include <array>

namespace sf {
namespace {

struct EdgeUse {
  int lo, hi, element, direction;  // direction +1: the element runs lo -> hi
};

std::vector<EdgeUse> edge_uses(std::span<const int> offsets, std::span<const int> nodes) {
  std::vector<EdgeUse> uses;
  uses.reserve(nodes.size());
  for (std::size_t e = 0; e + 1 < offsets.size(); ++e) {
    const int first = offsets[e], n = offsets[e + 1] - offsets[e];
    for (int k = 0; k < n; ++k) {
      const int a = nodes[first + k], b = nodes[first + (k + 1) % n];
      uses.push_back({std::min(a, b), std::max(a, b), static_cast<int>(e), a < b ? 1 : -1});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.lo != y.lo ? x.lo < y.lo : (x.hi != y.hi ? x.hi < y.hi : x.element < y.element);
  });
  return uses;
}

struct Link {
  int element, neighbour, same_direction, lo, hi;
  bool operator<(const Link& o) const {
    return element != o.element ? element < o.element : neighbour < o.neighbour;
  }
};

}  // namespace

ConsistentOrientation orient_consistently(std::span<const int> offsets,
                                          std::span<const int> nodes) {
  ConsistentOrientation result;
  const int ne = offsets.empty() ? 0 : static_cast<int>(offsets.size()) - 1;
  const std::vector<EdgeUse> uses = edge_uses(offsets, nodes);
  std::vector<Link> links;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) {
      ++j;
    }
    if (j - i > 2) {
      result.non_manifold.push_back({uses[i].lo, uses[i].hi, static_cast<int>(j - i)});
    } else if (j - i == 2) {
      const int same = uses[i].direction == uses[i + 1].direction ? 1 : 0;
      links.push_back({uses[i].element, uses[i + 1].element, same, uses[i].lo, uses[i].hi});
      links.push_back({uses[i + 1].element, uses[i].element, same, uses[i].lo, uses[i].hi});
    }
    i = j;
  }
  if (!result.non_manifold.empty()) {
    return result;
  }
  std::sort(links.begin(), links.end());
  std::vector<int> start(ne + 1, 0);  // CSR: the links of element e
  for (const Link& l : links) {
    ++start[l.element + 1];
  }
  for (int e = 0; e < ne; ++e) {
    start[e + 1] += start[e];
  }

  std::vector<int> piece(ne, -1);
  std::vector<char> flip(ne, 0);
  std::vector<int> queue;
  queue.reserve(ne);
  for (int seed = 0; seed < ne; ++seed) {
    if (piece[seed] >= 0) {
      continue;
    }
    const int p = result.num_pieces++;
    piece[seed] = p;
    queue.clear();
    queue.push_back(seed);
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int e = queue[head];
      for (int k = start[e]; k < start[e + 1]; ++k) {
        const Link& l = links[k];
        // Neighbours agree when they run the shared edge in opposite directions.
        const char want = static_cast<char>(flip[e] ^ l.same_direction);
        if (piece[l.neighbour] < 0) {
          piece[l.neighbour] = p;
          flip[l.neighbour] = want;
          queue.push_back(l.neighbour);
        } else if (flip[l.neighbour] != want) {
          result.conflict = OrientationConflict{e, l.neighbour, l.lo, l.hi};
          return result;
        }
      }
    }
    const auto turned = std::count_if(queue.begin(), queue.end(), [&](int e) { return flip[e]; });
    if (2 * static_cast<std::size_t>(turned) > queue.size()) {  // keep the majority's
      for (const int e : queue) {
        flip[e] = static_cast<char>(!flip[e]);
      }
    }
  }
  result.flip = std::move(flip);
  result.piece = std::move(piece);
  return result;
}

}  // namespace sf
