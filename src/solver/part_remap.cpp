#include "solver/part_remap.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

#include "core/errors.hpp"
#include "element/element_block.hpp"
#include "element/shell_geometry.hpp"
#include "element/shell_part.hpp"
#include "element/shell_triangle_geometry.hpp"
#include "solver/state_fields.hpp"

namespace sf {
namespace {

// Each field's place and mapping by its name (the tools' and contact pairs' keys aside).
std::map<std::string, StateField, std::less<>> fields_by_name() {
  std::map<std::string, StateField, std::less<>> out;
  SolutionState empty;  // no tools, no contact pairs: every key is a field's name
  auto record = [&](const StateField& field, const std::string& key, const auto&) {
    out.emplace(key, field);
  };
  visit_state_fields(record, empty);
  return out;
}

// The fields whose components are in the element frame, as remap_part turns them: the stress's
// three, the back stresses (three per back stress), the transverse shear's two.
constexpr std::string_view kStress[3] = {"shell/sxx", "shell/syy", "shell/sxy"};
constexpr std::string_view kBackStress = "shell/back_stress";
constexpr std::string_view kShear[2] = {"shell/sxz", "shell/syz"};
constexpr std::string_view kDirector = "shell/director";

// A field in the element frame that remap_part does not know how to turn is a programming error:
// it would be inherited in the parent's frame, silently wrong in every piece.
void check_frame_fields_known() {
  static const bool checked = [] {
    std::set<std::string_view> known{kBackStress, kStress[0], kStress[1],
                                     kStress[2],  kShear[0],  kShear[1]};
    for (const auto& [name, field] : fields_by_name()) {
      if (field.mapping == FieldMapping::inherit_in_frame && !known.contains(name)) {
        throw std::logic_error("remap_part cannot turn the frame field " + name);
      }
    }
    return true;
  }();
  (void)checked;
}

Vec3 column(const std::vector<double>& data, int node) {
  const auto i = static_cast<std::size_t>(node);
  return {data[3 * i], data[3 * i + 1], data[3 * i + 2]};
}

// The values of a node field (`width` per node) at the new nodes.
std::vector<double> interpolate_nodes(const std::vector<double>& data, std::size_t width,
                                      const std::vector<NodeSource>& nodes) {
  std::vector<double> out;
  out.reserve(nodes.size() * width);
  for (const NodeSource& n : nodes) {
    for (std::size_t c = 0; c < width; ++c) {
      const double va = data[static_cast<std::size_t>(n.a) * width + c];
      const double vb = data[static_cast<std::size_t>(n.b) * width + c];
      out.push_back(n.t == 0.0 ? va : (1.0 - n.t) * va + n.t * vb);
    }
  }
  return out;
}

// The new elements in state order: quads, then triangles.
std::vector<const ElementSource*> new_elements(const PartRemap& map) {
  std::vector<const ElementSource*> out;
  for (const ElementSource& e : map.quads) {
    out.push_back(&e);
  }
  for (const ElementSource& e : map.triangles) {
    out.push_back(&e);
  }
  return out;
}

// The corotational frame (columns e1, e2, e3) of an element at x (3 per node): the one its
// stresses are written in (shell_geometry.hpp, shell_triangle_geometry.hpp). Identity for a
// collapsed element (its state is then left as it is).
Mat3 element_frame(const std::vector<double>& x, const int* nodes, int count) {
  if (count == 4) {
    Quad3 q;
    for (int a = 0; a < 4; ++a) {
      q.col(a) = column(x, nodes[a]);
    }
    ShellGeometry g;
    return compute_shell_geometry(q, g) ? g.frame : Mat3::Identity();
  }
  Tri3 t;
  for (int a = 0; a < 3; ++a) {
    t.col(a) = column(x, nodes[a]);
  }
  TriangleGeometry g;
  return compute_triangle_geometry(t, g) ? g.frame : Mat3::Identity();
}

// (cos, sin) of the angle from the parent's e1 to the piece's e1, about the parent's e3.
Vec2 frame_turn(const Mat3& parent, const Mat3& piece) {
  const Vec2 c(parent.col(0).dot(piece.col(0)), parent.col(1).dot(piece.col(0)));
  const double length = c.norm();
  return length > 0.0 ? Vec2(c / length) : Vec2(1.0, 0.0);
}

// An in-plane symmetric tensor (xx, yy, xy) in the piece's frame, turned by (c, s).
void turn_tensor(double& xx, double& yy, double& xy, const Vec2& turn) {
  const double c = turn(0), s = turn(1);
  const double a = xx, b = yy, d = xy;
  xx = c * c * a + 2.0 * c * s * d + s * s * b;
  yy = s * s * a - 2.0 * c * s * d + c * c * b;
  xy = -c * s * a + (c * c - s * s) * d + c * s * b;
}

class Remapper {
 public:
  Remapper(const FormedPart& part, const PartRemap& map)
      : part_(part), map_(map), elements_(new_elements(map)) {
    check_frame_fields_known();
    check_map();
  }

