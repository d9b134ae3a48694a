#include "meshing/gmsh_model.hpp"

#include "core/errors.hpp"
#include "core/quoted.hpp"

namespace sf {

const GmshPhysicalGroup* GmshModel::find_group(const std::string& name, int dim) const {
  for (const auto& g : groups) {  // sorted by (dim, tag): the lowest dimension comes first
    if (g.name == name && (dim < 0 || g.dim == dim)) {
      return &g;
    }
  }
  return nullptr;
}

std::string GmshModel::list_groups() const {
  std::string text;
  for (const auto& g : groups) {
    text += (text.empty() ? "" : ", ") + group_label(g);
  }
  return text.empty() ? "none" : text;
}

std::string group_label(const GmshPhysicalGroup& g) {
  return (g.name.empty() ? "(unnamed, tag " + std::to_string(g.tag) + ")" : g.name) + " (" +
         std::to_string(g.dim) + "-D)";
}

void check_model_has_groups(const GmshModel& model) {
  const std::string file = quoted(model.file);
  if (model.node_tags.empty()) {
    throw InputError(file + ": the mesh is empty (gmsh made no nodes)");
  }
  if (model.groups.empty()) {
    throw InputError(file +
                     ": no physical groups (name the parts, e.g. Physical Surface(\"blank\") = "
                     "{1};)");
  }
  std::size_t element_count = 0;
  for (const auto& group : model.groups) {
    for (const auto& block : group.elements) {
      element_count += block.element_tags.size();
    }
  }
  if (element_count == 0) {
    throw InputError(file + ": the mesh is empty (no elements in its physical groups)");
  }
}

}  // namespace sf
