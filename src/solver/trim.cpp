#include "solver/trim.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <string>

#include "core/errors.hpp"
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

// The element's node indices (quads first, then triangles).
std::vector<int> element_nodes(const FormedPart& part, Eigen::Index e) {
  const Eigen::Index n_quads = part.quads.cols();
  if (e < n_quads) {
    return {part.quads(0, e), part.quads(1, e), part.quads(2, e), part.quads(3, e)};
  }
  const Eigen::Index t = e - n_quads;
  return {part.triangles(0, t), part.triangles(1, t), part.triangles(2, t)};
}

// Which elements are kept: those whose current centre projects on the kept side.
std::vector<char> kept_elements(const FormedPart& part, const TrimOutline& outline) {
  const TrimRegion region(outline, part.file);
  const std::vector<double>& x = part.fields.at("x");
  const Eigen::Index elements = part.quads.cols() + part.triangles.cols();
  std::vector<char> kept(static_cast<std::size_t>(elements), 0);
  for (Eigen::Index e = 0; e < elements; ++e) {
    Vec3 centre = Vec3::Zero();
    const std::vector<int> nodes = element_nodes(part, e);
    for (int a : nodes) {
      centre += Vec3(x[3 * a], x[3 * a + 1], x[3 * a + 2]);
    }
    centre /= static_cast<double>(nodes.size());
    kept[static_cast<std::size_t>(e)] = region.keeps(centre);
  }
  return kept;
}

// The kept elements' connected pieces through shared nodes, elements each, largest first.
std::vector<int> piece_sizes(const FormedPart& part, const std::vector<char>& kept) {
  std::vector<int> parent(static_cast<std::size_t>(part.reference_nodes.cols()));
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
      i = parent[static_cast<std::size_t>(i)] =
          parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
    }
    return i;
  };
  for (std::size_t e = 0; e < kept.size(); ++e) {
    if (kept[e]) {
      const std::vector<int> nodes = element_nodes(part, static_cast<Eigen::Index>(e));
      for (std::size_t a = 1; a < nodes.size(); ++a) {
        parent[static_cast<std::size_t>(root(nodes[a]))] = root(nodes[0]);
      }
    }
  }
  std::map<int, int> count;
  for (std::size_t e = 0; e < kept.size(); ++e) {
    if (kept[e]) {
      ++count[root(element_nodes(part, static_cast<Eigen::Index>(e))[0])];
    }
  }
  std::vector<int> sizes;
  for (const auto& [piece, elements] : count) {
    sizes.push_back(elements);
  }
  std::sort(sizes.rbegin(), sizes.rend());
  return sizes;
}

// The values of the kept entities, `width` each (entity i's at i * width).
std::vector<double> subset(const std::vector<double>& data, const std::vector<int>& kept_index,
                           std::size_t count) {
  if (count == 0 || data.size() % count != 0) {
    return data;
  }
  const std::size_t width = data.size() / count;
  std::vector<double> out;
  out.reserve(kept_index.size() * width);
  for (int i : kept_index) {
    const auto first =
        data.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(i) * width);
    out.insert(out.end(), first, first + static_cast<std::ptrdiff_t>(width));
  }
  return out;
}

}  // namespace