  FormedPart run() {
    FormedPart out;
    out.file = part_.file;
    out.n_points = part_.n_points;
    out.rule = part_.rule;
    out.law = part_.law;
    out.part_names = part_.part_names;
    out.tools = part_.tools;
    out.contact_tools = part_.contact_tools;
    map_mesh(out);
    map_fields(out);
    if (out.fields.contains("x")) {
      turn_pieces(out);
    }
    return out;
  }

 private:
  std::size_t old_elements() const {
    return static_cast<std::size_t>(part_.quads.cols() + part_.triangles.cols());
  }

  void check_map() const {
    const auto n_nodes = static_cast<int>(part_.reference_nodes.cols());
    for (const NodeSource& n : map_.nodes) {
      if (n.a < 0 || n.a >= n_nodes || n.b < 0 || n.b >= n_nodes || n.origin >= n_nodes) {
        throw std::logic_error("remap_part: a node source outside the part");
      }
    }
    const auto new_nodes = static_cast<int>(map_.nodes.size());
    auto check = [&](const std::vector<ElementSource>& list, int count) {
      for (const ElementSource& e : list) {
        if (e.parent < 0 || static_cast<std::size_t>(e.parent) >= old_elements() ||
            std::any_of(e.nodes.begin(), e.nodes.begin() + count,
                        [&](int n) { return n < 0 || n >= new_nodes; })) {
          throw std::logic_error("remap_part: an element outside the part or the new nodes");
        }
      }
    };
    check(map_.quads, 4);
    check(map_.triangles, 3);
  }

  void map_mesh(FormedPart& out) const {
    const std::size_t n = map_.nodes.size();
    out.reference_nodes.resize(3, static_cast<Eigen::Index>(n));
    double next_tag = part_.node_tags.empty()
                          ? 0.0
                          : *std::max_element(part_.node_tags.begin(), part_.node_tags.end()) + 1.0;
    for (std::size_t k = 0; k < n; ++k) {
      const NodeSource& s = map_.nodes[k];
      out.reference_nodes.col(static_cast<Eigen::Index>(k)) =
          (1.0 - s.t) * part_.reference_nodes.col(s.a) + s.t * part_.reference_nodes.col(s.b);
      if (!part_.node_tags.empty()) {
        out.node_tags.push_back(s.origin >= 0 ? part_.node_tags[static_cast<std::size_t>(s.origin)]
                                              : next_tag++);
      }
    }
    out.quads.resize(4, static_cast<Eigen::Index>(map_.quads.size()));
    for (std::size_t e = 0; e < map_.quads.size(); ++e) {
      for (int a = 0; a < 4; ++a) {
        out.quads(a, static_cast<Eigen::Index>(e)) =
            map_.quads[e].nodes[static_cast<std::size_t>(a)];
      }
    }
    out.triangles.resize(3, static_cast<Eigen::Index>(map_.triangles.size()));
    for (std::size_t e = 0; e < map_.triangles.size(); ++e) {
      for (int a = 0; a < 3; ++a) {
        out.triangles(a, static_cast<Eigen::Index>(e)) =
            map_.triangles[e].nodes[static_cast<std::size_t>(a)];
      }
    }
    out.initial_thickness = element_values("initial_thickness", part_.initial_thickness);
    for (const ElementSource* e : elements_) {  // each piece in its parent's part
      if (!part_.element_part.empty()) {
        out.element_part.push_back(part_.element_part[static_cast<std::size_t>(e->parent)]);
      }
    }
    map_groups(out);
  }

