// Part meshes and node groups from a gmsh model: local numbering, element checks, one
// orientation per piece.
#include "meshing/part_extraction.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>
#include <vector>

#include "core/errors.hpp"
#include "core/quoted.hpp"
#include "mesh/consistent_orientation.hpp"

namespace sf {
namespace {

constexpr int gmsh_triangle3 = 2;  // gmsh element type numbers (gmsh reference manual, MSH format)
constexpr int gmsh_quad4 = 3;

// Whether an element (3 or 4 local node indices) has no area: below 1e-12 of its longest side
// squared (a quad's area from its diagonals' cross product). Lengths relative to the first node.
bool has_zero_area(const Matrix3X& x, const std::vector<int>& el) {
  auto p = [&](std::size_t k) -> Vec3 { return x.col(el[k]) - x.col(el[0]); };
  const std::size_t n = el.size();
  const Vec3 normal =
      n == 4 ? Vec3((p(2) - p(0)).cross(p(3) - p(1))) : Vec3((p(1) - p(0)).cross(p(2) - p(0)));
  double longest = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    longest = std::max(longest, (p((k + 1) % n) - p(k)).squaredNorm());
  }
  return !(0.5 * normal.norm() > 1e-12 * longest);
}

std::string node_tag_list(const std::vector<std::size_t>& tags, const std::vector<int>& el) {
  std::string text;
  for (const int i : el) {
    text += (text.empty() ? "" : " ") + std::to_string(tags[static_cast<std::size_t>(i)]);
  }
  return text;
}

// The elements to reverse so that each piece has one orientation; InputError naming the edge
// (gmsh tags, mid-point) of a non-manifold or non-orientable surface.
std::vector<char> orientation_flips(const std::vector<std::vector<int>>& elements,
                                    const std::vector<std::size_t>& gmsh_tags, const Matrix3X& x,
                                    const std::string& where) {
  std::vector<int> offsets{0}, nodes;
  for (const auto& el : elements) {
    nodes.insert(nodes.end(), el.begin(), el.end());
    offsets.push_back(static_cast<int>(nodes.size()));
  }
  const auto edge_text = [&](int lo, int hi) {
    const Vec3 mid = 0.5 * (x.col(lo) + x.col(hi));
    return fmt::format("edge between gmsh nodes {} and {} (mid-point at ({:.6g}, {:.6g}, {:.6g}))",
                       gmsh_tags[lo], gmsh_tags[hi], mid(0), mid(1), mid(2));
  };
  ConsistentOrientation o = orient_consistently(offsets, nodes);
  if (!o.non_manifold.empty()) {
    const NonManifoldEdge& e = o.non_manifold.front();
    throw InputError(fmt::format("{}: the {} is shared by {} elements (a non-manifold surface)",
                                 where, edge_text(e.lo, e.hi), e.elements));
  }
  if (o.conflict) {
    throw InputError(
        fmt::format("{}: the surface is not orientable (orientation conflict at the {})", where,
                    edge_text(o.conflict->lo, o.conflict->hi)));
  }
  return std::move(o.flip);
}

// A node far beyond any sheet or tool (kMaxCoordinate), or not finite.
void check_node_position(const Vec3& x, std::size_t gmsh_tag, const std::string& where) {
  if (!x.allFinite()) {
    throw InputError(fmt::format("{}: node {} has a non-finite coordinate ({}, {}, {})", where,
                                 gmsh_tag, x(0), x(1), x(2)));
  }
  if (x.cwiseAbs().maxCoeff() > kMaxCoordinate) {
    throw InputError(fmt::format(
        "{}: node {} lies at ({:g}, {:g}, {:g}), beyond {:g} in the file's length unit: no sheet "
        "or tool is that large (a coordinate in the wrong unit, or a damaged file?)",
        where, gmsh_tag, x(0), x(1), x(2), kMaxCoordinate));
  }
}

}  // namespace

