// The field tables of the parts: a mesh source, [blank], [[tools]], [tools.motion], [[contact]].
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "casefile/case_config_common.hpp"
#include "casefile/case_fields.hpp"
#include "meshing/mesh_import.hpp"

namespace sf {

namespace fs = std::filesystem;

namespace {

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
void read_geo_parameters(const TomlSection& s, std::vector<GeoParameter>& parameters) {
  const toml::node* node = s.find("parameters");
  if (!node) {
    return;
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

void write_geo_parameters(TomlWriter& w, const std::vector<GeoParameter>& parameters) {
  std::string table;
  for (const GeoParameter& p : parameters) {
    table +=
        fmt::format("{}{} = {}", table.empty() ? "" : ", ", p.name, format_toml_number(p.value));
  }
  w.raw("parameters", "{ " + table + " }");
}

FieldTable<MeshSourceConfig> make_mesh_source_fields() {
  using M = MeshSourceConfig;
  const auto format = [](const M& m) { return mesh_format(m.file); };
  FieldTable<M> t;
  t.push_back(custom_field<M>(
                  {"mesh",
                   "string",
                   "required",
                   {},
                   "a `.geo` (meshed by gmsh), `.msh`, CAD (`.step`, `.stp`, `.iges`, `.igs`, "
                   "`.brep`: meshed by gmsh), `.stl`, Nastran (`.bdf`, `.nas`), `.unv` or `.vtk` "
                   "file, relative to the case file's folder (stored absolute); must exist "
                   "(below: \"Mesh sources\")"},
                  [](const TomlSection& s, M& m, Presence) {
                    m.file = read_existing_file(
                        s, "mesh",
                        [](const fs::path& p) { return find_mesh_format(p).has_value(); },
                        fmt::format("a {} file", accepted_mesh_extensions()));
                  },
                  [](TomlWriter& w, const M& m) { w.string("mesh", m.file.string()); })
                  .required());
  t.push_back(string_field<M>("group", &M::group,
                              "physical group name of the part's surface; for a file without "
                              "part names (CAD, STL, Nastran, VTK), the name its surfaces are "
                              "given"));
  Field<M> size = number_field<M>("element_size", &M::element_size, at_least(0.0, "mm"),
                                  "0 = the `.geo` file's own sizes (ignored for `.msh` and other "
                                  "codes' meshes); required > 0 for CAD");
  size.read = [](const TomlSection& s, M& m, Presence) {
    s.read_number("element_size", m.element_size, at_least(0.0, "mm"));
    if (is_cad(mesh_format(m.file)) && !(m.element_size > 0.0)) {
      s.fail_missing("element_size", "an element size > 0 (mm): a CAD file has no mesh sizes");
    }
  };
  t.push_back(std::move(size));
  t.push_back(
      custom_field<M>(
          {"parameters", "table of numbers", "none", "the `.geo`'s",
           "numbers set in the `.geo` before gmsh parses it, e.g. `{ n = 16 "
           "}` (below: \"`.geo` parameters\")"},
          [](const TomlSection& s, M& m, Presence) { read_geo_parameters(s, m.parameters); },
          [](TomlWriter& w, const M& m) { write_geo_parameters(w, m.parameters); })
          .when([format](const M& m) { return format(m) == MeshFormat::geo; }, "`.geo` only",
                "parameters are set in a .geo file before gmsh parses it; a .msh mesh "
                "is read as it is")
          .write_if([](const M& m) { return !m.parameters.empty(); }));
  t.push_back(number_field<M>("scale", &M::scale, greater_than(0.0),
                              "the file's lengths are multiplied by it (after a STEP file's own "
                              "unit is converted to mm)")
                  .when([format](const M& m) { return format(m) != MeshFormat::geo; },
                        "every format but `.geo`",
                        "a .geo script sets its own lengths; scale is for the other formats")
                  .write_if([](const M& m) { return m.scale != 1.0; }));
  t.push_back(
      integer_field<M>("curvature_elements", &M::curvature_elements,
                       IntegerRange{.lo = 0, .hi = 1000, .unit = "elements per 2 pi of curvature"},
                       "curved faces refined to at most 2πR/N on a radius R (gmsh's "
                       "`Mesh.MeshSizeFromCurvature`); 0 = off")
          .when([format](const M& m) { return is_cad(format(m)); }, "CAD only",
                "curvature refinement is for a CAD mesh source")
          .write_if([](const M& m) { return m.curvature_elements > 0; }));
  t.push_back(
      number_field<M>("chord_error", &M::chord_error, at_least(0.0, "mm"),
                      "curved faces and edges refined so that no element stands off the CAD "
                      "surface by more than this (on a radius R, elements at most "
                      "2√(e(2R − e)) long); 0 = off")
          .when([format](const M& m) { return is_cad(format(m)); }, "CAD only",
                "chord error refinement is for a CAD mesh source")
          .write_if([](const M& m) { return m.chord_error > 0.0; }));
  t.push_back(
      custom_field<M>(
          {"surfaces",
           "array of integers",
           "all",
           {},
           "the file's surface tags (Nastran property ids) that form the part (open "
           "the file in the gmsh GUI to see its surface tags)"},
          [](const TomlSection& s, M& m, Presence p) {
            read_entity_tags(s, "surfaces", "surface", m.surfaces, p);
          },
          [](TomlWriter& w, const M& m) {
            w.numbers("surfaces", std::vector<double>(m.surfaces.begin(), m.surfaces.end()),
                      "the file's surface tags that form the part");
          })
          .when([format](const M& m) { return is_imported(format(m)); },
                "CAD, `.stl`, `.bdf`/`.nas`, `.unv`, `.vtk` only",
                "a surface list is for a CAD, STL, Nastran, UNV or VTK file; a .geo or .msh "
                "names its parts by physical groups")
          .write_if([](const M& m) { return !m.surfaces.empty(); }));
  return t;
}

FieldTable<BlankConfig> make_blank_fields() {
  using B = BlankConfig;
  FieldTable<B> t = embed_fields<B>(mesh_source_fields(), &B::mesh);
  // Without `mesh`, a case starting from a formed part takes the part's own mesh and node
  // groups (a trimmed part's); the other mesh keys then have nothing to say.
  for (Field<B>& f : t) {
    if (f.doc.key == "mesh") {
      f.presence = Presence::optional;
      f.doc.default_text = "required; none with `formed_part`: the part's mesh";
      f.read = [read = f.read](const TomlSection& s, B& b, Presence) {
        if (s.has("mesh") || !s.has("formed_part")) {
          read(s, b, Presence::required);
        }
      };
      continue;
    }
    f = std::move(f).when(
        [applies = f.applies](const B& b) {
          return !b.mesh.file.empty() && (!applies || applies(b));
        },
        "",
        [why = f.not_applicable](const B& b) {
          return b.mesh.file.empty() || !why
                     ? std::string("the blank has no `mesh`: it is the formed part's own")
                     : why(b);
        });
  }
  const auto belytschko_tsay = [](const B& b) {
    return b.formulation == ShellFormulation::belytschko_tsay;
  };
  const std::string bt_only =
      "applies to formulation = \"belytschko_tsay\" only: the assumed-strain formulation (the "
      "default) has a physical stabilisation with no coefficient; set formulation = "
      "\"belytschko_tsay\" to use the hourglass keys";
  t.push_back(choice_field<B, BlankMeshing>(
      "element", &B::element, kBlankMeshingNames,
      "how a `.geo` or CAD blank is meshed. Quadrilaterals become shells of the `formulation` "
      "below and triangles C0 (DSG3) shell triangles either way, so a blank may hold quads, "
      "triangles or both; a `.msh` is read as it is"));
  const auto one_part = [](const B& b) { return b.parts.empty(); };
  const std::string parts_own =
      "a blank of several parts (`[[blank.parts]]`) gives each part's thickness and material in "
      "its own table";
  t.push_back(number_field<B>("thickness", &B::thickness, greater_than(0.0, "mm"))
                  .required()
                  .when(one_part, "without `[[blank.parts]]`", parts_own));
  t.push_back(choice_field<B, ThroughThicknessRule>(
      "integration_rule", &B::integration_rule, kThroughThicknessRuleNames,
      "elastic bending is integrated exactly with Gauss n >= 2, Lobatto n >= 3"));
  t.push_back(integer_field<B>(
      "integration_points", &B::integration_points,
      [](const B& b) {
        return b.integration_rule == ThroughThicknessRule::lobatto
                   ? IntegerRange{.lo = 2, .hi = 9, .unit = "with integration_rule = \"lobatto\""}
                   : IntegerRange{.lo = 1, .hi = 9};
      },
      "1 … 9 (Gauss), 2 … 9 (Lobatto)", "points through the thickness"));
  t.push_back(string_field<B>("material", &B::material, "the name of a `[materials.NAME]` table")
                  .required()
                  .when(one_part, "without `[[blank.parts]]`", parts_own));
  t.push_back(choice_field<B, ShellFormulation>(
      "formulation", &B::formulation, kShellFormulationNames,
      "the quadrilaterals' formulation (docs/element-and-material.md)"));
  t.push_back(number_field<B>("hourglass", &B::hourglass_coefficient,
                              interval(0.0, false, 0.5, false),
                              "hourglass coefficient κ (Flanagan–Belytschko) of the form below")
                  .when(belytschko_tsay, "`belytschko_tsay` only", bt_only));
  t.push_back(choice_field<B, HourglassForm>("hourglass_form", &B::hourglass_form,
                                             kHourglassFormNames, "docs/element-and-material.md")
                  .when(belytschko_tsay, "`belytschko_tsay` only", bt_only));
  t.push_back(direction_field<B>(
      "rolling_direction", &B::rolling_direction,
      "global axes. Used by the anisotropic materials: projected on each element at the start "
      "to fix its material axes (docs/material.md). It must not be within about 5.7° of an "
      "element's normal (in-plane part of the unit vector >= 0.1): building the model stops "
      "with an error naming the element. Also the along direction of a contact's "
      "`friction_across_ratio`"));
  t.push_back(
      custom_field<B>(
          {"formed_part",
           "string",
           "none",
           {},
           "a formed part (`formed_part.h5` of another run's results folder), relative to the "
           "case file's folder: the run starts from its state (time, shape, thickness, stresses, "
           "plastic strains; tools of the same name where it left them). With `mesh`, the part's "
           "blank must be that mesh; without, the blank is the part's own mesh and node groups "
           "(a trimmed part's; docs/process-chain.md)"},
          [](const TomlSection& s, B& b, Presence) {
            if (!s.has("formed_part")) {
              return;
            }
            b.formed_part = read_existing_file(
                s, "formed_part", [](const fs::path& p) { return p.extension() == ".h5"; },
                "a formed part (.h5)");
          },
          [](TomlWriter& w, const B& b) { w.string("formed_part", b.formed_part.string()); })
          .write_if([](const B& b) { return !b.formed_part.empty(); }));
  return t;
}

FieldTable<BlankPartConfig> make_blank_part_fields() {
  using P = BlankPartConfig;
  FieldTable<P> t;
  t.push_back(name_field<P>("name", &P::name,
                            "unique among the parts; names the part in the banner, the summary "
                            "and the results' `part` field")
                  .required());
  Field<P> group = string_field<P>("group", &P::group,
                                   "a 2-D physical group of the blank's mesh: the part's elements. "
                                   "Every element of the blank is in exactly one part; the parts "
                                   "share the nodes of their weld lines. A blank that is a formed "
                                   "part's own mesh (`formed_part` without `mesh`) has none: its "
                                   "elements are in the formed part's part of this `name`");
  group.doc.default_text = "required with the blank's `mesh`";
  t.push_back(std::move(group));
  t.push_back(number_field<P>("thickness", &P::thickness, greater_than(0.0, "mm")).required());
  t.push_back(string_field<P>("material", &P::material, "the name of a `[materials.NAME]` table")
                  .required());
  return t;
}

FieldTable<ToolConfig> make_tool_fields() {
  using T = ToolConfig;
  FieldTable<T> t;
  t.push_back(name_field<T>("name", &T::name,
                            "unique among tools; letters, digits, `_`, `-`, `.`, not starting "
                            "with `.` (it names the tool's results and history columns)")
                  .required());
  for (Field<T>& f : embed_fields<T>(mesh_source_fields(), &T::mesh)) {
    if (f.doc.key == "group") {
      f.doc.default_text = "the tool's `name`";
    }
    t.push_back(std::move(f));
  }
  static constexpr std::array<Choice<T::Position>, 2> kPositions{{
      {T::Position::as_meshed, "as_meshed", "where its mesh puts it"},
      {T::Position::touch, "touch",
       "moved along its motion's `direction` until it touches the blank (its surface half the "
       "blank's thickness from the blank's mid-surface along that direction); a tool with a "
       "motion only; the distance is in the banner"},
  }};
  t.push_back(choice_field<T, T::Position>("position", &T::position, kPositions, ""));
  return t;
}

// A tool that turns (a flanging steel, a cam): its angle curve, axis and pivot.
void add_turn_fields(FieldTable<MotionConfig>& t) {
  using M = MotionConfig;
  const auto not_forced = [](const M& m) { return m.type != M::Type::force; };
  const auto turns = [](const M& m) { return m.turns(); };
  const std::string turn_only = "axis and pivot are for a tool that turns: give its `angle` curve";
  t.push_back(curve_field<M>("angle", &M::angle, "degrees",
                             "the tool turns by this angle about `axis` through `pivot` "
                             "(right-hand rule), piecewise linear, held after the last point; "
                             "with any `type` but `\"force\"` (a translation moves the pivot "
                             "with the tool)")
                  .when(not_forced, "not for `\"force\"`",
                        "a force-controlled tool moves along its direction only (no angle)"));
  t.push_back(direction_field<M>("axis", &M::axis,
                                 "the axis the tool turns about, in the mesh's coordinates")
                  .when(turns, "with `angle` only", turn_only));
  t.push_back(vector_field<M>("pivot", &M::pivot, "mm",
                              "a point of the axis, in the mesh's coordinates (the hinge "
                              "where the die drawing has it)")
                  .when(turns, "with `angle` only", turn_only));
}

FieldTable<MotionConfig> make_motion_fields() {
  using M = MotionConfig;
  using Type = MotionConfig::Type;
  static constexpr std::array<Choice<Type>, 4> kTypes{{
      {Type::velocity, "velocity", "the tool moves along `direction` at the curve's speed"},
      {Type::displacement, "displacement", "the tool's travel along `direction` is the curve"},
      {Type::fixed, "fixed", ""},
      {Type::force, "force", "force-controlled, below"},
  }};
  const auto moves = [](const M& m) { return m.type != Type::fixed; };
  const auto force = [](const M& m) { return m.type == Type::force; };
  const std::string force_only =
      "mass and damping are for type = \"force\" (a fixed tool does not move; a tool with a "
      "prescribed motion has no mass or damping of its own)";
  FieldTable<M> t;
  t.push_back(choice_field<M, Type>("type", &M::type, kTypes, "")
                  .required()
                  .shown_default("required when the table is present"));
  t.push_back(direction_field<M>("direction", &M::direction,
                                 "for `\"force\"` the direction the force pushes and the only "
                                 "one the tool moves along")
                  .when(moves, "not for `\"fixed\"`", "a fixed tool does not move"));
  t.push_back(curve_field<M>("curve", &M::curve, "mm/s (velocity), mm (displacement) or N (force)",
                             "piecewise linear, held constant after the last point; against the "
                             "time in s, or (`force_of = \"travel\"`) the travel in mm")
                  .required()
                  .when(moves, "not for `\"fixed\"`", "a fixed tool does not move"));
  static constexpr std::array<Choice<M::ForceOf>, 2> kForceOf{{
      {M::ForceOf::time, "time", "the curve is the force against the time (s)"},
      {M::ForceOf::travel, "travel",
       "the force against the tool's travel along `direction` (mm): a gas spring, a nitrogen "
       "cylinder, a cushion; its steepest slope counts in the mass check below"},
  }};
  t.push_back(choice_field<M, M::ForceOf>("force_of", &M::force_of, kForceOf, "")
                  .when(force, "`\"force\"` only",
                        "force_of is for type = \"force\" (what its force curve is against)"));
  t.push_back(custom_field<M>(
                  {"mass", "float", "the blank's mass at the start", "tonne",
                   "> 0, the tool's moving mass; checked when the model is built (below)"},
                  [](const TomlSection& s, M& m, Presence) {
                    double mass = 0.0;
                    if (s.read_number("mass", mass, greater_than(0.0, "tonne"))) {
                      m.mass = mass;
                    }
                  },
                  [](TomlWriter& w, const M& m) {
                    if (m.mass) {
                      w.number("mass", *m.mass, "tonne");
                    } else {
                      w.comment(
                          "mass: not given, the blank's mass at the start (set when the "
                          "model is built)");
                    }
                  })
                  .when(force, "`\"force\"` only", force_only));
  t.push_back(number_field<M>("damping", &M::damping, at_least(0.0, "1/s"),
                              "mass-proportional damping on the tool (force −damping × mass × "
                              "speed); damping × time step must stay below 1 (checked when the "
                              "model is built)")
                  .when(force, "`\"force\"` only", force_only));
  add_turn_fields(t);
  return t;
}

// Friction beyond Coulomb (docs/contact.md, "Friction laws"): a pressure power law or table, a
// slip-speed table and the orthotropic ratio. Each is written only when given, so a case without
// them resolves (and digests) as before.
bool coulomb_friction(const ContactConfig& c) {
  return c.friction_static > 0.0 && c.friction_pressure_table.empty();
}

bool has_friction(const ContactConfig& c) {
  return c.friction_static > 0.0 || !c.friction_pressure_table.empty();
}

std::string needs_friction(const ContactConfig& c) {
  return c.friction_pressure_table.empty()
             ? "friction_static (or friction) is 0: there is no friction to shape"
             : "friction_pressure_table gives the coefficient against the pressure itself";
}

// A friction table [[x, y], ...] of a contact: x, its unit and y name its points in the docs, the
// messages and the resolved case ("pressure", "MPa", "mu").
Field<ContactConfig> friction_table_field(std::string key,
                                          std::vector<std::array<double, 2>> ContactConfig::*m,
                                          std::string x, std::string unit, std::string y,
                                          std::string doc) {
  const std::string point = fmt::format("[{} ({}), {}]", x, unit, y);
  return custom_field<ContactConfig>(
             {key, fmt::format("array of `[{}, {}]`", x, y), "none", unit + ", —", std::move(doc)},
             [key, m, point, x, unit, y](const TomlSection& s, ContactConfig& c, Presence) {
               const std::string context = fmt::format("contact with tool '{}': ", c.tool);
               const PointTableSpec spec{.point = point,
                                         .abscissa = x,
                                         .abscissa_range = at_least(0.0, unit),
                                         .value = y,
                                         .value_range = at_least(0.0),
                                         .min_points = 2,
                                         .context = context};
               read_point_table(s, key, spec, c.*m);
             },
             [key, m, point](TomlWriter& w, const ContactConfig& c) {
               w.points(key, c.*m, fmt::format("[{}, ...]", point));
             })
      .write_if([m](const ContactConfig& c) { return !(c.*m).empty(); });
}

void add_friction_law_fields(FieldTable<ContactConfig>& t) {
  using C = ContactConfig;
  Field<C> pressure_table = friction_table_field(
      "friction_pressure_table", &C::friction_pressure_table, "pressure", "MPa", "mu",
      "at least 2 points, pressures >= 0 strictly increasing, μ >= 0: μ against the contact "
      "pressure, linear between points, the end value held beyond them (a warning, once, when "
      "the run meets a pressure beyond them). Instead of `friction`, `friction_static`, "
      "`friction_dynamic`, `friction_decay` and the power law");
  const auto read_table = pressure_table.read;
  pressure_table.read = [read_table](const TomlSection& s, C& c, Presence p) {
    if (!s.has("friction_pressure_table")) {
      return;
    }
    for (const char* key : {"friction", "friction_static", "friction_dynamic", "friction_decay"}) {
      if (s.has(key)) {
        s.fail_forbidden(key, fmt::format("contact with tool '{}': friction_pressure_table gives "
                                          "the coefficient; give either it or the Coulomb keys",
                                          c.tool));
      }
    }
    read_table(s, c, p);
  };
  t.push_back(std::move(pressure_table));
  t.push_back(number_field<C>("friction_pressure_exponent", &C::friction_pressure_exponent,
                              greater_than(0.0),
                              "n of the pressure power law μ = μc(v) (p / p0)^(n − 1), μc the "
                              "Coulomb coefficient above and p the contact pressure; 1: none")
                  .when(coulomb_friction, "with `friction_static` > 0", needs_friction)
                  .write_if([](const C& c) { return c.friction_pressure_exponent != 1.0; }));
  t.push_back(number_field<C>("friction_reference_pressure", &C::friction_reference_pressure,
                              greater_than(0.0, "MPa"), "p0 of the power law")
                  .required()
                  .when([](const C& c) { return c.friction_pressure_exponent != 1.0; },
                        "with `friction_pressure_exponent` ≠ 1",
                        "friction_reference_pressure is p0 of the power law: it needs "
                        "friction_pressure_exponent (not 1)"));
  t.push_back(friction_table_field(
                  "friction_speed_table", &C::friction_speed_table, "slip speed", "mm/s", "factor",
                  "at least 2 points, slip speeds >= 0 strictly increasing, factors >= 0: a "
                  "factor on μ against the slip speed, linear between points, the end value held "
                  "beyond them")
                  .when(has_friction, "with friction", needs_friction));
  t.push_back(number_field<C>("friction_across_ratio", &C::friction_across_ratio, greater_than(0.0),
                              "μ across the blank's `rolling_direction` over μ along it: an "
                              "elliptic (orthotropic) Coulomb limit; 1: isotropic")
                  .when(has_friction, "with friction", needs_friction)
                  .write_if([](const C& c) { return c.friction_across_ratio != 1.0; }));
}

FieldTable<ContactConfig> make_contact_fields() {
  using C = ContactConfig;
  FieldTable<C> t;
  t.push_back(string_field<C>("tool", &C::tool, "the name of a `[[tools]]` entry").required());
  t.push_back(choice_field<C, ContactSearchKind>("search", &C::search, kContactSearchNames,
                                                 "docs/contact.md"));
  t.push_back(choice_field<C, ContactProjection>("projection", &C::projection,
                                                 kContactProjectionNames, ""));
  t.push_back(number_field<C>("penalty_scale", &C::penalty_scale, greater_than(0.0),
                              "scales the blank's bulk stiffness into the per-node penalty "
                              "stiffness (docs/contact.md). Not with `penalty_stiffness`")
                  .write_if([](const C& c) { return !(c.penalty_stiffness > 0.0); }));
  Field<C> stiffness =
      number_field<C>("penalty_stiffness", &C::penalty_stiffness, greater_than(0.0, "N/mm"),
                      "one penalty stiffness for every blank node. Either way each node's "
                      "stiffness is capped so that it cannot break the stable time step (for a "
                      "given value, the number of nodes capped is logged)")
          .shown_default("from `penalty_scale`")
          .write_if([](const C& c) { return c.penalty_stiffness > 0.0; });
  stiffness.read = [](const TomlSection& s, C& c, Presence) {
    if (s.has("penalty_scale") && s.has("penalty_stiffness")) {
      s.fail_forbidden(
          "penalty_stiffness",
          "give either penalty_scale (relative) or penalty_stiffness (N/mm), not both");
    }
    s.read_number("penalty_stiffness", c.penalty_stiffness, greater_than(0.0));
  };
  t.push_back(std::move(stiffness));
  t.push_back(custom_field<C>(
      {"friction",
       "float",
       "`0.0`",
       {},
       ">= 0; one Coulomb coefficient for rest and sliding. Not with the three keys below"},
      [](const TomlSection& s, C& c, Presence) {
        if (!s.has("friction")) {
          return;
        }
        for (const char* key : {"friction_static", "friction_dynamic", "friction_decay"}) {
          if (s.has(key)) {
            s.fail_forbidden(key,
                             "friction sets one coefficient for rest and sliding; give either "
                             "friction or friction_static (with friction_dynamic, "
                             "friction_decay)");
          }
        }
        s.read_number("friction", c.friction_static, at_least(0.0));
      },
      nullptr));  // written as friction_static and friction_dynamic
  Field<C> static_friction = number_field<C>("friction_static", &C::friction_static, at_least(0.0),
                                             "Coulomb coefficient at rest");
  static_friction.read = [](const TomlSection& s, C& c, Presence) {
    s.read_number("friction_static", c.friction_static, at_least(0.0));
    c.friction_dynamic = c.friction_static;  // the default of friction_dynamic
  };
  // A pressure table replaces the Coulomb keys: they are not written with it.
  const auto coulomb_keys = [](const C& c) { return c.friction_pressure_table.empty(); };
  static_friction.written = coulomb_keys;
  t.push_back(std::move(static_friction));
  t.push_back(number_field<C>(
                  "friction_dynamic", &C::friction_dynamic,
                  [](const C& c) { return NumberRange{.lo = 0.0, .hi = c.friction_static}; }, "",
                  "in [0, `friction_static`]", "Coulomb coefficient when sliding")
                  .shown_default("`friction_static`")
                  .write_if(coulomb_keys));
  t.push_back(number_field<C>("friction_decay", &C::friction_decay, at_least(0.0, "s/mm"),
                              "μ = μd + (μs − μd) exp(−decay · |slip speed|)")
                  .write_if(coulomb_keys));
  add_friction_law_fields(t);
  t.push_back(bool_field<C>(
      "audit", &C::audit,
      "also run the exact search at every frame and history row and record, per blank node, "
      "whether this pair's search chose a triangle that is not an exact closest one, and the gap "
      "error (results fields `search_miss_TOOL`, `search_gap_error_TOOL`; history column "
      "`TOOL_search_misses`)"));
  t.push_back(number_field<C>("search_margin", &C::search_margin, at_least(0.0, "mm"),
                              "how far a node may move relative to the tool before its candidate "
                              "list is rebuilt; 0 = the search's default")
                  .when([](const C& c) { return c.search == ContactSearchKind::cached; },
                        "only with `search = \"cached\"`",
                        "search_margin is the margin of search = \"cached\""));
  return t;
}

}  // namespace

const FieldTable<MeshSourceConfig>& mesh_source_fields() {
  static const FieldTable<MeshSourceConfig> table = make_mesh_source_fields();
  return table;
}

const FieldTable<BlankPartConfig>& blank_part_fields() {
  static const FieldTable<BlankPartConfig> table = make_blank_part_fields();
  return table;
}

const FieldTable<BlankConfig>& blank_fields() {
  static const FieldTable<BlankConfig> table = make_blank_fields();
  return table;
}

const FieldTable<ToolConfig>& tool_fields() {
  static const FieldTable<ToolConfig> table = make_tool_fields();
  return table;
}

const FieldTable<MotionConfig>& motion_fields() {
  static const FieldTable<MotionConfig> table = make_motion_fields();
  return table;
}

const FieldTable<ContactConfig>& contact_fields() {
  static const FieldTable<ContactConfig> table = make_contact_fields();
  return table;
}

}  // namespace sf
