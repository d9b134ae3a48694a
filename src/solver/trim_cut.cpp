#include "solver/trim_cut.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "element/element_block.hpp"
#include "solver/part_remap.hpp"

namespace sf {
namespace {

enum class Side : char { scrap, kept, on_line };

// Where the line crosses an edge: the point (1 - t) x_kept + t x_scrap.
struct Crossing {
  int kept = 0;
  int scrap = 0;
  double t = 0.0;
};

// A corner of a kept polygon: one of the part's nodes, or a crossing (its index).
struct Corner {
  int node = -1;
  int crossing = -1;
};

using Piece = std::vector<Corner>;  // 3 or 4 corners, counter-clockwise as the parent

class Cutter {
 public:
  Cutter(const FormedPart& part, const TrimOutline& outline, double fraction)
      : part_(part),
        region_(outline, part.file),
        x_(part.fields.at("x")),
        fraction_(fraction),
        elements_(static_cast<int>(part.quads.cols() + part.triangles.cols())) {
    classify();
    find_crossings();
    group_nodes();
  }

  FormedPart run(TrimSummary* summary) {
    move_nodes_near_crossings();
    remove_slivers();
    return build(summary);
  }

 private:
  Vec3 original(int node) const {
    const auto i = 3 * static_cast<std::size_t>(node);
    return {x_[i], x_[i + 1], x_[i + 2]};
  }
  Vec3 at(const Crossing& c) const {
    return (1.0 - c.t) * original(c.kept) + c.t * original(c.scrap);
  }
  Vec3 position(const Corner& c) const {
    if (c.crossing >= 0) {
      return at(crossings_[static_cast<std::size_t>(c.crossing)]);
    }
    const auto& moved = moved_[static_cast<std::size_t>(c.node)];
    return moved ? at(crossings_[static_cast<std::size_t>(*moved)]) : original(c.node);
  }
  Side side(int node) const { return side_[static_cast<std::size_t>(node)]; }
  bool active(const Crossing& c) const {
    return side(c.kept) == Side::kept && side(c.scrap) == Side::scrap;
  }

  void classify() {
    side_.assign(static_cast<std::size_t>(part_.reference_nodes.cols()), Side::scrap);
    moved_.assign(side_.size(), std::nullopt);
    for (std::size_t i = 0; i < side_.size(); ++i) {
      side_[i] = region_.keeps(original(static_cast<int>(i))) ? Side::kept : Side::scrap;
    }
  }

  // Every edge joining the sides, in the order of its ends' numbers, crossed where bisection on
  // the edge as it stands finds the line (to round-off: 60 halvings).
  void find_crossings() {
    std::map<std::pair<int, int>, Crossing> found;
    for (int e = 0; e < elements_; ++e) {
      const std::vector<int> nodes = part_element_nodes(part_, e);
      for (std::size_t k = 0; k < nodes.size(); ++k) {
        const int a = nodes[k], b = nodes[(k + 1) % nodes.size()];
        if (side(a) != side(b)) {
          const int kept = side(a) == Side::kept ? a : b;
          const int scrap = kept == a ? b : a;
          found.try_emplace({std::min(a, b), std::max(a, b)}, Crossing{kept, scrap, 0.0});
        }
      }
    }
    for (auto& [edge, c] : found) {
      double lo = 0.0, hi = 1.0;
      for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (region_.keeps((1.0 - mid) * original(c.kept) + mid * original(c.scrap)) ? lo : hi) = mid;
      }
      c.t = 0.5 * (lo + hi);
      crossing_of_[edge] = static_cast<int>(crossings_.size());
      crossings_.push_back(c);
    }
  }

  void group_nodes() {
    groups_of_.resize(side_.size());
    int id = 0;
    for (const auto& [name, members] : part_.groups) {
      for (int i : members) {
        groups_of_[static_cast<std::size_t>(i)].push_back(id);
      }
      ++id;
    }
  }

  // A node may move along its edge to `other` when `other` is in every group it is in.
  bool may_move(int node, int other) const {
    const auto& mine = groups_of_[static_cast<std::size_t>(node)];
    const auto& theirs = groups_of_[static_cast<std::size_t>(other)];
    return std::includes(theirs.begin(), theirs.end(), mine.begin(), mine.end());
  }