PartMesh extract_part_mesh(const GmshModel& model, const std::string& group,
                           const std::string& part_name) {
  const std::string where = quoted(model.file) + ", physical group '" + group + "'";
  const GmshPhysicalGroup* g = model.find_group(group, 2);
  if (g == nullptr) {
    const GmshPhysicalGroup* other = model.find_group(group);
    throw InputError(quoted(model.file) + ": no 2-D physical group '" + group + "'" +
                     (other ? " (there is one of dimension " + std::to_string(other->dim) + ")"
                            : std::string()) +
                     "; groups in the file: " + model.list_groups());
  }

  // Local numbering: the group's nodes in ascending gmsh tag order.
  PartMesh part;
  part.name = part_name;
  std::set<std::size_t> tags;
  for (const auto& block : g->elements) {
    if (block.type != gmsh_triangle3 && block.type != gmsh_quad4) {
      throw InputError(where + ": element type '" + block.type_name + "' (gmsh type " +
                       std::to_string(block.type) +
                       ") is not supported; use 4-node quadrangles or 3-node triangles "
                       "(first order, Mesh.ElementOrder = 1)");
    }
    tags.insert(block.node_tags.begin(), block.node_tags.end());
  }
  if (tags.empty()) {
    throw InputError(where + ": the group has no elements");
  }
  part.gmsh_node_tags.assign(tags.begin(), tags.end());
  std::unordered_map<std::size_t, int> local;
  part.nodes.resize(3, static_cast<Eigen::Index>(part.gmsh_node_tags.size()));
  for (std::size_t i = 0; i < part.gmsh_node_tags.size(); ++i) {
    const auto it = model.node_index.find(part.gmsh_node_tags[i]);
    if (it == model.node_index.end()) {
      throw InputError(where + ": element node " + std::to_string(part.gmsh_node_tags[i]) +
                       " has no coordinates");
    }
    part.nodes.col(static_cast<Eigen::Index>(i)) = model.node_coords.col(it->second);
    check_node_position(part.nodes.col(static_cast<Eigen::Index>(i)), part.gmsh_node_tags[i],
                        where);
    local.emplace(part.gmsh_node_tags[i], static_cast<int>(i));
  }

  // All elements, quads first, as local node lists.
  std::vector<std::vector<int>> elements;
  std::vector<std::size_t> element_tags;
  for (const int type : {gmsh_quad4, gmsh_triangle3}) {
    for (const auto& block : g->elements) {
      if (block.type != type) {
        continue;
      }
      const std::size_t n = static_cast<std::size_t>(block.nodes_per_element);
      for (std::size_t e = 0; e < block.element_tags.size(); ++e) {
        std::vector<int> el(n);
        for (std::size_t k = 0; k < n; ++k) {
          el[k] = local.at(block.node_tags[e * n + k]);
        }
        std::vector<int> sorted = el;
        std::sort(sorted.begin(), sorted.end());
        if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
          throw InputError(where + ": element " + std::to_string(block.element_tags[e]) +
                           " is degenerate (a node repeats)");
        }
        elements.push_back(std::move(el));
        element_tags.push_back(block.element_tags[e]);
      }
    }
  }

  const std::vector<char> reverse =
      orientation_flips(elements, part.gmsh_node_tags, part.nodes, where);
  // After the topology's checks (a Moebius band's closing element can be flat as well).
  for (std::size_t e = 0; e < elements.size(); ++e) {
    if (has_zero_area(part.nodes, elements[e])) {
      throw InputError(fmt::format(
          "{}: element {} has zero area (its nodes, gmsh tags {}, are collinear or coincide)",
          where, element_tags[e], node_tag_list(part.gmsh_node_tags, elements[e])));
    }
  }
  int quad_count = 0, triangle_count = 0;
  for (const auto& el : elements) {
    (el.size() == 4 ? quad_count : triangle_count)++;
  }
  part.quads.resize(4, quad_count);
  part.triangles.resize(3, triangle_count);
  part.reoriented = static_cast<int>(std::count(reverse.begin(), reverse.end(), 1));
  part.gmsh_element_tags = element_tags;  // quads first, as `elements`
  int q = 0, t = 0;
  for (std::size_t e = 0; e < elements.size(); ++e) {
    std::vector<int> el = elements[e];
    if (reverse[e]) {
      std::reverse(el.begin() + 1, el.end());  // keeps the first node: (a b c d) -> (a d c b)
    }
    if (el.size() == 4) {
      part.quads.col(q++) << el[0], el[1], el[2], el[3];
    } else {
      part.triangles.col(t++) << el[0], el[1], el[2];
    }
  }
  return part;
}

NodeGroup extract_node_group(const GmshModel& model, const PartMesh& part,
                             const std::string& group) {
  std::vector<std::size_t> tags;
  bool found = false;
  for (const auto& g : model.groups) {
    if (g.name == group) {
      found = true;
      tags.insert(tags.end(), g.node_tags.begin(), g.node_tags.end());
    }
  }
  if (!found) {
    throw InputError(quoted(model.file) + ": no physical group '" + group +
                     "'; groups in the file: " + model.list_groups());
  }
  std::unordered_map<std::size_t, int> local;
  for (std::size_t i = 0; i < part.gmsh_node_tags.size(); ++i) {
    local.emplace(part.gmsh_node_tags[i], static_cast<int>(i));
  }
  NodeGroup result;
  result.name = group;
  for (const std::size_t tag : tags) {
    const auto it = local.find(tag);
    if (it == local.end()) {
      throw InputError(quoted(model.file) + ", physical group '" + group + "': gmsh node " +
                       std::to_string(tag) + " is not a node of part '" + part.name + "'");
    }
    result.nodes.push_back(it->second);
  }
  std::sort(result.nodes.begin(), result.nodes.end());
  result.nodes.erase(std::unique(result.nodes.begin(), result.nodes.end()), result.nodes.end());
  return result;
}

}  // namespace sf
