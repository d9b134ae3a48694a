// read_case: case.toml -> CaseConfig. The reader starts from default-constructed structs (the
// defaults live in case_config.hpp) and overwrites what the file gives, checking every key.
#include "io/case_config.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>

#include "core/errors.hpp"
#include "io/case_config_common.hpp"
#include "io/case_config_constraints.hpp"
#include "io/case_config_history.hpp"
#include "io/case_config_implicit.hpp"
#include "io/case_overrides.hpp"
#include "io/mesh_import.hpp"
#include "io/toml_reader.hpp"
#include "io/unit_system.hpp"

namespace sf {

namespace fs = std::filesystem;

namespace {

/// Reads `key` as a path (relative to `folder`) to a file that must exist; returns it absolute.
/// `accepts` says whether its extension is one of `accepted` (text for the message).
fs::path read_existing_file(const TomlSection& s, std::string_view key, const fs::path& folder,
                            const std::function<bool(const fs::path&)>& accepts,
                            std::string_view accepted) {
  std::string text;
  s.read_string(key, text, Presence::required);
  const toml::node& node = *s.find(key);
  const fs::path given(text);
  if (!accepts(given)) {
    s.fail_value(key, fmt::format("a {} file", accepted));
  }
  const fs::path file = (given.is_absolute() ? given : folder / given).lexically_normal();
  std::error_code error;
  if (!fs::exists(file, error)) {
    s.fail_at(node, s.key_path(key), fmt::format("file not found: {}", file.string()));
  }
  if (!fs::is_regular_file(file, error)) {
    s.fail_at(node, s.key_path(key), fmt::format("not a regular file: {}", file.string()));
  }
  return file;
}

bool is_geo_identifier(std::string_view name) {
  for (std::size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
    if (!letter && !(i > 0 && c >= '0' && c <= '9')) {
      return false;
    }
  }
  return !name.empty();
}

/// `parameters`: a table of numbers set in a .geo before gmsh parses it ({ n = 16 }).
void read_geo_parameters(const TomlSection& s, const MeshSourceConfig& mesh,
                         std::vector<GeoParameter>& parameters) {
  const toml::node* node = s.find("parameters");
  if (!node) {
    return;
  }
  if (mesh.file.extension() != ".geo") {
    s.fail_forbidden("parameters",
                     "parameters are set in a .geo file before gmsh parses it; a .msh mesh is "
                     "read as it is");
  }
  const toml::table* table = node->as_table();
  if (!table) {
    s.fail_value("parameters", "a table of numbers, e.g. { n = 16 }");
  }
  const std::string path = s.key_path("parameters");
  for (const auto& [key, value] : *table) {
    const std::string name(key.str());
    const std::string key_path = fmt::format("{}.{}", path, name);
    const auto& region = key.source().begin.line != 0 ? key.source() : value.source();
    if (!is_geo_identifier(name)) {
      s.fail_at(value, key_path,
                "expected a .geo variable name (a letter or '_', then letters, digits or '_')");
    }
    const std::optional<double> number = number_of(value);
    if (!number || !std::isfinite(*number)) {
      s.fail_at(value, key_path,
                fmt::format("expected a finite number, got {}", describe_value(value)));
    }
    parameters.push_back({name, *number, format_location(s.file(), region)});
  }
  std::sort(parameters.begin(), parameters.end(),
            [](const GeoParameter& a, const GeoParameter& b) { return a.name < b.name; });
}

// The keys of CAD and STL files: scale, curvature refinement (CAD), the surfaces that form the
// part; each refused for the formats it means nothing to.
void read_import_keys(const TomlSection& s, MeshSourceConfig& mesh) {
  const MeshFormat format = mesh_format(mesh.file);
  const bool imported = is_imported(format);
  if (format == MeshFormat::geo && s.has("scale")) {
    s.fail_forbidden("scale", "a .geo script sets its own lengths; scale is for the other formats");
  }
  s.read_number("scale", mesh.scale, greater_than(0.0));
  if (!is_cad(format) && s.has("curvature_elements")) {
    s.fail_forbidden("curvature_elements", "curvature refinement is for a CAD mesh source");
  }
  s.read_integer("curvature_elements", mesh.curvature_elements,
                 IntegerRange{.lo = 0, .hi = 1000, .unit = "elements per 2 pi of curvature"});
  if (!imported && s.has("surfaces")) {
    s.fail_forbidden("surfaces",
                     "a surface list is for a CAD, STL, Nastran, UNV or VTK file; a .geo or .msh "
                     "names its parts by physical groups");
  }
  std::vector<double> tags;
  if (s.read_numbers("surfaces", tags, at_least(1.0, "surface tags"), 1, 100000)) {
    for (const double t : tags) {
      if (t != std::floor(t) || t > 2147483647.0) {
        s.fail_value("surfaces", "whole surface tags (integers >= 1)");
      }
      mesh.surfaces.push_back(static_cast<int>(t));
    }
  }
}

void read_mesh_source(const TomlSection& s, const fs::path& folder, MeshSourceConfig& mesh) {
  mesh.file = read_existing_file(
      s, "mesh", folder, [](const fs::path& p) { return find_mesh_format(p).has_value(); },
      accepted_mesh_extensions());
  s.read_string("group", mesh.group);
  s.read_number("element_size", mesh.element_size, at_least(0.0, "mm"));
  if (is_cad(mesh_format(mesh.file)) && !(mesh.element_size > 0.0)) {
    s.fail_missing("element_size", "an element size > 0 (mm): a CAD file has no mesh sizes");
  }
  read_geo_parameters(s, mesh, mesh.parameters);
  read_import_keys(s, mesh);
}

void read_hardening(const TomlSection& s, const fs::path& folder, HardeningConfig& hardening) {
  using Law = HardeningConfig::Law;
  s.read_choice("law", hardening.law,
                {{"swift", Law::swift},
                 {"linear", Law::linear},
                 {"voce", Law::voce},
                 {"ludwik", Law::ludwik},
                 {"tabulated", Law::tabulated},
                 {"hockett_sherby", Law::hockett_sherby},
                 {"swift_voce", Law::swift_voce}});
  switch (hardening.law) {
    case Law::swift:
      s.check_keys({"law", "K", "eps0", "n"});
      s.read_number("K", hardening.swift_k, greater_than(0.0, "MPa"), Presence::required);
      s.read_number("eps0", hardening.swift_eps0, at_least(0.0), Presence::required);
      s.read_number("n", hardening.swift_n, interval(0.0, false, 1.0, true), Presence::required);
      return;
    case Law::linear:
      s.check_keys({"law", "yield_stress", "modulus"});
      s.read_number("yield_stress", hardening.yield_stress, greater_than(0.0, "MPa"),
                    Presence::required);
      s.read_number("modulus", hardening.modulus, at_least(0.0, "MPa"), Presence::required);
      return;
    case Law::voce:
      s.check_keys({"law", "sigma0", "Q", "b"});
      s.read_number("sigma0", hardening.voce_sigma0, greater_than(0.0, "MPa"), Presence::required);
      s.read_number("Q", hardening.voce_q, at_least(0.0, "MPa"), Presence::required);
      s.read_number("b", hardening.voce_b, greater_than(0.0), Presence::required);
      return;
    case Law::ludwik:
      s.check_keys({"law", "A", "B", "n"});
      s.read_number("A", hardening.ludwik_a, greater_than(0.0, "MPa"), Presence::required);
      s.read_number("B", hardening.ludwik_b, at_least(0.0, "MPa"), Presence::required);
      s.read_number("n", hardening.ludwik_n, interval(0.0, true, 1.0, false), Presence::required);
      return;
    case Law::hockett_sherby:
      s.check_keys({"law", "sigma_s", "sigma_i", "N", "p"});
      s.read_number("sigma_s", hardening.hs_sigma_s, greater_than(0.0, "MPa"), Presence::required);
      s.read_number("sigma_i", hardening.hs_sigma_i,
                    interval(0.0, true, hardening.hs_sigma_s, false, "MPa"), Presence::required);
      s.read_number("N", hardening.hs_n, greater_than(0.0), Presence::required);
      s.read_number("p", hardening.hs_p, interval(0.0, true, 1.0, false));
      return;
    case Law::swift_voce:
      s.check_keys({"law", "weight", "K", "eps0", "n", "sigma0", "Q", "b"});
      s.read_number("weight", hardening.sv_weight, interval(0.0, false, 1.0, false),
                    Presence::required);
      s.read_number("K", hardening.swift_k, greater_than(0.0, "MPa"), Presence::required);
      s.read_number("eps0", hardening.swift_eps0, greater_than(0.0), Presence::required);
      s.read_number("n", hardening.swift_n, interval(0.0, false, 1.0, true), Presence::required);
      s.read_number("sigma0", hardening.voce_sigma0, greater_than(0.0, "MPa"), Presence::required);
      s.read_number("Q", hardening.voce_q, at_least(0.0, "MPa"), Presence::required);
      s.read_number("b", hardening.voce_b, greater_than(0.0), Presence::required);
      return;
    case Law::tabulated:
      s.check_keys({"law", "file"});
      hardening.table_file = read_existing_file(
          s, "file", folder, [](const fs::path& p) { return p.extension() == ".csv"; }, ".csv");
      return;
  }
}

/// The optional forming limit curve: an array of at least 2 [minor, major] true-strain points,
/// finite, minor strictly increasing, major > 0. Only read back and written out (the solver does
/// not use it; scripts/plot_forming_limit.py does).
void read_forming_limit_curve(const TomlSection& s,
                              std::vector<std::array<double, 2>>& forming_limit_curve) {
  constexpr std::string_view key = "forming_limit_curve";
  const toml::node* node = s.find(key);
  if (!node) {
    return;
  }
  const auto* points = node->as_array();
  if (!points || points->size() < 2) {
    s.fail_value(key, "an array of at least 2 [minor, major] true-strain points");
  }
  const std::string path = s.key_path(key);
  std::vector<std::array<double, 2>> curve;
  for (std::size_t i = 0; i < points->size(); ++i) {
    const toml::node& point_node = *points->get(i);
    const std::string point_path = fmt::format("{}[{}]", path, i);
    const auto* point = point_node.as_array();
    std::optional<double> minor, major;
    if (point && point->size() == 2) {
      minor = number_of(*point->get(0));
      major = number_of(*point->get(1));
    }
    if (!minor || !major || !std::isfinite(*minor) || !std::isfinite(*major)) {
      s.fail_at(point_node, point_path,
                fmt::format("expected a point [minor, major] of 2 finite numbers (true strains), "
                            "got {}",
                            describe_value(point_node)));
    }
    if (!(*major > 0.0)) {
      s.fail_at(point_node, point_path,
                fmt::format("expected a major strain > 0, got {}", format_toml_number(*major)));
    }
    if (!curve.empty() && !(*minor > curve.back()[0])) {
      s.fail_at(point_node, point_path,
                fmt::format("expected minor strains strictly increasing, got {} after {}",
                            format_toml_number(*minor), format_toml_number(curve.back()[0])));
    }
    curve.push_back({*minor, *major});
  }
  forming_limit_curve = std::move(curve);
}

void read_kinematic(const TomlSection& s, KinematicConfig& kinematic) {
  s.check_keys({"C", "gamma"});
  s.read_numbers("C", kinematic.C, at_least(0.0, "MPa"), 1, 4, Presence::required);
  s.read_numbers("gamma", kinematic.gamma, at_least(0.0), 1, 4, Presence::required);
  if (kinematic.gamma.size() != kinematic.C.size()) {
    s.fail_value("gamma", fmt::format("one gamma per back stress: an array of {} numbers (as C)",
                                      kinematic.C.size()));
  }
}

void read_cowper_symonds(const TomlSection& s, CowperSymondsConfig& rate) {
  s.check_keys({"D", "q"});
  s.read_number("D", rate.D, greater_than(0.0, "1/s"), Presence::required);
  s.read_number("q", rate.q, greater_than(0.0), Presence::required);
}

// The anisotropy keys of each type: r-values (hill48, yld89, yld2000's fit), Barlat's exponent,
// Yld2000-2d's coefficients or the data they are fitted to.
void read_anisotropy(const TomlSection& s, MaterialConfig& material) {
  using Type = MaterialConfig::Type;
  const auto forbid = [&](std::initializer_list<const char*> keys, std::string_view why) {
    for (const auto* key : keys) {
      if (s.has(key)) {
        s.fail_forbidden(key, why);
      }
    }
  };
  const auto r_values = [&](Presence presence) {
    s.read_number("r0", material.r0, greater_than(0.0), presence);
    s.read_number("r45", material.r45, greater_than(0.0), presence);
    s.read_number("r90", material.r90, greater_than(0.0), presence);
  };
  const bool barlat = material.type == Type::yld2000 || material.type == Type::yld89;
  if (barlat) {
    s.read_number("exponent", material.exponent, at_least(2.0), Presence::optional);
  } else {
    forbid({"exponent"}, "the exponent is for type = \"yld2000\" or \"yld89\"");
  }
  if (material.type == Type::hill48 || material.type == Type::yld89) {
    r_values(Presence::required);
  }
  if (material.type != Type::yld2000) {
    forbid({"alpha", "sigma0", "sigma45", "sigma90", "sigma_b", "r_b"},
           "Yld2000-2d coefficients and data are for type = \"yld2000\"");
    if (material.type != Type::hill48 && material.type != Type::yld89) {
      forbid({"r0", "r45", "r90"},
             "Lankford coefficients are for type = \"hill48\", \"yld89\" or \"yld2000\"");
    }
    return;
  }
  if (s.read_numbers("alpha", material.alpha, NumberRange{}, 8, 8)) {
    forbid({"sigma0", "sigma45", "sigma90", "sigma_b", "r0", "r45", "r90", "r_b"},
           "alpha is given: Yld2000-2d is not fitted (give either alpha or the eight data)");
    return;
  }
  const NumberRange stress = greater_than(0.0, "MPa, or ratios");
  s.read_number("sigma0", material.sigma0, stress, Presence::required);
  s.read_number("sigma45", material.sigma45, stress, Presence::required);
  s.read_number("sigma90", material.sigma90, stress, Presence::required);
  s.read_number("sigma_b", material.sigma_b, stress, Presence::required);
  r_values(Presence::required);
  s.read_number("r_b", material.r_b, greater_than(0.0), Presence::required);
}

void read_material(const TomlSection& s, const fs::path& folder, MaterialConfig& material) {
  using Type = MaterialConfig::Type;
  s.check_keys({"type", "density", "young", "poisson", "hardening", "kinematic", "cowper_symonds",
                "r0", "r45", "r90", "exponent", "alpha", "sigma0", "sigma45", "sigma90", "sigma_b",
                "r_b", "forming_limit_curve"});
  s.read_choice("type", material.type,
                {{"von_mises", Type::von_mises},
                 {"elastic", Type::elastic},
                 {"hill48", Type::hill48},
                 {"yld2000", Type::yld2000},
                 {"yld89", Type::yld89}});
  s.read_number("density", material.density, greater_than(0.0, "tonne/mm^3"), Presence::required);
  s.read_number("young", material.young, greater_than(0.0, "MPa"), Presence::required);
  s.read_number("poisson", material.poisson, interval(-1.0, true, 0.5, true), Presence::required);
  read_forming_limit_curve(s, material.forming_limit_curve);
  read_anisotropy(s, material);
  if (material.type == Type::elastic) {
    for (const auto* key : {"hardening", "kinematic", "cowper_symonds"}) {
      if (s.has(key)) {
        s.fail_forbidden(key,
                         "an elastic material has no hardening (remove the table or set type = "
                         "\"von_mises\", \"hill48\", \"yld2000\" or \"yld89\")");
      }
    }
    return;
  }
  read_hardening(*s.sub_table("hardening", Presence::required), folder, material.hardening);
  if (const auto kinematic = s.sub_table("kinematic", Presence::optional)) {
    read_kinematic(*kinematic, material.kinematic);
  }
  if (const auto rate = s.sub_table("cowper_symonds", Presence::optional)) {
    read_cowper_symonds(*rate, material.cowper_symonds);
  }
}

void read_materials(const TomlSection& top, const fs::path& folder,
                    std::vector<MaterialConfig>& materials) {
  const TomlSection all = *top.sub_table("materials", Presence::required);
  for (const auto& [key, node] : all.table()) {
    const std::string name(key.str());
    const std::string path = fmt::format("materials.{}", name);
    const auto* table = node.as_table();
    if (!table) {
      all.fail_at(node, path,
                  fmt::format("expected a table [{}], got {}", path, describe_value(node)));
    }
    MaterialConfig material;
    material.name = name;
    read_material(TomlSection(*table, path, all.file()), folder, material);
    materials.push_back(std::move(material));
  }
  if (materials.empty()) {
    all.fail_at(all.table(), "materials", "expected at least one [materials.NAME] table, got none");
  }
}

void read_blank(const TomlSection& top, const fs::path& folder, const CaseConfig& config,
                BlankConfig& blank) {
  const TomlSection s = *top.sub_table("blank", Presence::required);
  using Rule = BlankConfig::IntegrationRule;
  using Form = BlankConfig::HourglassForm;
  using Formulation = BlankConfig::Formulation;
  s.check_keys({"mesh", "group", "element_size", "parameters", "scale", "curvature_elements",
                "surfaces", "element", "thickness", "integration_points", "integration_rule",
                "material", "formulation", "hourglass", "hourglass_form", "rolling_direction"});
  read_mesh_source(s, folder, blank.mesh);
  s.read_choice<std::string>("element", blank.element,
                             {{"quad", "quad"}, {"as_meshed", "as_meshed"}});
  s.read_number("thickness", blank.thickness, greater_than(0.0, "mm"), Presence::required);
  s.read_choice("integration_rule", blank.integration_rule,
                {{"gauss", Rule::gauss}, {"lobatto", Rule::lobatto}});
  if (blank.integration_rule == Rule::lobatto) {
    s.read_integer("integration_points", blank.integration_points,
                   IntegerRange{.lo = 2, .hi = 9, .unit = "with integration_rule = \"lobatto\""});
  } else {
    s.read_integer("integration_points", blank.integration_points, IntegerRange{.lo = 1, .hi = 9});
  }
  s.read_string("material", blank.material, Presence::required);
  s.read_choice("formulation", blank.formulation,
                {{"belytschko_tsay", Formulation::belytschko_tsay},
                 {"assumed_strain", Formulation::assumed_strain}});
  if (blank.formulation == Formulation::assumed_strain) {
    for (const char* key : {"hourglass", "hourglass_form"}) {
      if (s.find(key)) {
        s.fail_at(*s.find(key), s.key_path(key),
                  "applies to formulation = \"belytschko_tsay\" only: the assumed-strain "
                  "formulation (the default) has a physical stabilisation with no coefficient; "
                  "set formulation = \"belytschko_tsay\" to use the hourglass keys");
      }
    }
  }
  s.read_number("hourglass", blank.hourglass_coefficient, interval(0.0, false, 0.5, false));
  s.read_choice("hourglass_form", blank.hourglass_form,
                {{"viscous", Form::viscous}, {"stiffness", Form::stiffness}});
  s.read_direction("rolling_direction", blank.rolling_direction);

  bool found = false;
  std::string names;
  for (const auto& material : config.materials) {
    found = found || material.name == blank.material;
    names += fmt::format("{}{}", names.empty() ? "" : ", ", quote_toml_string(material.name));
  }
  if (!found) {
    s.fail_value("material", fmt::format("the name of a [materials.NAME] table ({})", names));
  }
}

void read_motion(const TomlSection& s, MotionConfig& motion) {
  using Type = MotionConfig::Type;
  s.check_keys({"type", "direction", "curve", "mass", "damping"});
  s.read_choice("type", motion.type,
                {{"velocity", Type::velocity},
                 {"displacement", Type::displacement},
                 {"fixed", Type::fixed},
                 {"force", Type::force}},
                Presence::required);
  if (motion.type == Type::fixed) {
    for (const auto key : {"direction", "curve", "mass", "damping"}) {
      if (s.has(key)) {
        s.fail_forbidden(key, "a fixed tool does not move");
      }
    }
    return;
  }
  s.read_direction("direction", motion.direction);
  read_curve(s, "curve", motion.curve);
  if (motion.type != Type::force) {
    for (const auto key : {"mass", "damping"}) {
      if (s.has(key)) {
        s.fail_forbidden(key,
                         "a tool with a prescribed motion has no mass or damping of its own "
                         "(they are for type = \"force\")");
      }
    }
    return;
  }
  // A force-controlled tool: the curve is the force (N) along the direction; any sign (a negative
  // force pulls the tool back, e.g. a holder lifting).
  double mass = 0.0;
  if (s.read_number("mass", mass, greater_than(0.0, "tonne"))) {
    motion.mass = mass;
  }
  s.read_number("damping", motion.damping, at_least(0.0, "1/s"));
}

void read_tools(const TomlSection& top, const fs::path& folder, std::vector<ToolConfig>& tools) {
  const std::vector<TomlSection> sections = top.table_array("tools");
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const TomlSection& s = sections[i];
    s.check_keys({"name", "mesh", "group", "element_size", "parameters", "scale",
                  "curvature_elements", "surfaces", "motion"});
    ToolConfig tool;
    s.read_name("name", tool.name, Presence::required);
    for (std::size_t j = 0; j < i; ++j) {
      if (tools[j].name == tool.name) {
        s.fail_at(*s.find("name"), s.key_path("name"),
                  fmt::format("duplicate tool name {} (already used by tools[{}])",
                              quote_toml_string(tool.name), j));
      }
    }
    tool.mesh.group = tool.name;  // the default group is the tool's name
    read_mesh_source(s, folder, tool.mesh);
    if (const auto motion = s.sub_table("motion", Presence::optional)) {
      read_motion(*motion, tool.motion);
    }
    tools.push_back(std::move(tool));
  }
}

std::string tool_names(const CaseConfig& config) {
  std::string names;
  for (const auto& tool : config.tools) {
    names += fmt::format("{}{}", names.empty() ? "" : ", ", quote_toml_string(tool.name));
  }
  return names.empty() ? "none defined" : names;
}

/// Coulomb friction: `friction` alone sets one coefficient for rest and sliding; or
/// friction_static with an optional friction_dynamic (default: the static one) and decay.
void read_friction(const TomlSection& s, ContactConfig& contact) {
  if (s.has("friction")) {
    for (const char* key : {"friction_static", "friction_dynamic", "friction_decay"}) {
      if (s.has(key)) {
        s.fail_forbidden(key,
                         "friction sets one coefficient for rest and sliding; give either friction "
                         "or friction_static (with friction_dynamic, friction_decay)");
      }
    }
    s.read_number("friction", contact.friction_static, at_least(0.0));
    contact.friction_dynamic = contact.friction_static;
    return;
  }
  s.read_number("friction_static", contact.friction_static, at_least(0.0));
  contact.friction_dynamic = contact.friction_static;
  s.read_number("friction_dynamic", contact.friction_dynamic,
                NumberRange{.lo = 0.0, .hi = contact.friction_static});
  s.read_number("friction_decay", contact.friction_decay, at_least(0.0));
}

void read_contacts(const TomlSection& top, const CaseConfig& config,
                   std::vector<ContactConfig>& contacts) {
  const std::vector<TomlSection> sections = top.table_array("contact");
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const TomlSection& s = sections[i];
    s.check_keys({"tool", "search", "projection", "penalty_scale", "penalty_stiffness", "friction",
                  "friction_static", "friction_dynamic", "friction_decay", "audit",
                  "search_margin"});
    ContactConfig contact;
    s.read_string("tool", contact.tool, Presence::required);
    if (!config.find_tool(contact.tool)) {
      s.fail_value("tool", fmt::format("the name of a [[tools]] entry ({})", tool_names(config)));
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (contacts[j].tool == contact.tool) {
        s.fail_at(*s.find("tool"), s.key_path("tool"),
                  fmt::format("a second [[contact]] for tool {} (the first is contact[{}])",
                              quote_toml_string(contact.tool), j));
      }
    }
    s.read_choice<std::string>("search", contact.search,
                               {{"standard", "standard"},
                                {"modified", "modified"},
                                {"cached", "cached"},
                                {"standard_brute_force", "standard_brute_force"},
                                {"modified_brute_force", "modified_brute_force"}});
    s.read_choice("projection", contact.projection,
                  {{"interpolated", ContactConfig::Projection::interpolated},
                   {"orthogonal", ContactConfig::Projection::orthogonal}});
    if (s.has("penalty_scale") && s.has("penalty_stiffness")) {
      s.fail_forbidden(
          "penalty_stiffness",
          "give either penalty_scale (relative) or penalty_stiffness (N/mm), not both");
    }
    s.read_number("penalty_scale", contact.penalty_scale, greater_than(0.0));
    s.read_number("penalty_stiffness", contact.penalty_stiffness, greater_than(0.0));
    read_friction(s, contact);
    s.read_bool("audit", contact.audit);
    if (s.has("search_margin") && contact.search != "cached") {
      s.fail_forbidden("search_margin", "search_margin is the margin of search = \"cached\"");
    }
    s.read_number("search_margin", contact.search_margin, at_least(0.0));
    contacts.push_back(std::move(contact));
  }
}