  void map_groups(FormedPart& out) const {
    for (const auto& [name, members] : part_.groups) {
      std::vector<char> in(static_cast<std::size_t>(part_.reference_nodes.cols()), 0);
      for (int i : members) {
        in[static_cast<std::size_t>(i)] = 1;
      }
      std::vector<int>& group = out.groups[name];
      for (std::size_t k = 0; k < map_.nodes.size(); ++k) {
        const NodeSource& s = map_.nodes[k];
        const bool member = s.origin >= 0 ? in[static_cast<std::size_t>(s.origin)] != 0
                                          : in[static_cast<std::size_t>(s.a)] != 0 &&
                                                in[static_cast<std::size_t>(s.b)] != 0;
        if (member) {
          group.push_back(static_cast<int>(k));
        }
      }
    }
  }

  // An element or point field: the parent's values for every new element.
  std::vector<double> element_values(const std::string& key, const std::vector<double>& data,
                                     bool reset_pieces = false) const {
    if (data.size() % old_elements() != 0) {
      throw InputError(
          fmt::format("{}: entry {} holds {} values, not a whole number per element "
                      "(a damaged formed part)",
                      part_.file, key, data.size()));
    }
    const std::size_t width = data.size() / old_elements();
    std::vector<double> out;
    out.reserve(elements_.size() * width);
    for (const ElementSource* e : elements_) {
      const auto first =
          data.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(e->parent) * width);
      if (reset_pieces && !e->whole) {
        out.insert(out.end(), width, 0.0);
      } else {
        out.insert(out.end(), first, first + static_cast<std::ptrdiff_t>(width));
      }
    }
    return out;
  }

  void map_fields(FormedPart& out) const {
    static const auto by_name = fields_by_name();
    const auto n_nodes = static_cast<std::size_t>(part_.reference_nodes.cols());
    for (const auto& [key, data] : part_.fields) {
      if (key.starts_with("tools/")) {
        out.fields[key] = data;  // where the tools stand
        continue;
      }
      const auto found = by_name.find(key);
      if (key.starts_with("contacts/") || found == by_name.end()) {
        continue;  // the contact pairs' history starts afresh on the new edge
      }
      const StateField& field = found->second;
      switch (field.place) {
        case FieldPlace::node:
          if (field.mapping == FieldMapping::interpolate && n_nodes > 0) {
            out.fields[key] = interpolate_nodes(data, data.size() / n_nodes, map_.nodes);
          }
          break;  // forces, masses, offsets: the next model's
        case FieldPlace::element:
        case FieldPlace::point:
          out.fields[key] =
              element_values("/state/" + key, data, field.mapping == FieldMapping::reset);
          break;
        default:
          out.fields[key] = data;
      }
    }
  }

  // Each piece's frame fields turned into its own frame, its directors interpolated.
  void turn_pieces(FormedPart& out) const {
    const std::vector<double>& x_old = part_.fields.at("x");
    const std::vector<double>& x_new = out.fields.at("x");
    const ElementBlocks old_blocks = element_blocks(part_.quads, part_.triangles);
    const ElementBlocks new_blocks = element_blocks(out.quads, out.triangles);
    const std::size_t n_new = elements_.size();
    for (std::size_t e = 0; e < n_new; ++e) {
      const ElementSource& piece = *elements_[e];
      if (piece.whole) {
        continue;
      }
      const std::vector<int> parent_nodes = part_element_nodes(part_, piece.parent);
      const int count = new_blocks.of(static_cast<int>(e)).nodes_per_element();
      const Vec2 turn = frame_turn(element_frame(x_old, parent_nodes.data(),
                                                 old_blocks.of(piece.parent).nodes_per_element()),
                                   element_frame(x_new, piece.nodes.data(), count));
      turn_point_fields(out, e, turn);
      turn_shear(out, e, turn);
      interpolate_directors(out, e, parent_nodes, count);
    }
  }

