#include "solver/formed_part.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <type_traits>

#include "core/build_info.hpp"
#include "core/comma_list.hpp"
#include "core/errors.hpp"
#include "results/atomic_hdf5_write.hpp"
#include "results/hdf5_file.hpp"
#include "results/hdf5_probe.hpp"
#include "solver/state_fields.hpp"

namespace sf {

namespace {

constexpr const char* kFormat = "sheetform formed part";
// 2: the tools' turns (rotation, angle, moment); a format 1 part's tools have not turned.
// 3: the blank's parts (/mesh/element_part, /mesh/parts); a format 1 or 2 part is of one part.
// 4: the contact's results (normal forces, sliding distances); an earlier part's start at zero.
constexpr int kFormatVersion = 4;
constexpr const char* kUnits = "mm, tonne, s; N, MPa, N mm";

const char* place_name(FieldPlace place) {
  switch (place) {
    case FieldPlace::run:
      return "run";
    case FieldPlace::node:
      return "node";
    case FieldPlace::element:
      return "element";
    case FieldPlace::point:
      return "point";
    case FieldPlace::tool:
      return "tool";
    case FieldPlace::contact:
      return "contact";
  }
  return "?";
}

// A connectivity (nodes per element, n) as the (n, nodes) table its memory already is.
template <class Conn>
std::span<const int> row_major(const Conn& conn) {
  return {conn.data(), static_cast<std::size_t>(conn.size())};
}

// Writes the fields with the formed-part role under /state, shaped per node or per element.
class FieldWriter {
 public:
  FieldWriter(h5::File& file, int n_elements) : file_(file), n_elements_(n_elements) {}
  template <class T>
  void operator()(const StateField& field, const std::string& key, const T& value) {
    const std::string path = "/state/" + key;
    if constexpr (std::is_arithmetic_v<T>) {
      const double v = static_cast<double>(value);
      file_.write(path, std::span<const double>(&v, 1), {1});
    } else if constexpr (std::is_same_v<T, std::vector<double>>) {
      const std::size_t n = static_cast<std::size_t>(n_elements_);
      const bool per_element = n > 0 && !value.empty() && value.size() % n == 0;
      file_.write(path, value,
                  per_element ? std::vector<hsize_t>{n, value.size() / n}
                              : std::vector<hsize_t>{value.size()});
    } else {
      const std::span<const double> data(value.data(), static_cast<std::size_t>(value.size()));
      file_.write(path, data,
                  value.rows() == 3 ? std::vector<hsize_t>{static_cast<hsize_t>(value.cols()), 3}
                                    : std::vector<hsize_t>{data.size()});
    }
    file_.write_attribute(path, "place", std::string(place_name(field.place)));
    file_.write_attribute(path, "unit", std::string(field.unit));
  }