  // Moves the nearer end of an active crossing onto it; false if that end may not move (the far
  // end never does: it would cross half its elements).
  bool move_onto(int crossing) {
    const Crossing& c = crossings_[static_cast<std::size_t>(crossing)];
    const bool kept_end = c.t <= 0.5;
    const int node = kept_end ? c.kept : c.scrap;
    if (!may_move(node, kept_end ? c.scrap : c.kept)) {
      return false;
    }
    side_[static_cast<std::size_t>(node)] = Side::on_line;
    moved_[static_cast<std::size_t>(node)] = crossing;
    return true;
  }

  // A crossing within the sliver fraction of an edge's end moves that end onto the line: the
  // nearest first, each node once.
  void move_nodes_near_crossings() {
    std::vector<std::pair<double, int>> near;
    for (std::size_t k = 0; k < crossings_.size(); ++k) {
      const double t = crossings_[k].t;
      if (std::min(t, 1.0 - t) < fraction_) {
        near.emplace_back(std::min(t, 1.0 - t), static_cast<int>(k));
      }
    }
    std::sort(near.begin(), near.end());
    for (const auto& [distance, k] : near) {
      if (active(crossings_[static_cast<std::size_t>(k)])) {
        move_onto(k);
      }
    }
  }

  // The element's unit normal (mean of its corners' normals) and area as it stands.
  std::pair<Vec3, double> normal_and_area(int e) const {
    const std::vector<int> n = part_element_nodes(part_, e);
    const Vec3 twice_area =
        n.size() == 4
            ? Vec3((original(n[2]) - original(n[0])).cross(original(n[3]) - original(n[1])))
            : Vec3((original(n[1]) - original(n[0])).cross(original(n[2]) - original(n[0])));
    const double norm = twice_area.norm();
    return {norm > 0.0 ? Vec3(twice_area / norm) : Vec3::UnitZ(), 0.5 * norm};
  }

  // The area of a polygon projected on the normal, positive counter-clockwise.
  double area(const Piece& p, const Vec3& normal) const {
    double twice = 0.0;
    for (std::size_t k = 1; k + 1 < p.size(); ++k) {
      twice +=
          (position(p[k]) - position(p[0])).cross(position(p[k + 1]) - position(p[0])).dot(normal);
    }
    return 0.5 * twice;
  }

  bool convex(const Piece& p, const Vec3& normal) const {
    for (std::size_t k = 0; k < p.size(); ++k) {
      const Vec3 a = position(p[k]), b = position(p[(k + 1) % p.size()]),
                 c = position(p[(k + 2) % p.size()]);
      if (!((b - a).cross(c - b).dot(normal) > 0.0)) {
        return false;
      }
    }
    return true;
  }

  // The kept polygon of an element with nodes on both sides.
  Piece kept_polygon(const std::vector<int>& nodes) const {
    Piece polygon;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      const int a = nodes[k], b = nodes[(k + 1) % nodes.size()];
      if (side(a) != Side::scrap) {
        polygon.push_back({a, -1});
      }
      if ((side(a) == Side::kept && side(b) == Side::scrap) ||
          (side(a) == Side::scrap && side(b) == Side::kept)) {
        polygon.push_back({-1, crossing_of_.at({std::min(a, b), std::max(a, b)})});
      }
    }
    return polygon;
  }

  // The polygon split into convex quadrilaterals and triangles: of the splits into at most two
  // pieces, the one whose smallest piece is largest; else a fan of triangles.
  std::vector<Piece> split(const Piece& polygon, const Vec3& normal) const {
    const std::size_t n = polygon.size();
    if (n < 3) {
      return {};
    }
    if (n == 3 || (n == 4 && convex(polygon, normal))) {
      return {polygon};
    }
    auto corner = [&](std::size_t k) { return polygon[k % n]; };
    std::vector<Piece> best;
    double best_smallest = 0.0;
    // Cut along the diagonal from corner k to corner k + m: the pieces k..k+m and k+m..k+n.
    const std::size_t m = n == 4 ? 2 : 3;
    for (std::size_t k = 0; k < n; ++k) {
      Piece first, second;
      for (std::size_t j = 0; j <= m; ++j) {
        first.push_back(corner(k + j));
      }
      for (std::size_t j = m; j <= n; ++j) {
        second.push_back(corner(k + j));
      }
      const bool valid = [&] {
        for (const Piece* p : {&first, &second}) {
          if (p->size() == 4 ? !convex(*p, normal) : !(area(*p, normal) > 0.0)) {
            return false;
          }
        }
        return true;
      }();
      const double smallest = std::min(area(first, normal), area(second, normal));
      if (valid && smallest > best_smallest) {
        best = {first, second};
        best_smallest = smallest;
      }
    }
    if (best.empty()) {
      for (std::size_t k = 1; k + 1 < n; ++k) {
        best.push_back({polygon[0], polygon[k], polygon[k + 1]});
      }
    }
    return best;
  }

