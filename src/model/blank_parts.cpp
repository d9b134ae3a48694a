#include "model/blank_parts.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <numeric>
#include <unordered_map>

#include "core/errors.hpp"
#include "element/corner_forces.hpp"
#include "element/element_block.hpp"

namespace sf {
namespace {

// Each element's part (-1: none yet), from the parts' groups' element tags.
std::vector<int> find_element_parts(const GmshModel& model,
                                    const std::vector<BlankPartConfig>& parts,
                                    const std::string& case_file, const PartMesh& mesh) {
  std::unordered_map<std::size_t, int> element_of;  // gmsh element tag -> blank element
  for (std::size_t e = 0; e < mesh.gmsh_element_tags.size(); ++e) {
    element_of.emplace(mesh.gmsh_element_tags[e], static_cast<int>(e));
  }
  std::vector<int> part_of(mesh.gmsh_element_tags.size(), -1);
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const BlankPartConfig& part = parts[p];
    const std::string where =
        fmt::format("{}:{}: blank.parts[{}] ('{}')", case_file, part.line, p, part.name);
    const GmshPhysicalGroup* group = model.find_group(part.group, 2);
    if (group == nullptr) {
      throw InputError(fmt::format("{}: group: no 2-D physical group '{}' in {}; groups there: {}",
                                   where, part.group, model.file.string(), model.list_groups()));
    }
    for (const GmshElementBlock& block : group->elements) {
      for (const std::size_t tag : block.element_tags) {
        const auto found = element_of.find(tag);
        if (found == element_of.end()) {
          throw InputError(
              fmt::format("{}: group '{}' holds element {}, which is not an element of the blank",
                          where, part.group, tag));
        }
        int& owner = part_of[static_cast<std::size_t>(found->second)];
        if (owner >= 0 && owner != static_cast<int>(p)) {
          throw InputError(
              fmt::format("{}: element {} is also in part '{}'; expected each "
                          "element of the blank in one part",
                          where, tag, parts[static_cast<std::size_t>(owner)].name));
        }
        owner = static_cast<int>(p);
      }
    }
  }
  for (std::size_t e = 0; e < part_of.size(); ++e) {
    if (part_of[e] < 0) {
      throw InputError(
          fmt::format("{}: blank.parts: element {} of the blank is in no part's "
                      "group; expected each element of the blank in one part",
                      case_file, mesh.gmsh_element_tags[e]));
    }
  }
  return part_of;
}

// The order of elements [first, last) sorted stably by part.
std::vector<int> sorted_by_part(const std::vector<int>& part_of, int first, int last) {
  std::vector<int> order(static_cast<std::size_t>(last - first));
  std::iota(order.begin(), order.end(), first);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return part_of[static_cast<std::size_t>(a)] < part_of[static_cast<std::size_t>(b)];
  });
  return order;
}

// Two distinct nodes at one place (within 1e-9 of the blank's size): a weld line meshed twice,
// so the parts would not be joined.
void check_joined(const PartMesh& mesh, const std::string& case_file) {
  const Eigen::Index n = mesh.nodes.cols();
  if (n < 2) {
    return;
  }
  const double size = (mesh.nodes.rowwise().maxCoeff() - mesh.nodes.rowwise().minCoeff()).norm();
  const double tolerance = 1e-9 * size;
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return mesh.nodes(0, a) < mesh.nodes(0, b); });
  for (std::size_t i = 0; i < order.size(); ++i) {
    const int a = order[i];
    for (std::size_t j = i + 1;
         j < order.size() && mesh.nodes(0, order[j]) - mesh.nodes(0, a) <= tolerance; ++j) {
      const int b = order[j];
      if ((mesh.nodes.col(a) - mesh.nodes.col(b)).norm() <= tolerance) {
        const Vec3 x = mesh.nodes.col(a);
        throw InputError(fmt::format(
            "{}: blank.parts: gmsh nodes {} and {} of the blank lie at one place ({:.6g}, {:.6g}, "
            "{:.6g}): the parts are not joined there; expected the parts to share the nodes of "
            "their weld line (mesh the parts' surfaces together, e.g. with shared curves in the "
            ".geo, or merge the duplicate nodes)",
            case_file, mesh.gmsh_node_tags[static_cast<std::size_t>(a)],
            mesh.gmsh_node_tags[static_cast<std::size_t>(b)], x(0), x(1), x(2)));
      }
    }
  }
}

}  // namespace