void read_draw_ins(const TomlSection& top, std::vector<DrawInConfig>& draw_ins) {
  for (const TomlSection& s : top.table_array("draw_in")) {
    s.check_keys({"name", "group", "direction", "measured", "measured_stroke", "source"});
    DrawInConfig draw_in;
    s.read_name("name", draw_in.name, Presence::required);
    for (const auto& other : draw_ins) {
      if (other.name == draw_in.name) {
        s.fail_value("name", "a name not used by another [[draw_in]]");
      }
    }
    s.read_string("group", draw_in.group, Presence::required);
    s.read_direction("direction", draw_in.direction);
    s.read_number("measured", draw_in.measured, at_least(0.0, "mm"));
    s.read_number("measured_stroke", draw_in.measured_stroke, at_least(0.0, "mm"));
    if (s.has("measured_stroke") && !s.has("measured")) {
      s.fail_forbidden("measured_stroke",
                       "it is the stroke of the `measured` value, which is absent");
    }
    s.read_string("source", draw_in.source, Presence::optional, true);
    draw_ins.push_back(std::move(draw_in));
  }
}

void read_loads(const TomlSection& top, std::vector<LoadConfig>& loads) {
  using Type = LoadConfig::Type;
  for (const TomlSection& s : top.table_array("load")) {
    s.check_keys({"group", "type", "value", "pressure", "curve"});
    LoadConfig load;
    s.read_string("group", load.group, Presence::required);
    s.read_choice("type", load.type,
                  {{"force", Type::force}, {"moment", Type::moment}, {"pressure", Type::pressure}},
                  Presence::required);
    if (load.type == Type::pressure) {
      if (s.has("value")) {
        s.fail_forbidden("value", "a pressure load takes `pressure` (MPa)");
      }
      s.read_number("pressure", load.pressure, NumberRange{}, Presence::required);
    } else {
      if (s.has("pressure")) {
        s.fail_forbidden("pressure", "a force or moment load takes `value` (3 numbers per node)");
      }
      if (!s.has("value")) {
        s.fail_missing("value", "an array of 3 numbers (N or N mm per node)");
      }
      read_vector(s, "value", load.value);
    }
    if (s.has("curve")) {
      read_curve(s, "curve", load.curve);
    }
    loads.push_back(std::move(load));
  }
}