  // What stays of element e: nothing, itself (its nodes, some perhaps moved onto the line), or
  // the pieces of its kept polygon.
  std::vector<Piece> kept_pieces(int e) const {
    const std::vector<int> nodes = part_element_nodes(part_, e);
    const auto count = [&](Side s) {
      return std::count_if(nodes.begin(), nodes.end(), [&](int a) { return side(a) == s; });
    };
    Piece whole;
    for (int a : nodes) {
      whole.push_back({a, -1});
    }
    if (count(Side::scrap) == 0) {
      if (count(Side::kept) > 0) {
        return {whole};
      }
      Vec3 centre = Vec3::Zero();  // every node on the line: its centre decides
      for (const Corner& c : whole) {
        centre += position(c);
      }
      if (region_.keeps(centre / static_cast<double>(nodes.size()))) {
        return {whole};
      }
      return {};
    }
    if (count(Side::kept) == 0) {
      return {};
    }
    return split(kept_polygon(nodes), normal_and_area(e).first);
  }

  bool has_active_crossing(int e) const {
    const std::vector<int> nodes = part_element_nodes(part_, e);
    return std::any_of(nodes.begin(), nodes.end(), [&](int a) { return side(a) == Side::kept; }) &&
           std::any_of(nodes.begin(), nodes.end(), [&](int a) { return side(a) == Side::scrap; });
  }

  // The smallest of the pieces' areas over the parent's (1 with no piece).
  double smallest_fraction(int e, const std::vector<Piece>& pieces) const {
    const auto [normal, parent_area] = normal_and_area(e);
    double smallest = 1.0;
    for (const Piece& p : pieces) {
      smallest = std::min(smallest, area(p, normal) / parent_area);
    }
    return smallest;
  }

  // While a cut element has a piece below the fraction, one of its nodes moves onto the line:
  // the end nearest to one of its crossings that may move. Each move ends a crossing, so this
  // ends; a sliver no node may be moved away from stays (TrimSummary::smallest_fraction).
  void remove_slivers() {
    for (bool moved = true; moved;) {
      moved = false;
      for (int e = 0; e < elements_; ++e) {
        if (!has_active_crossing(e) || smallest_fraction(e, kept_pieces(e)) >= fraction_) {
          continue;
        }
        const std::vector<int> nodes = part_element_nodes(part_, e);
        std::vector<std::pair<double, int>> options;
        for (std::size_t k = 0; k < nodes.size(); ++k) {
          const int a = nodes[k], b = nodes[(k + 1) % nodes.size()];
          const auto found = crossing_of_.find({std::min(a, b), std::max(a, b)});
          if (found != crossing_of_.end() &&
              active(crossings_[static_cast<std::size_t>(found->second)])) {
            const double t = crossings_[static_cast<std::size_t>(found->second)].t;
            options.emplace_back(std::min(t, 1.0 - t), found->second);
          }
        }
        std::sort(options.begin(), options.end());
        for (const auto& [distance, k] : options) {
          if (move_onto(k)) {
            moved = true;
            break;
          }
        }
      }
    }
  }