FormedPart trim_by_removal(const FormedPart& part, const TrimOutline& outline,
                           TrimSummary* summary) {
  const std::vector<char> kept = kept_elements(part, outline);
  const auto n_kept = std::count(kept.begin(), kept.end(), char{1});
  if (n_kept == static_cast<std::ptrdiff_t>(kept.size())) {
    throw InputError(part.file +
                     ": the trim line misses the part: no element's centre is on the "
                     "scrap side");
  }
  if (n_kept == 0) {
    throw InputError(part.file +
                     ": the trim line leaves no part: every element's centre is on "
                     "the scrap side");
  }
  const Eigen::Index n_nodes = part.reference_nodes.cols();
  const Eigen::Index n_quads = part.quads.cols();
  std::vector<int> new_node(static_cast<std::size_t>(n_nodes), -1);
  std::vector<int> kept_elements_list;
  for (std::size_t e = 0; e < kept.size(); ++e) {
    if (kept[e]) {
      kept_elements_list.push_back(static_cast<int>(e));
      for (int a : element_nodes(part, static_cast<Eigen::Index>(e))) {
        new_node[static_cast<std::size_t>(a)] = 0;
      }
    }
  }
  std::vector<int> kept_nodes;
  for (Eigen::Index i = 0; i < n_nodes; ++i) {
    if (new_node[static_cast<std::size_t>(i)] == 0) {
      new_node[static_cast<std::size_t>(i)] = static_cast<int>(kept_nodes.size());
      kept_nodes.push_back(static_cast<int>(i));
    }
  }

  FormedPart out;
  out.file = part.file;
  out.n_points = part.n_points;
  out.rule = part.rule;
  out.law = part.law;
  out.tools = part.tools;
  out.contact_tools = part.contact_tools;
  out.reference_nodes.resize(3, static_cast<Eigen::Index>(kept_nodes.size()));
  for (std::size_t k = 0; k < kept_nodes.size(); ++k) {
    out.reference_nodes.col(static_cast<Eigen::Index>(k)) = part.reference_nodes.col(kept_nodes[k]);
    if (static_cast<std::size_t>(kept_nodes[k]) < part.node_tags.size()) {
      out.node_tags.push_back(part.node_tags[static_cast<std::size_t>(kept_nodes[k])]);
    }
  }
  std::vector<int> quads, triangles;
  for (int e : kept_elements_list) {
    (e < n_quads ? quads : triangles).push_back(e);
  }
  out.quads.resize(4, static_cast<Eigen::Index>(quads.size()));
  for (std::size_t k = 0; k < quads.size(); ++k) {
    for (int a = 0; a < 4; ++a) {
      out.quads(a, static_cast<Eigen::Index>(k)) =
          new_node[static_cast<std::size_t>(part.quads(a, quads[k]))];
    }
  }
  out.triangles.resize(3, static_cast<Eigen::Index>(triangles.size()));
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    for (int a = 0; a < 3; ++a) {
      out.triangles(a, static_cast<Eigen::Index>(k)) =
          new_node[static_cast<std::size_t>(part.triangles(a, triangles[k] - n_quads))];
    }
  }
  const std::size_t n_elements = kept.size();
  out.initial_thickness = subset(part.initial_thickness, kept_elements_list, n_elements);
  for (const auto& [name, nodes] : part.groups) {
    std::vector<int>& group = out.groups[name];
    for (int i : nodes) {
      if (new_node[static_cast<std::size_t>(i)] >= 0) {
        group.push_back(new_node[static_cast<std::size_t>(i)]);
      }
    }
  }

  static const auto by_name = fields_by_name();
  for (const auto& [key, data] : part.fields) {
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
        if (field.mapping == FieldMapping::interpolate) {
          out.fields[key] = subset(data, kept_nodes, static_cast<std::size_t>(n_nodes));
        }
        break;  // forces, masses, offsets: the next model's
      case FieldPlace::element:
      case FieldPlace::point:
        out.fields[key] = subset(data, kept_elements_list, n_elements);
        break;
      default:
        out.fields[key] = data;
    }
  }
  if (summary) {
    summary->elements_before = static_cast<int>(n_elements);
    summary->elements_removed = static_cast<int>(n_elements) - static_cast<int>(n_kept);
    summary->nodes_removed = static_cast<int>(n_nodes) - static_cast<int>(kept_nodes.size());
    summary->piece_elements = piece_sizes(part, kept);
  }
  return out;
}

BlankMesh blank_mesh_of(const FormedPart& part) {
  BlankMesh b;
  b.mesh.name = "blank";
  b.mesh.nodes = part.reference_nodes;
  for (double tag : part.node_tags) {
    b.mesh.gmsh_node_tags.push_back(static_cast<std::size_t>(tag));
  }
  b.mesh.quads = part.quads;
  b.mesh.triangles = part.triangles;
  for (const auto& [name, nodes] : part.groups) {
    b.groups.push_back({name, nodes});
  }
  b.source = part.file;
  return b;
}

}  // namespace sf