// An array of 3 components, each a finite number or a string holding an expression of x, y, z
// (core/expression.hpp); absent: left as it is.
void read_field_vector(const TomlSection& s, std::string_view key,
                       std::array<Expression, 3>& value) {
  const toml::node* node = s.find(key);
  if (!node) {
    return;
  }
  const toml::array* array = node->as_array();
  if (!array || array->size() != 3) {
    s.fail_value(key, "an array of 3 numbers or expressions of x, y, z in quotes");
  }
  for (std::size_t i = 0; i < 3; ++i) {
    const toml::node& component = *array->get(i);
    if (const std::optional<double> v = number_of(component)) {
      if (!std::isfinite(*v)) {
        s.fail_value(key, "finite numbers");
      }
      value[i] = Expression::constant(*v);
    } else if (const auto* text = component.as_string()) {
      try {
        value[i] = Expression::parse(text->get());
      } catch (const InputError& e) {
        s.fail_at(component, s.key_path(key), e.what());
      }
    } else {
      s.fail_value(key, "an array of 3 numbers or expressions of x, y, z in quotes");
    }
  }
}

void read_initial_velocities(const TomlSection& top, std::vector<InitialVelocityConfig>& out) {
  for (const TomlSection& s : top.table_array("initial_velocity")) {
    s.check_keys({"group", "velocity", "angular_velocity"});
    InitialVelocityConfig iv;
    s.read_string("group", iv.group);
    if (!s.has("velocity") && !s.has("angular_velocity")) {
      s.fail_missing("velocity",
                     "an array of 3 numbers (mm/s), or angular_velocity (rad/s), or both");
    }
    read_field_vector(s, "velocity", iv.velocity);
    read_field_vector(s, "angular_velocity", iv.angular_velocity);
    out.push_back(std::move(iv));
  }
}