 private:
  h5::File& file_;
  int n_elements_;
};

// The fields the part's state should hold, by key: the formed-part fields of a state with
// `tools` tools and `contacts` contact pairs.
std::map<std::string, StateField> expected_fields(std::size_t tools, std::size_t contacts) {
  SolutionState s;
  s.tools.resize(tools);
  s.contacts.resize(contacts);
  std::map<std::string, StateField> fields;
  auto record = [&](const StateField& field, const std::string& key, const auto&) {
    fields.emplace(key, field);
  };
  visit_state_fields_with(field_role::formed_part, record, s);
  return fields;
}

// The scalar fields' values in a fresh state (a tool standing as meshed), by key.
std::map<std::string, double> scalar_defaults(std::size_t tools, std::size_t contacts) {
  SolutionState s;
  s.tools.resize(tools);
  s.contacts.resize(contacts);
  std::map<std::string, double> values;
  auto record = [&](const StateField&, const std::string& key, const auto& value) {
    if constexpr (std::is_arithmetic_v<std::decay_t<decltype(value)>>) {
      values.emplace(key, static_cast<double>(value));
    }
  };
  visit_state_fields_with(field_role::formed_part, record, s);
  return values;
}

// A field format 2 added: a tool's turn (format 1 parts come from tools that did not turn).
bool is_turn_field(const StateField& field) {
  namespace f = state_field;
  const auto is = [&](const StateField& turn) {
    return field.place == turn.place && std::string_view(field.name) == turn.name;
  };
  return is(f::tool_rotation) || is(f::tool_previous_rotation) || is(f::tool_angle) ||
         is(f::tool_moment) || is(f::tool_previous_moment);
}

// A field format 4 added: the contact's results (earlier parts' pairs start them at zero).
bool is_contact_result_field(const StateField& field) {
  namespace f = state_field;
  return field.place == FieldPlace::contact &&
         (std::string_view(field.name) == f::contact_normal_force.name ||
          std::string_view(field.name) == f::sliding_distance.name);
}

// A field a part may lack: one the next model makes again from its mesh (a trimmed part's
// forces, masses and offsets) or starts afresh (a contact pair's history).
bool may_be_left_out(const StateField& field) {
  return field.place == FieldPlace::contact || field.mapping == FieldMapping::recompute ||
         field.mapping == FieldMapping::reset;
}

void write_header(h5::File& out) {
  out.write_attribute("/", "format", std::string(kFormat));
  out.write_attribute("/", "format_version", kFormatVersion);
  out.write_attribute("/", "git_hash", std::string(build_info::git_hash));
  out.write_attribute("/", "units", std::string(kUnits));
}

// The model's parts' names (none for a blank of one part).
std::vector<std::string> part_names(const Blank& blank) {
  std::vector<std::string> names;
  if (blank.parts.size() > 1) {
    for (const BlankPartInfo& p : blank.parts) {
      names.push_back(p.name);
    }
  }
  return names;
}

// The parts of a blank of several: each element's part, and each part's name.
void write_parts(h5::File& out, const std::vector<std::string>& names,
                 std::span<const int> element_part) {
  if (names.empty()) {
    return;
  }
  out.write("/mesh/element_part", element_part, {element_part.size()});
  for (std::size_t p = 0; p < names.size(); ++p) {
    const std::string path = "/mesh/parts/" + std::to_string(p);
    out.create_group(path);
    out.write_attribute(path, "name", names[p]);
  }
}

void write_mesh(h5::File& out, const Matrix3X& nodes, std::span<const double> tags,
                const QuadConn& quads, const TriConn& triangles,
                std::span<const double> initial_thickness,
                const std::map<std::string, std::vector<int>>& groups) {
  out.write("/mesh/reference_nodes",
            std::span<const double>(nodes.data(), static_cast<std::size_t>(nodes.size())),
            {static_cast<hsize_t>(nodes.cols()), 3});
  out.write("/mesh/node_tags", tags, {tags.size()});
  out.write("/mesh/quads", row_major(quads), {static_cast<hsize_t>(quads.cols()), 4});
  out.write("/mesh/triangles", row_major(triangles), {static_cast<hsize_t>(triangles.cols()), 3});
  out.write("/mesh/initial_thickness", initial_thickness, {initial_thickness.size()});
  out.create_group("/mesh/groups");
  for (const auto& [name, group] : groups) {
    out.write("/mesh/groups/" + name, group, {group.size()});
  }
}

void write_section(h5::File& out, int n_points, const std::string& rule, const std::string& law) {
  out.create_group("/section");
  out.write_attribute("/section", "n_points", n_points);
  out.write_attribute("/section", "rule", rule);
  out.create_group("/material");
  out.write_attribute("/material", "law", law);
}

void write_mesh(h5::File& out, const Model& model) {
  const PartMesh& mesh = model.blank.mesh;
  const std::vector<double> tags(mesh.gmsh_node_tags.begin(), mesh.gmsh_node_tags.end());
  const std::vector<double> t0 =
      model.initial.element_thickness.empty()
          ? std::vector<double>(static_cast<std::size_t>(element_count(model.blank.part)),
                                model.initial.thickness)
          : model.initial.element_thickness;
  std::map<std::string, std::vector<int>> groups;
  for (const NodeGroup& g : model.blank.groups) {
    groups[g.name] = g.nodes;
  }
  write_mesh(out, mesh.nodes, tags, mesh.quads, mesh.triangles, t0, groups);
  write_parts(out, part_names(model.blank), model.blank.part.element_material);
}

}  // namespace

std::string material_law_kind(const Material& material) {
  return std::visit(
      [](const auto& law) -> std::string {
        using Law = std::decay_t<decltype(law)>;
        if constexpr (std::is_same_v<Law, ElasticPlaneStress>) {
          return "elastic";
        } else if constexpr (std::is_same_v<Law, J2PlaneStress>) {
          return "j2";
        } else if constexpr (std::is_same_v<Law, Hill48PlaneStress>) {
          return "hill48";
        } else {
          return "general_plasticity";
        }
      },
      material);
}

std::string material_law_kinds(const ShellPart& part) {
  std::string kinds;
  for (const ShellMaterial& m : part.materials) {
    kinds += (kinds.empty() ? "" : ", ") + material_law_kind(m.law);
  }
  return kinds;
}

void write_formed_part(const std::filesystem::path& file, const Model& model,
                       const SolutionState& state) {
  write_hdf5_atomically(file, "formed part", [&](h5::File& out) {
    write_header(out);
    write_mesh(out, model);
    const ShellPart& part = model.blank.part;
    write_section(out, part.section.n_points,
                  std::string(choice_name<ThroughThicknessRule>(kThroughThicknessRuleNames,
                                                                part.section.rule)),
                  material_law_kinds(part));
    FieldWriter writer(out, state.shell.n_elements);
    visit_state_fields_with(field_role::formed_part, writer, state);
    for (std::size_t t = 0; t < model.tools.size(); ++t) {
      out.write_attribute("/state/tools/" + std::to_string(t), "name", model.tools[t].name);
    }
    for (std::size_t c = 0; c < model.contacts.size(); ++c) {
      out.write_attribute("/state/contacts/" + std::to_string(c), "tool",
                          model.tools[static_cast<std::size_t>(model.contacts[c].tool)].name);
    }
  });
}

void write_formed_part(const std::filesystem::path& file, const FormedPart& part) {
  const auto n_nodes = static_cast<std::size_t>(part.reference_nodes.cols());
  const auto n_elements = static_cast<std::size_t>(part.quads.cols() + part.triangles.cols());
  write_hdf5_atomically(file, "formed part", [&](h5::File& out) {
    write_header(out);
    write_mesh(out, part.reference_nodes, part.node_tags, part.quads, part.triangles,
               part.initial_thickness, part.groups);
    write_parts(out, part.part_names, part.element_part);
    write_section(out, part.n_points, part.rule, part.law);
    std::string left_out;
    for (const auto& [key, field] : expected_fields(part.tools.size(), part.contact_tools.size())) {
      const auto found = part.fields.find(key);
      if (found == part.fields.end()) {
        left_out += (left_out.empty() ? "" : ",") + key;
        continue;
      }
      const std::vector<double>& v = found->second;
      const std::string path = "/state/" + key;
      std::vector<hsize_t> shape{v.size()};
      if (field.place == FieldPlace::node && v.size() == 3 * n_nodes) {
        shape = {n_nodes, 3};
      } else if ((field.place == FieldPlace::element || field.place == FieldPlace::point) &&
                 n_elements > 0 && !v.empty() && v.size() % n_elements == 0) {
        shape = {n_elements, v.size() / n_elements};
      }
      out.write(path, v, shape);
      out.write_attribute(path, "place", std::string(place_name(field.place)));
      out.write_attribute(path, "unit", std::string(field.unit));
    }
    // The groups a part left without fields (a contact pair's) still name their tool
    // (create_group makes a missing group and its parents, and leaves one that is there).
    out.create_group("/state");
    out.write_attribute("/state", "left_out", left_out);
    for (std::size_t t = 0; t < part.tools.size(); ++t) {
      const std::string tool = "/state/tools/" + std::to_string(t);
      out.create_group(tool);
      out.write_attribute(tool, "name", part.tools[t]);
    }
    for (std::size_t c = 0; c < part.contact_tools.size(); ++c) {
      const std::string contact = "/state/contacts/" + std::to_string(c);
      out.create_group(contact);
      out.write_attribute(contact, "tool", part.contact_tools[c]);
    }
  });
}

namespace {

// Reads one formed part (libhdf5 known to survive it), checking every entry before use.
class PartReader {
 public:
  PartReader(const h5::File& in, std::string where) : in_(in), where_(std::move(where)) {}

