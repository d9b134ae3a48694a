#include "casefile/case_config_node_groups.hpp"

#include <fmt/core.h>

#include <array>

#include "casefile/case_fields.hpp"

namespace sf {
namespace {

FieldTable<NodeGroupConfig> make_node_group_fields() {
  using G = NodeGroupConfig;
  const NumberRange any_mm{.unit = "mm"};
  FieldTable<G> t;
  t.push_back(name_field<G>("name", &G::name,
                            "the group's name, used as a physical group's name is (`group = "
                            "...` of `[[boundary]]`, `[[history]]`, `[[draw_in]]`, ...); not a "
                            "physical group of the blank's mesh")
                  .required());
  t.push_back(numbers_field<G>("point", &G::point, any_mm, 3, 3,
                               "with `normal`: a point of the plane (default the origin); alone: "
                               "the group is the one blank node nearest to it"));
  Field<G> normal = numbers_field<G>("normal", &G::normal, NumberRange{}, 3, 3,
                                     "the nodes within `tolerance` of the plane through `point` "
                                     "with this normal; not all zero, normalised on reading");
  normal.read = [](const TomlSection& s, G& g, Presence) {
    std::array<double, 3> n{};
    if (s.read_direction("normal", n)) {  // refuses a zero vector; a unit one is kept bit for bit
      g.normal.assign(n.begin(), n.end());
    }
  };
  t.push_back(std::move(normal));
  t.push_back(numbers_field<G>("box", &G::box, any_mm, 6, 6,
                               "`[x_min, y_min, z_min, x_max, y_max, z_max]`: the nodes inside "
                               "the box (its faces moved out by `tolerance`)"));
  t.push_back(bool_field<G>("outline", &G::outline,
                            "only the nodes on the blank's outline (edges of one element)"));
  t.push_back(number_field<G>("tolerance", &G::tolerance, at_least(0.0, "mm"),
                              "how far off the plane or outside the box a node may be; 0 = 1 % "
                              "of the blank's shortest element edge")
                  .write_if([](const G& g) { return g.tolerance > 0.0; }));
  return t;
}

/// The checks across keys: at least one criterion, an ordered box, a point either alone or with a
/// normal.
void check_node_group(const TomlSection& s, const NodeGroupConfig& g) {
  if (g.point.empty() && g.normal.empty() && g.box.empty() && !g.outline) {
    s.fail_missing("normal",
                   "at least one of point, normal, box, outline = true (a node group "
                   "chooses blank nodes by position)");
  }
  for (std::size_t k = 0; k < 3 && !g.box.empty(); ++k) {
    if (g.box[k] > g.box[k + 3]) {
      s.fail_value("box", fmt::format("[x_min, y_min, z_min, x_max, y_max, z_max] with each "
                                      "minimum at most its maximum ({} min {:g} > max {:g})",
                                      "xyz"[k], g.box[k], g.box[k + 3]));
    }
  }
  if (!g.point.empty() && g.normal.empty() && (!g.box.empty() || g.outline)) {
    s.fail_value("point",
                 "a plane's point, with normal; or alone, the nearest node (not with "
                 "box or outline)");
  }
}

}  // namespace

const FieldTable<NodeGroupConfig>& node_group_fields() {
  static const FieldTable<NodeGroupConfig> table = make_node_group_fields();
  return table;
}

void read_node_groups(const TomlSection& top, CaseConfig& config) {
  const std::vector<TomlSection> sections = top.table_array("node_group");
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const TomlSection& s = sections[i];
    NodeGroupConfig g;
    read_table(s, node_group_fields(), g);
    check_node_group(s, g);
    for (std::size_t j = 0; j < i; ++j) {
      if (config.node_groups[j].name == g.name) {
        s.fail_at(*s.find("name"), s.key_path("name"),
                  fmt::format("node group {} is already defined by node_group[{}]",
                              quote_toml_string(g.name), j));
      }
    }
    g.line = static_cast<int>(s.table().source().begin.line);
    config.node_groups.push_back(std::move(g));
  }
}

}  // namespace sf