void read_control(const TomlSection& top, const CaseConfig& config, ControlConfig& control) {
  const TomlSection s = *top.sub_table("control", Presence::required);
  s.check_keys({"end_time", "stroke", "stroke_tool", "output_frames", "history_interval",
                "progress_interval", "time_step_safety", "mass_scaling_dt",
                "mass_scaling_max_added", "energy_blowup_ratio", "checkpoint_cycles",
                "checkpoint_minutes", "gravity", "damping"});
  read_vector(s, "gravity", control.gravity);
  s.read_number("damping", control.damping, at_least(0.0, "1/s"));
  s.read_number("end_time", control.end_time, at_least(0.0, "s"));
  s.read_number("stroke", control.stroke, at_least(0.0, "mm"));
  if (control.end_time > 0.0 && control.stroke > 0.0) {
    s.fail_at(*s.find("stroke"), s.key_path("stroke"),
              fmt::format("expected exactly one of end_time and stroke > 0, got end_time = {} "
                          "and stroke = {}",
                          control.end_time, control.stroke));
  }
  if (!(control.end_time > 0.0) && !(control.stroke > 0.0)) {
    s.fail_at(s.table(), "control.end_time/control.stroke",
              "expected exactly one of end_time (s) and stroke (mm) > 0, got neither");
  }
  s.read_integer("output_frames", control.output_frames, IntegerRange{.lo = 1});
  s.read_integer("history_interval", control.history_interval, IntegerRange{.lo = 1});
  s.read_integer("progress_interval", control.progress_interval, IntegerRange{.lo = 0});
  s.read_number("time_step_safety", control.time_step_safety, interval(0.0, true, 1.0, false));
  s.read_number("mass_scaling_dt", control.mass_scaling_dt, at_least(0.0, "s"));
  s.read_number("mass_scaling_max_added", control.mass_scaling_max_added, at_least(0.0));
  s.read_number("energy_blowup_ratio", control.energy_blowup_ratio, greater_than(1.0));
  s.read_integer("checkpoint_cycles", control.checkpoint_cycles, IntegerRange{.lo = 0});
  s.read_number("checkpoint_minutes", control.checkpoint_minutes, at_least(0.0, "min"));

  if (s.read_string("stroke_tool", control.stroke_tool)) {
    const ToolConfig* tool = config.find_tool(control.stroke_tool);
    if (!tool) {
      s.fail_value("stroke_tool",
                   fmt::format("the name of a [[tools]] entry ({})", tool_names(config)));
    }
    if (tool->motion.type == MotionConfig::Type::force) {
      s.fail_at(*s.find("stroke_tool"), s.key_path("stroke_tool"),
                fmt::format("tool {} is force-controlled (type = \"force\": its travel follows "
                            "from the force), so it cannot define the stroke; expected a tool "
                            "with a prescribed motion (type = \"velocity\" or \"displacement\")",
                            quote_toml_string(tool->name)));
    }
    if (control.stroke > 0.0 && tool->motion.type == MotionConfig::Type::fixed) {
      s.fail_value("stroke_tool", "the name of a tool whose motion is not fixed (stroke > 0)");
    }
    return;
  }
  for (const auto& tool : config.tools) {
    if (tool.motion.type == MotionConfig::Type::velocity ||
        tool.motion.type == MotionConfig::Type::displacement) {
      control.stroke_tool = tool.name;
      return;
    }
  }
  if (control.stroke > 0.0) {
    s.fail_at(*s.find("stroke"), s.key_path("stroke"),
              "stroke > 0 needs a moving tool, but no [[tools]] entry has a prescribed motion "
              "(type = \"velocity\" or \"displacement\")");
  }
}