  // A list of doubles or integers of `shape`'s size (a dimension of -1: any, within `limit`).
  std::vector<double> doubles(const std::string& path, std::size_t limit) const {
    check_size(path, limit);
    if (!in_.holds_doubles(path)) {
      fail(path, "does not hold 64-bit floating-point numbers");
    }
    return in_.read_doubles(path);
  }
  std::vector<int> ints(const std::string& path, std::size_t limit, int below) const {
    check_size(path, limit);
    std::vector<int> values = in_.read_ints(path);
    for (int v : values) {
      if (v < 0 || v >= below) {
        fail(path, fmt::format("holds {}, a node index is 0 to {}", v, below - 1));
      }
    }
    return values;
  }
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw InputError(fmt::format("{}: entry {} {} (a damaged formed part)", where_, path, what));
  }
  const std::string& where() const { return where_; }

 private:
  void check_size(const std::string& path, std::size_t limit) const {
    if (!in_.exists(path)) {
      throw InputError(
          fmt::format("{}: no entry {} (not a formed part of this format)", where_, path));
    }
    if (in_.value_count(path) > limit) {
      fail(path, fmt::format("holds {} values, more than the {} the part can have",
                             in_.value_count(path), limit));
    }
  }
  const h5::File& in_;
  std::string where_;
};

template <class Conn>
Conn read_connectivity(const PartReader& r, const std::string& path, int nodes_per_element,
                       int n_nodes, const std::vector<hsize_t>& shape) {
  if (shape.size() != 2 || shape[1] != static_cast<hsize_t>(nodes_per_element)) {
    r.fail(path, fmt::format("is not a table of {} node indices per element", nodes_per_element));
  }
  const std::vector<int> v =
      r.ints(path, static_cast<std::size_t>(shape[0]) * nodes_per_element, n_nodes);
  Conn conn(nodes_per_element, static_cast<Eigen::Index>(shape[0]));
  std::copy(v.begin(), v.end(), conn.data());
  return conn;
}

// The parts of a blank of several (format 3; none: a blank of one part).
void read_parts(const h5::File& in, const PartReader& r, std::size_t n_elements, FormedPart& part) {
  if (!in.exists("/mesh/parts")) {
    return;
  }
  const std::size_t count = in.list("/mesh/parts").size();
  if (count < 2 || count > n_elements) {
    r.fail("/mesh/parts",
           fmt::format("holds {} parts, not 2 to the {} elements", count, n_elements));
  }
  for (std::size_t p = 0; p < count; ++p) {
    std::string name = in.read_attribute_string("/mesh/parts/" + std::to_string(p), "name");
    if (std::find(part.part_names.begin(), part.part_names.end(), name) != part.part_names.end()) {
      r.fail("/mesh/parts/" + std::to_string(p),
             fmt::format("names part '{}' a second time (each part's name is its own)", name));
    }
    part.part_names.push_back(std::move(name));
  }
  part.element_part = r.ints("/mesh/element_part", n_elements, static_cast<int>(count));
  if (part.element_part.size() != n_elements) {
    r.fail("/mesh/element_part", fmt::format("holds {} values, not one per element ({})",
                                             part.element_part.size(), n_elements));
  }
}

FormedPart read_checked_part(const std::filesystem::path& file) {
  const std::string where = file.string();
  try {
    const h5::File in(file, h5::FileMode::read_only);
    if (!in.has_attribute("/", "format") || in.read_attribute_string("/", "format") != kFormat) {
      throw InputError(where + ": not a sheetform formed part (a results folder's formed_part.h5)");
    }
    const int version = in.read_attribute_int("/", "format_version");
    if (version < 1 || version > kFormatVersion) {
      throw InputError(fmt::format(
          "{}: formed part format {}, this build reads formats 1 to {} (written by a {} build)",
          where, version, kFormatVersion, version > kFormatVersion ? "newer" : "older"));
    }
    const PartReader r(in, where);
    FormedPart part;
    part.file = where;
    const std::vector<hsize_t> node_shape = in.exists("/mesh/reference_nodes")
                                                ? in.shape("/mesh/reference_nodes")
                                                : std::vector<hsize_t>{};
    if (node_shape.size() != 2 || node_shape[1] != 3 || node_shape[0] == 0 ||
        node_shape[0] > static_cast<hsize_t>(std::numeric_limits<int>::max() / 64)) {
      r.fail("/mesh/reference_nodes", "is not a table of (x, y, z) per node");
    }
    const int n = static_cast<int>(node_shape[0]);
    const std::vector<double> xyz = r.doubles("/mesh/reference_nodes", 3 * node_shape[0]);
    part.reference_nodes = Eigen::Map<const Matrix3X>(xyz.data(), 3, n);
    part.node_tags = r.doubles("/mesh/node_tags", node_shape[0]);
    part.quads = read_connectivity<QuadConn>(r, "/mesh/quads", 4, n, in.shape("/mesh/quads"));
    part.triangles =
        read_connectivity<TriConn>(r, "/mesh/triangles", 3, n, in.shape("/mesh/triangles"));
    const std::size_t n_elements =
        static_cast<std::size_t>(part.quads.cols() + part.triangles.cols());
    part.initial_thickness = r.doubles("/mesh/initial_thickness", n_elements);
    if (part.initial_thickness.size() != n_elements ||
        !std::all_of(part.initial_thickness.begin(), part.initial_thickness.end(),
                     [](double t) { return std::isfinite(t) && t > 0.0; })) {
      r.fail("/mesh/initial_thickness", "is not a positive thickness per element");
    }
    for (const std::string& name : in.list("/mesh/groups")) {
      part.groups[name] = r.ints("/mesh/groups/" + name, node_shape[0], n);
    }
    read_parts(in, r, n_elements, part);
    part.n_points = in.read_attribute_int("/section", "n_points");
    if (part.n_points < 1 || part.n_points > 9) {
      r.fail("/section@n_points", fmt::format("is {}, not 1 to 9", part.n_points));
    }
    part.rule = in.read_attribute_string("/section", "rule");
    part.law = in.read_attribute_string("/material", "law");
    const std::size_t tools = in.exists("/state/tools") ? in.list("/state/tools").size() : 0;
    for (std::size_t t = 0; t < tools; ++t) {
      part.tools.push_back(in.read_attribute_string("/state/tools/" + std::to_string(t), "name"));
    }
    // No field holds more than 3 values per node, or (12 directors) per element, or 3 back
    // stresses of 3 components per point.
    const std::size_t limit = std::max<std::size_t>(
        {3 * node_shape[0], 12 * n_elements, 9 * n_elements * part.n_points, 1});
    const std::size_t contacts =
        in.exists("/state/contacts") ? in.list("/state/contacts").size() : 0;
    for (std::size_t c = 0; c < contacts; ++c) {
      part.contact_tools.push_back(
          in.read_attribute_string("/state/contacts/" + std::to_string(c), "tool"));
    }
    // A part trimmed (solver/trim.hpp) lists the fields the next model makes again.
    const std::vector<std::string> left_out =
        in.has_attribute("/state", "left_out")
            ? split_comma_list(in.read_attribute_string("/state", "left_out"))
            : std::vector<std::string>{};
    const std::map<std::string, double> unturned = scalar_defaults(tools, contacts);
    for (const auto& [key, field] : expected_fields(tools, contacts)) {
      if (version == 1 && is_turn_field(field)) {
        part.fields[key] = {unturned.at(key)};
        continue;
      }
      if (version <= 3 && is_contact_result_field(field)) {
        continue;  // the pair starts them at zero (FieldCopy: a contact field may be left out)
      }
      if (!in.exists("/state/" + key) && may_be_left_out(field) &&
          std::find(left_out.begin(), left_out.end(), key) != left_out.end()) {
        continue;
      }
      part.fields[key] = r.doubles("/state/" + key, limit);
    }
    return part;
  } catch (const h5::Error& e) {
    throw InputError(where + ": cannot read the formed part: " + e.what());
  }
}

}  // namespace