  FormedPart build(TrimSummary* summary) const {
    PartRemap map;
    std::vector<int> new_node(side_.size(), -1), new_crossing(crossings_.size(), -1);
    TrimSummary s;
    s.elements_before = elements_;
    const ElementBlocks blocks = element_blocks(part_.quads, part_.triangles);
    std::vector<std::pair<int, Piece>> kept;  // (parent, piece) in the parent's order
    for (int e = 0; e < elements_; ++e) {
      const std::vector<Piece> pieces = kept_pieces(e);
      const bool cut = has_active_crossing(e);
      s.elements_removed += pieces.empty() ? 1 : 0;
      s.elements_cut += cut ? 1 : 0;
      s.pieces_made += cut ? static_cast<int>(pieces.size()) : 0;
      s.elements_reshaped += !cut && !pieces.empty() &&
                                     std::any_of(pieces[0].begin(), pieces[0].end(),
                                                 [&](const Corner& c) {
                                                   return moved_[static_cast<std::size_t>(c.node)];
                                                 })
                                 ? 1
                                 : 0;
      if (!pieces.empty()) {
        s.smallest_fraction = std::min(s.smallest_fraction, smallest_fraction(e, pieces));
      }
      for (const Piece& p : pieces) {
        kept.emplace_back(e, p);
        for (const Corner& c : p) {
          (c.node >= 0 ? new_node[static_cast<std::size_t>(c.node)]
                       : new_crossing[static_cast<std::size_t>(c.crossing)]) = 0;
        }
      }
    }
    if (kept.empty()) {
      throw InputError(part_.file +
                       ": the trim line leaves no part: every element is on the "
                       "scrap side");
    }
    if (s.elements_removed == 0 && s.elements_cut == 0) {
      throw InputError(part_.file +
                       ": the trim line misses the part: it crosses no element and "
                       "leaves every element whole");
    }
    for (std::size_t i = 0; i < new_node.size(); ++i) {
      if (new_node[i] == 0) {
        new_node[i] = static_cast<int>(map.nodes.size());
        const auto node = static_cast<int>(i);
        if (moved_[i]) {
          const Crossing& c = crossings_[static_cast<std::size_t>(*moved_[i])];
          map.nodes.push_back({c.kept, c.scrap, c.t, node});
          s.nodes_moved += 1;
          s.largest_move = std::max(s.largest_move, (at(c) - original(node)).norm());
        } else {
          map.nodes.push_back({node, node, 0.0, node});
        }
      }
    }
    for (std::size_t k = 0; k < crossings_.size(); ++k) {
      if (new_crossing[k] == 0) {
        new_crossing[k] = static_cast<int>(map.nodes.size());
        map.nodes.push_back({crossings_[k].kept, crossings_[k].scrap, crossings_[k].t, -1});
        s.nodes_made += 1;
      }
    }
    s.nodes_removed =
        static_cast<int>(side_.size()) - (static_cast<int>(map.nodes.size()) - s.nodes_made);
    for (const auto& [parent, piece] : kept) {
      ElementSource element{.nodes = {}, .parent = parent, .whole = true};
      for (std::size_t k = 0; k < piece.size(); ++k) {
        const Corner& c = piece[k];
        element.nodes[k] = c.node >= 0 ? new_node[static_cast<std::size_t>(c.node)]
                                       : new_crossing[static_cast<std::size_t>(c.crossing)];
        element.whole = element.whole && c.node >= 0 && !moved_[static_cast<std::size_t>(c.node)];
      }
      const auto parent_corners = static_cast<std::size_t>(blocks.of(parent).nodes_per_element());
      element.whole = element.whole && piece.size() == parent_corners;
      (piece.size() == 4 ? map.quads : map.triangles).push_back(element);
    }
    FormedPart out = remap_part(part_, map);
    s.piece_elements = part_piece_sizes(out);
    if (summary) {
      *summary = s;
    }
    return out;
  }

  const FormedPart& part_;
  const TrimRegion region_;
  const std::vector<double>& x_;
  const double fraction_;
  const int elements_;
  std::vector<Side> side_;
  std::vector<std::optional<int>> moved_;  ///< per node: the crossing it was moved onto
  std::vector<Crossing> crossings_;
  std::map<std::pair<int, int>, int> crossing_of_;  ///< by the edge's ends, lower first
  std::vector<std::vector<int>> groups_of_;         ///< per node: its groups' numbers, ascending
};

}  // namespace

FormedPart trim_by_cutting(const FormedPart& part, const TrimOutline& outline,
                           double sliver_fraction, TrimSummary* summary) {
  if (!(sliver_fraction >= 0.0 && sliver_fraction < 0.5)) {
    throw InputError(
        fmt::format("{}: the sliver fraction {} is outside [0, 0.5)", part.file, sliver_fraction));
  }
  if (!part.fields.contains("x")) {
    throw InputError(part.file + ": no entry /state/x (a damaged formed part)");
  }
  return Cutter(part, outline, sliver_fraction).run(summary);
}

}  // namespace sf