void read_output(const TomlSection& top, const fs::path& folder, OutputConfig& output) {
  if (const auto s = top.sub_table("output", Presence::optional)) {
    s->check_keys({"directory", "stress_layers"});
    s->read_string("directory", output.directory);
    s->read_bool("stress_layers", output.stress_layers);
  }
  const fs::path directory(output.directory);
  if (directory.is_relative()) {
    output.directory = (folder / directory).lexically_normal().string();
  }
}

void read_limits(const TomlSection& top, LimitsConfig& limits) {
  const auto s = top.sub_table("limits", Presence::optional);
  if (!s) {
    return;
  }
  s->check_keys({"max_cycles", "max_elements", "max_frames", "max_output_gb", "max_memory_gb",
                 "mesh_seconds", "max_initial_penetration"});
  s->read_number("max_cycles", limits.max_cycles, greater_than(0.0, "cycles"));
  s->read_number("max_elements", limits.max_elements, greater_than(0.0, "elements"));
  s->read_integer("max_frames", limits.max_frames, IntegerRange{.lo = 1});
  s->read_number("max_output_gb", limits.max_output_gb, greater_than(0.0, "GB"));
  s->read_number("max_memory_gb", limits.max_memory_gb, at_least(0.0, "GB"));
  s->read_number("mesh_seconds", limits.mesh_seconds, greater_than(0.0, "s"));
  s->read_number("max_initial_penetration", limits.max_initial_penetration, at_least(0.0));
}