FormedPart read_formed_part(const std::filesystem::path& file) {
  const std::string where = file.string();
  if (!std::filesystem::is_regular_file(file)) {
    throw InputError(where + ": no such formed part (a run writes <results>/formed_part.h5)");
  }
  read_in_child_first(file, "formed part", [&] { read_checked_part(file); });
  return read_checked_part(file);
}

namespace {

// Refuses a part whose elements are in other parts than the model's, or of other laws (each
// part's law compared by its name, whatever the order in which the case lists the parts).
template <class Refuse>
void check_same_parts(const FormedPart& part, const Model& model, const Refuse& refuse) {
  const ShellPart& shell = model.blank.part;
  const std::vector<std::string> names = part_names(model.blank);
  if (names.empty() != part.part_names.empty()) {
    refuse(fmt::format(
        "a blank of {}; the case's blank is of {}",
        part.part_names.empty() ? "one part"
                                : fmt::format("parts {}", fmt::join(part.part_names, ", ")),
        names.empty() ? "one part" : fmt::format("parts {}", fmt::join(names, ", "))));
  }
  if (names.empty()) {
    if (part.law != material_law_kinds(shell)) {
      refuse(fmt::format("material law {}; the case's blank has {}", part.law,
                         material_law_kinds(shell)));
    }
    return;
  }
  std::vector<int> model_part(part.part_names.size(), -1);  // the part's parts in the model
  for (std::size_t p = 0; p < part.part_names.size(); ++p) {
    const auto found = std::find(names.begin(), names.end(), part.part_names[p]);
    if (found == names.end()) {
      refuse(fmt::format("a part '{}'; the case's blank has parts {}", part.part_names[p],
                         fmt::join(names, ", ")));
    }
    model_part[p] = static_cast<int>(found - names.begin());
  }
  for (std::size_t e = 0; e < part.element_part.size(); ++e) {
    const int p = part.element_part[e];
    if (model_part[static_cast<std::size_t>(p)] != material_index(shell, static_cast<int>(e))) {
      refuse(
          fmt::format("element {} is in part '{}'; the case's is in part '{}'", e,
                      part.part_names[static_cast<std::size_t>(p)],
                      names[static_cast<std::size_t>(material_index(shell, static_cast<int>(e)))]));
    }
  }
  std::string laws;  // the model's laws in the part's order of parts
  for (const int p : model_part) {
    laws += (laws.empty() ? "" : ", ") +
            material_law_kind(shell.materials[static_cast<std::size_t>(p)].law);
  }
  if (part.law != laws) {
    refuse(fmt::format("material laws {} (parts {}); the case's blank has {}", part.law,
                       fmt::join(part.part_names, ", "), laws));
  }
}

// Refuses a part whose blank is not the model's: it would put one mesh's state on another.
void check_same_blank(const FormedPart& part, const Model& model) {
  const PartMesh& mesh = model.blank.mesh;
  const ShellPart& shell = model.blank.part;
  const std::string rule(
      choice_name<ThroughThicknessRule>(kThroughThicknessRuleNames, shell.section.rule));
  auto refuse = [&](const std::string& what) {
    throw InputError(fmt::format("{}: a formed part of another blank: {}", part.file, what));
  };
  if (part.reference_nodes.cols() != mesh.nodes.cols() || part.quads.cols() != mesh.quads.cols() ||
      part.triangles.cols() != mesh.triangles.cols()) {
    refuse(fmt::format("{} nodes, {} quads, {} triangles; the case's blank has {}, {}, {}",
                       part.reference_nodes.cols(), part.quads.cols(), part.triangles.cols(),
                       mesh.nodes.cols(), mesh.quads.cols(), mesh.triangles.cols()));
  }
  for (Eigen::Index i = 0; i < mesh.nodes.cols(); ++i) {
    if (part.reference_nodes.col(i) != mesh.nodes.col(i)) {
      refuse(fmt::format("node {} was at ({}, {}, {}) mm, the case's is at ({}, {}, {}) mm", i,
                         part.reference_nodes(0, i), part.reference_nodes(1, i),
                         part.reference_nodes(2, i), mesh.nodes(0, i), mesh.nodes(1, i),
                         mesh.nodes(2, i)));
    }
  }
  if (part.quads != mesh.quads || part.triangles != mesh.triangles) {
    refuse("the elements join other nodes");
  }
  if (part.n_points != shell.section.n_points || part.rule != rule) {
    refuse(fmt::format("{} {} points through the thickness; the case's blank has {} {}",
                       part.n_points, part.rule, shell.section.n_points, rule));
  }
  check_same_parts(part, model, refuse);
}

// Copies the part's fields into the state, checking each one's size against the model's.
class FieldCopy {
 public:
  FieldCopy(const FormedPart& part, std::vector<int> part_tool, std::vector<int> part_contact)
      : part_(part), part_tool_(std::move(part_tool)), part_contact_(std::move(part_contact)) {}
  template <class T>
  void operator()(const StateField& field, const std::string& key, T& value) {
    std::string part_key = key;
    if (field.place == FieldPlace::tool || field.place == FieldPlace::contact) {
      // "tools/T/..." or "contacts/C/...": the part's own index of the tool or pair
      const std::size_t first = key.find('/') + 1;
      const std::size_t slash = key.find('/', first);
      const auto index = static_cast<std::size_t>(std::stoi(key.substr(first, slash - first)));
      const int in_part =
          field.place == FieldPlace::tool ? part_tool_[index] : part_contact_[index];
      if (in_part < 0) {
        return;  // of this case only: it starts as the case sets it
      }
      part_key = key.substr(0, first) + std::to_string(in_part) + key.substr(slash);
    }
    const auto found = part_.fields.find(part_key);
    if (found == part_.fields.end()) {
      if (may_be_left_out(field)) {
        return;  // left out by a trim: the model's own, recomputed (solver/trim.hpp)
      }
      throw InputError(
          fmt::format("{}: no entry /state/{} (a damaged formed part)", part_.file, part_key));
    }
    const std::vector<double>& data = found->second;
    if constexpr (!std::is_arithmetic_v<T>) {
      if (field.place == FieldPlace::contact &&
          data.size() != static_cast<std::size_t>(value.size())) {
        return;  // friction on in one case only: no stick forces to hand on
      }
    }
    if constexpr (std::is_arithmetic_v<T>) {
      check_size(part_key, data.size(), 1);
      if constexpr (std::is_same_v<T, double>) {
        value = data[0];
      } else {
        const double lowest = std::is_same_v<T, bool> ? 0.0 : -1.0;
        const double beyond = std::is_same_v<T, bool> ? 2.0 : std::ldexp(1.0, 31);
        if (!(data[0] >= lowest && data[0] < beyond && data[0] == std::trunc(data[0]))) {
          throw InputError(
              fmt::format("{}: entry /state/{} is {}, not a count (a damaged "
                          "formed part)",
                          part_.file, part_key, data[0]));
        }
        value = static_cast<T>(data[0]);
      }
    } else {
      check_size(part_key, data.size(), static_cast<std::size_t>(value.size()));
      std::copy(data.begin(), data.end(), value.data());
    }
  }