  void turn_point_fields(FormedPart& out, std::size_t e, const Vec2& turn) const {
    const auto points = static_cast<std::size_t>(out.n_points);
    if (out.fields.contains(std::string(kStress[0]))) {
      auto& xx = out.fields.at(std::string(kStress[0]));
      auto& yy = out.fields.at(std::string(kStress[1]));
      auto& xy = out.fields.at(std::string(kStress[2]));
      for (std::size_t k = e * points; k < (e + 1) * points; ++k) {
        turn_tensor(xx[k], yy[k], xy[k], turn);
      }
    }
    const auto back = out.fields.find(std::string(kBackStress));
    if (back != out.fields.end() && !back->second.empty()) {
      std::vector<double>& b = back->second;
      const std::size_t width = b.size() / elements_.size();  // 3 per back stress and point
      for (std::size_t i = e * width; i < (e + 1) * width; i += 3) {
        turn_tensor(b[i], b[i + 1], b[i + 2], turn);
      }
    }
  }

  void turn_shear(FormedPart& out, std::size_t e, const Vec2& turn) const {
    if (!out.fields.contains(std::string(kShear[0]))) {
      return;
    }
    double& qx = out.fields.at(std::string(kShear[0]))[e];
    double& qy = out.fields.at(std::string(kShear[1]))[e];
    const double a = qx, b = qy;
    qx = turn(0) * a + turn(1) * b;
    qy = -turn(1) * a + turn(0) * b;
  }

  // The piece's directors: the parent's at the corner it shares, interpolated (and made unit)
  // along the parent's edge where a corner lies on one.
  void interpolate_directors(FormedPart& out, std::size_t e, const std::vector<int>& parent_nodes,
                             int count) const {
    const auto found = out.fields.find(std::string(kDirector));
    if (found == out.fields.end()) {
      return;
    }
    const std::vector<double>& old = part_.fields.at(std::string(kDirector));
    std::vector<double>& d = found->second;
    const auto parent = static_cast<std::size_t>(elements_[e]->parent);
    auto director_of = [&](int node) -> std::optional<Vec3> {
      const auto at = std::find(parent_nodes.begin(), parent_nodes.end(), node);
      if (at == parent_nodes.end()) {
        return std::nullopt;
      }
      const auto slot =
          3 * (kDirectorNodes * parent + static_cast<std::size_t>(at - parent_nodes.begin()));
      return Vec3(old[slot], old[slot + 1], old[slot + 2]);
    };
    for (int corner = 0; corner < kDirectorNodes; ++corner) {
      const std::size_t slot = 3 * (kDirectorNodes * e + static_cast<std::size_t>(corner));
      Vec3 value = Vec3::Zero();
      if (corner < count) {
        const NodeSource& s = map_.nodes[static_cast<std::size_t>(elements_[e]->nodes[corner])];
        const auto da = director_of(s.a), db = director_of(s.b);
        const auto own = director_of(s.origin);
        if (da && db) {
          value = ((1.0 - s.t) * *da + s.t * *db).normalized();
        } else if (own) {
          value = *own;
        }
      }
      d[slot] = value(0);
      d[slot + 1] = value(1);
      d[slot + 2] = value(2);
    }
  }

  const FormedPart& part_;
  const PartRemap& map_;
  std::vector<const ElementSource*> elements_;
};

}  // namespace

std::vector<int> part_element_nodes(const FormedPart& part, int element) {
  const ElementBlock block = element_blocks(part.quads, part.triangles).of(element);
  const int* nodes = block.element_nodes(element);
  return {nodes, nodes + block.nodes_per_element()};
}

std::vector<int> part_piece_sizes(const FormedPart& part) {
  std::vector<int> parent(static_cast<std::size_t>(part.reference_nodes.cols()));
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
      i = parent[static_cast<std::size_t>(i)] =
          parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
    }
    return i;
  };
  const auto elements = static_cast<int>(part.quads.cols() + part.triangles.cols());
  for (int e = 0; e < elements; ++e) {
    const std::vector<int> nodes = part_element_nodes(part, e);
    for (std::size_t a = 1; a < nodes.size(); ++a) {
      parent[static_cast<std::size_t>(root(nodes[a]))] = root(nodes[0]);
    }
  }
  std::map<int, int> count;
  for (int e = 0; e < elements; ++e) {
    ++count[root(part_element_nodes(part, e)[0])];
  }
  std::vector<int> sizes;
  for (const auto& [piece, n] : count) {
    sizes.push_back(n);
  }
  std::sort(sizes.rbegin(), sizes.rend());
  return sizes;
}

FormedPart remap_part(const FormedPart& part, const PartRemap& map) {
  return Remapper(part, map).run();
}

}  // namespace sf