/// `units`: a consistent LENGTH-TIME-MASS-FORCE-STRESS system (parse_unit_system).
void read_units(const TomlSection& top, std::string& units) {
  if (!top.read_string("units", units)) {
    return;
  }
  try {
    parse_unit_system(units);
  } catch (const std::invalid_argument& error) {
    top.fail_at(*top.find("units"), "units",
                fmt::format("{}; got {}", error.what(), quote_toml_string(units)));
  }
}

std::string read_text_file(const fs::path& file) {
  std::error_code error;
  if (!fs::exists(file, error)) {
    throw InputError(fmt::format("{}: case file not found", file.string()));
  }
  if (!fs::is_regular_file(file, error)) {
    throw InputError(fmt::format("{}: case file is not a regular file", file.string()));
  }
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) {
    throw InputError(fmt::format("{}: cannot read the case file", file.string()));
  }
  return text.str();
}

toml::table parse_toml(const std::string& text, const std::string& file) {
  try {
    return toml::parse(std::string_view(text), std::string_view(file));
  } catch (const toml::parse_error& error) {
    throw InputError(fmt::format("{}: TOML syntax error: {}", format_location(file, error.source()),
                                 error.description()));
  }
}

}  // namespace

const MaterialConfig& CaseConfig::blank_material() const {
  for (const auto& material : materials) {
    if (material.name == blank.material) {
      return material;
    }
  }
  throw InputError(
      fmt::format("{}: blank.material: no material named \"{}\"", file.string(), blank.material));
}