 private:
  void check_size(const std::string& key, std::size_t has, std::size_t needs) const {
    if (has != needs) {
      throw InputError(fmt::format(
          "{}: entry /state/{} holds {} values, the case's blank needs {} (a formed part of "
          "another material law or element)",
          part_.file, key, has, needs));
    }
  }
  const FormedPart& part_;
  std::vector<int> part_tool_;
  std::vector<int> part_contact_;
};

}  // namespace

std::vector<std::string> apply_formed_part(const FormedPart& part, const Model& model,
                                           SolutionState& state) {
  check_same_blank(part, model);
  std::vector<int> part_tool(model.tools.size(), -1);
  std::vector<std::string> placed;
  for (std::size_t t = 0; t < model.tools.size(); ++t) {
    const auto found = std::find(part.tools.begin(), part.tools.end(), model.tools[t].name);
    if (found != part.tools.end()) {
      part_tool[t] = static_cast<int>(found - part.tools.begin());
      placed.push_back(model.tools[t].name);
    }
  }
  // A pair takes the stick forces of the part's pair with its tool, when that tool was placed.
  std::vector<int> part_contact(model.contacts.size(), -1);
  for (std::size_t c = 0; c < model.contacts.size(); ++c) {
    const auto tool = static_cast<std::size_t>(model.contacts[c].tool);
    const auto found =
        std::find(part.contact_tools.begin(), part.contact_tools.end(), model.tools[tool].name);
    if (part_tool[tool] >= 0 && found != part.contact_tools.end()) {
      part_contact[c] = static_cast<int>(found - part.contact_tools.begin());
    }
  }
  FieldCopy copy(part, std::move(part_tool), std::move(part_contact));
  visit_state_fields_with(field_role::formed_part, copy, state);
  return placed;
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
  b.part_names = part.part_names;
  b.element_part = part.element_part;
  b.source = part.file;
  return b;
}

}  // namespace sf