std::vector<int> sort_blank_by_part(const GmshModel& model,
                                    const std::vector<BlankPartConfig>& parts,
                                    const std::string& case_file, PartMesh& mesh) {
  check_joined(mesh, case_file);
  const std::vector<int> part_of = find_element_parts(model, parts, case_file, mesh);
  // Within each block (the part's quads, then its triangles), its elements ordered by part.
  const QuadConn old_quads = mesh.quads;
  const TriConn old_triangles = mesh.triangles;
  const std::vector<std::size_t> old_tags = mesh.gmsh_element_tags;
  const ElementBlocks blocks = element_blocks(old_quads, old_triangles);
  std::vector<int> element_part(static_cast<std::size_t>(blocks.element_count()));
  for (const ElementBlock& block : blocks) {
    const std::vector<int> order = sorted_by_part(part_of, block.first, block.end());
    int* nodes = block.shape == ElementShape::quad ? mesh.quads.data() : mesh.triangles.data();
    const int width = block.nodes_per_element();
    for (int k = 0; k < block.count; ++k) {
      const int e = order[static_cast<std::size_t>(k)];
      const auto to = static_cast<std::size_t>(block.first + k);
      std::copy_n(block.element_nodes(e), width, nodes + static_cast<std::ptrdiff_t>(width) * k);
      mesh.gmsh_element_tags[to] = old_tags[static_cast<std::size_t>(e)];
      element_part[to] = part_of[static_cast<std::size_t>(e)];
    }
  }
  return element_part;
}

std::vector<int> parts_by_name(const std::vector<std::string>& names,
                               const std::vector<int>& element_part,
                               const std::vector<BlankPartConfig>& parts,
                               const std::string& case_file, const std::string& source) {
  std::string case_names;
  for (const BlankPartConfig& p : parts) {
    case_names += (case_names.empty() ? "" : ", ") + p.name;
  }
  const std::string part_names = fmt::format("{}", fmt::join(names, ", "));
  if (names.empty() && !parts.empty()) {
    throw InputError(fmt::format(
        "{}: blank.parts: the formed part {} is a blank of one part; expected a blank of one part "
        "([blank] thickness and material, no [[blank.parts]]) to start from it",
        case_file, source));
  }
  if (!names.empty() && parts.empty()) {
    throw InputError(fmt::format(
        "{}: [blank]: the formed part {} is a blank of parts {}; expected a [[blank.parts]] for "
        "each, of its name, with its thickness and material",
        case_file, source, part_names));
  }
  std::vector<int> case_part(names.size());
  for (std::size_t p = 0; p < names.size(); ++p) {
    const auto found = std::find_if(parts.begin(), parts.end(),
                                    [&](const BlankPartConfig& c) { return c.name == names[p]; });
    if (found == parts.end()) {
      throw InputError(fmt::format(
          "{}: blank.parts: the formed part {} has a part '{}' the case does not name; expected a "
          "[[blank.parts]] named '{}' (the case's parts: {})",
          case_file, source, names[p], names[p], case_names));
    }
    case_part[p] = static_cast<int>(found - parts.begin());
  }
  for (const BlankPartConfig& c : parts) {
    if (std::find(names.begin(), names.end(), c.name) == names.end()) {
      throw InputError(fmt::format(
          "{}:{}: blank.parts ('{}'): the formed part {} has no part of this name; expected one "
          "of its parts: {}",
          case_file, c.line, c.name, source, part_names));
    }
  }
  std::vector<int> out(element_part.size());
  for (std::size_t e = 0; e < out.size(); ++e) {
    out[e] = case_part[static_cast<std::size_t>(element_part[e])];
  }
  return out;
}

std::vector<double> element_thicknesses(const Blank& blank) {
  std::vector<double> t(static_cast<std::size_t>(element_count(blank.part)));
  for (std::size_t e = 0; e < t.size(); ++e) {
    t[e] = blank.parts[static_cast<std::size_t>(material_index(blank.part, static_cast<int>(e)))]
               .thickness;
  }
  return t;
}

ShellState make_blank_shell_state(const Blank& blank, const InitialConditions& initial) {
  ShellState state =
      make_shell_state(element_count(blank.part), initial.integration_points, initial.thickness);
  if (!initial.element_thickness.empty()) {
    state.thickness = initial.element_thickness;
  }
  size_shell_state_for_part(state, blank.part);
  return state;
}

VectorX initial_half_thickness(const Blank& blank, const InitialConditions& initial) {
  if (initial.element_thickness.empty()) {
    return VectorX::Constant(blank.mesh.nodes.cols(), 0.5 * initial.thickness);
  }
  VectorX half(blank.mesh.nodes.cols());
  gather_half_thickness(blank.node_corners, initial.element_thickness, blank.inverse_element_count,
                        half);
  return half;
}

}  // namespace sf