const ToolConfig* CaseConfig::find_tool(const std::string& name) const {
  for (const auto& tool : tools) {
    if (tool.name == name) {
      return &tool;
    }
  }
  return nullptr;
}

CaseConfig read_case(const fs::path& case_file, const std::vector<std::string>& overrides) {
  CaseConfig config;
  config.file = fs::absolute(case_file).lexically_normal();
  const std::string file = config.file.string();
  toml::table root = parse_toml(read_text_file(config.file), file);
  apply_case_overrides(root, overrides);
  const fs::path folder = config.file.parent_path();

  const TomlSection top(root, "", file);
  top.check_keys({"title", "units", "blank", "materials", "tools", "contact", "boundary", "draw_in",
                  "load", "initial_velocity", "prescribed_velocity", "prescribed_motion", "control",
                  "output", "analysis", "implicit", "springback", "history", "limits"});
  top.read_string("title", config.title, Presence::optional, true);
  read_units(top, config.units);
  read_materials(top, folder, config.materials);
  read_blank(top, folder, config, config.blank);
  read_tools(top, folder, config.tools);
  read_contacts(top, config, config.contacts);
  read_draw_ins(top, config.draw_ins);
  read_loads(top, config.loads);
  read_initial_velocities(top, config.initial_velocities);
  read_constraint_sections(top, config);
  read_control(top, config, config.control);
  read_limits(top, config.limits);
  read_output(top, folder, config.output);
  read_implicit_sections(top, config);
  check_constraints_for_analysis(top, config);
  read_history_groups(top, config);
  return config;
}

}  // namespace sf
