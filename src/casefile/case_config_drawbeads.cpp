#include "casefile/case_config_drawbeads.hpp"

#include <fmt/core.h>

#include <array>
#include <cmath>
#include <optional>

#include "casefile/case_config_common.hpp"
#include "casefile/case_fields.hpp"
#include "meshing/mesh_import.hpp"

namespace sf {
namespace {

using B = DrawbeadConfig;
using Force = DrawbeadConfig::Force;

constexpr std::array<Choice<Force>, 2> kForces{{
    {Force::curve, "curve",
     "`restraining_force` and `uplift_force` (N/mm) against `closure`, linear between points"},
    {Force::round_bead, "round_bead",
     "from a round bead's geometry and the sheet: bending and unbending over the shoulders and "
     "the bead with friction on the arcs (docs/drawbeads.md), times the closure"},
}};

// The formats a bead line's file may have: a .geo or .msh with a physical curve, or CAD curves.
bool is_line_format(const std::filesystem::path& file) {
  const std::optional<MeshFormat> format = find_mesh_format(file);
  return format && (*format == MeshFormat::geo || *format == MeshFormat::msh || is_cad(*format));
}

bool line_file_is(const B& b, bool (*test)(MeshFormat)) {
  const std::optional<MeshFormat> format = find_mesh_format(b.line_file);
  return format && test(*format);
}

bool named_curve_format(MeshFormat f) {
  return f == MeshFormat::geo || f == MeshFormat::msh;
}

bool curve(const B& b) {
  return b.force == Force::curve;
}
bool round_bead(const B& b) {
  return b.force == Force::round_bead;
}

// [[x, y, z], ...] or [[x, y], ...] (z = 0): an open polyline of at least 2 points, none
// repeating the one before it.
void read_line(const TomlSection& s, B& b, Presence) {
  if (!read_polyline(s, "line", 2, b.line)) {
    return;  // line_file, or neither (check_line_source)
  }
  for (std::size_t k = 1; k < b.line.size(); ++k) {
    if (b.line[k] == b.line[k - 1]) {
      s.fail_value("line", fmt::format("points that differ; point {} repeats point {}", k + 1, k));
    }
  }
}

void write_line(TomlWriter& w, const B& b) {
  w.raw("line", format_polyline(b.line));
}

FieldTable<B> make_drawbead_fields() {
  FieldTable<B> t;
  t.push_back(name_field<B>("name", &B::name,
                            "unique among the beads; names it in the banner and the summary")
                  .required());
  t.push_back(string_field<B>("tool", &B::tool,
                              "the `[[tools]]` entry the bead belongs to; it needs a `[[contact]]` "
                              "and the bead moves with it")
                  .required());
  t.push_back(custom_field<B>({"line", "array of [x, y] or [x, y, z]", "", "mm",
                               "the bead's centre line: an open polyline on the tool's surface, "
                               "where the tool is meshed (each point within `width` / 2 of it). "
                               "This or `line_file`"},
                              read_line, write_line)
                  .shown_default("none")
                  .write_if([](const B& b) { return !b.line.empty(); }));
  t.push_back(custom_field<B>(
                  {"line_file",
                   "string",
                   "",
                   {},
                   "the bead's centre line from a file, relative to the case file's folder "
                   "(stored absolute), must exist: a `.geo` or `.msh` file's 1-D physical group "
                   "`line_group`, or the curves `line_curves` of a CAD file (`.step`, `.stp`, "
                   "`.iges`, `.igs`, `.brep`); gmsh meshes the curves into points "
                   "`line_element_size` apart, which join into one open line (ends within a "
                   "hundredth of `line_element_size` are one point)"},
                  [](const TomlSection& s, B& b, Presence) {
                    if (s.has("line_file")) {
                      b.line_file = read_existing_file(
                          s, "line_file", is_line_format,
                          "a .geo, .msh, .step, .stp, .iges, .igs or .brep file");
                    }
                  },
                  [](TomlWriter& w, const B& b) { w.string("line_file", b.line_file.string()); })
                  .shown_default("none")
                  .write_if([](const B& b) { return !b.line_file.empty(); }));
  t.push_back(string_field<B>("line_group", &B::line_group,
                              "the 1-D physical group (`Physical Curve`) of `line_file` that is "
                              "the line")
                  .shown_default("the bead's `name`")
                  .when([](const B& b) { return line_file_is(b, named_curve_format); },
                        "`line_file` `.geo` or `.msh` only",
                        "a CAD file's curves are chosen by line_curves"));
  t.push_back(custom_field<B>(
                  {"line_curves",
                   "array of integers",
                   "all",
                   {},
                   "the CAD file's curve tags that form the line"},
                  [](const TomlSection& s, B& b, Presence p) {
                    read_entity_tags(s, "line_curves", "curve", b.line_curves, p);
                  },
                  [](TomlWriter& w, const B& b) {
                    w.numbers("line_curves",
                              std::vector<double>(b.line_curves.begin(), b.line_curves.end()),
                              "the CAD file's curve tags");
                  })
                  .when([](const B& b) { return line_file_is(b, is_cad); }, "`line_file` CAD only",
                        "a .geo or .msh names its line by line_group")
                  .write_if([](const B& b) { return !b.line_curves.empty(); }));
  t.push_back(number_field<B>("line_element_size", &B::line_element_size, greater_than(0.0, "mm"),
                              "the spacing of the line's points along the curves")
                  .when([](const B& b) { return line_file_is(b, is_meshed); },
                        "`line_file` `.geo` or CAD only", "a .msh file's line is read as it is"));
  t.push_back(number_field<B>("width", &B::width, greater_than(0.0, "mm"),
                              "the band across the line the force acts in (about the groove's "
                              "width); its force is spread over it by a cosine window")
                  .required());
  t.push_back(number_field<B>("height", &B::height, greater_than(0.0, "mm"),
                              "the closing travel: the closure goes from 0 with the tool this far "
                              "from the sheet's surface to 1 with it closed on the sheet")
                  .shown_default("required with `force = \"curve\"`; else `depth`")
                  .write_if([](const B& b) { return b.height > 0.0; }));
  t.push_back(choice_field<B, Force>("force", &B::force, kForces, ""));
  t.push_back(bool_field<B>("locking", &B::locking,
                            "a locking bead: the sheet does not pass it (no limit to the "
                            "restraint, which is then an elastic spring)"));
  t.push_back(numbers_field<B>("closure", &B::closure, interval(0.0, false, 1.0, false), 1, 100,
                               "the curves' abscissae, increasing")
                  .when(curve, "`force = \"curve\"` only",
                        "the round bead's force follows from its geometry"));
  t.push_back(numbers_field<B>("restraining_force", &B::restraining_force, at_least(0.0, "N/mm"), 1,
                               100,
                               "force per unit length of bead against the sheet's motion "
                               "across it, at each `closure`")
                  .when([](const B& b) { return curve(b) && !b.locking; },
                        "`force = \"curve\"` and not `locking`",
                        [](const B& b) {
                          return std::string(b.locking ? "a locking bead has no restraint limit"
                                                       : "the round bead's force follows from "
                                                         "its geometry");
                        }));
  t.push_back(numbers_field<B>("uplift_force", &B::uplift_force, at_least(0.0, "N/mm"), 1, 100,
                               "force per unit length pushing the sheet away from the tool (and "
                               "the tool open), at each `closure`; none when absent")
                  .when(curve, "`force = \"curve\"` only",
                        "the round bead's uplift follows from its geometry"));
  const auto round_only = [](Field<B> f) {
    return std::move(f).when(round_bead, "`force = \"round_bead\"` only",
                             "a key of `force = \"round_bead\"`; this bead's force comes from "
                             "its curves");
  };
  t.push_back(round_only(
      number_field<B>("bead_radius", &B::bead_radius, greater_than(0.0, "mm"), "the bead's crest")
          .required()));
  t.push_back(round_only(number_field<B>("shoulder_radius", &B::shoulder_radius,
                                         greater_than(0.0, "mm"), "the groove's shoulders")
                             .required()));
  t.push_back(round_only(number_field<B>("depth", &B::depth, greater_than(0.0, "mm"),
                                         "how far the bead's crest stands into the groove with "
                                         "the binder closed (the bead penetration)")
                             .required()));
  t.push_back(round_only(number_field<B>("clearance", &B::clearance, at_least(0.0, "mm"),
                                         "side clearance: bead and shoulder centres are "
                                         "bead_radius + shoulder_radius + t + clearance apart")));
  t.push_back(round_only(number_field<B>("friction", &B::friction, at_least(0.0),
                                         "Coulomb coefficient on the bead and shoulders; "
                                         "required when the tool's contact friction depends on "
                                         "the pressure")
                             .shown_default("the tool's `[[contact]]` sliding friction")
                             .write_if([](const B& b) { return b.friction >= 0.0; })));
  t.push_back(round_only(number_field<B>("flow_stress", &B::flow_stress, greater_than(0.0, "MPa"),
                                         "one flow stress for the sheet in every bend")
                             .shown_default("the blank material's hardening curve, through the "
                                            "bends (docs/drawbeads.md)")
                             .write_if([](const B& b) { return b.flow_stress > 0.0; })));
  t.push_back(round_only(number_field<B>("thickness", &B::thickness, greater_than(0.0, "mm"),
                                         "the sheet's thickness in the bead")
                             .shown_default("`blank.thickness`")
                             .write_if([](const B& b) { return b.thickness > 0.0; })));
  return t;
}

// The curves: as long as `closure`, which increases (a function of the closure).
void check_curves(const TomlSection& s, const B& b) {
  if (!curve(b)) {
    return;
  }
  if (!b.locking && b.closure.empty()) {
    s.fail_missing("closure", "the closures (0 to 1) `restraining_force` is given at");
  }
  if (!b.locking && b.restraining_force.empty()) {
    s.fail_missing("restraining_force", "N/mm at each `closure` (or `locking = true`)");
  }
  if (!b.uplift_force.empty() && b.closure.empty()) {
    s.fail_missing("closure", "the closures (0 to 1) `uplift_force` is given at");
  }
  for (std::size_t k = 1; k < b.closure.size(); ++k) {
    if (!(b.closure[k] > b.closure[k - 1])) {
      s.fail_value("closure", fmt::format("increasing values (the force must be a function of the "
                                          "closure); value {} is {}, value {} is {}",
                                          k, b.closure[k - 1], k + 1, b.closure[k]));
    }
  }
  for (const auto& [key, values] :
       {std::pair{"restraining_force", &b.restraining_force}, {"uplift_force", &b.uplift_force}}) {
    if (!values->empty() && values->size() != b.closure.size()) {
      s.fail_value(key, fmt::format("{} values, one per `closure` (got {})", b.closure.size(),
                                    values->size()));
    }
  }
  if (!(b.height > 0.0)) {
    s.fail_missing("height",
                   "the bead's closing travel (mm): the curves' closure goes from 0 "
                   "with the tool this far from the sheet to 1 closed on it");
  }
}

}  // namespace

const FieldTable<DrawbeadConfig>& drawbead_fields() {
  static const FieldTable<DrawbeadConfig> table = make_drawbead_fields();
  return table;
}

void read_drawbeads(const TomlSection& top, CaseConfig& config) {
  const std::vector<TomlSection> sections = top.table_array("drawbeads");
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const TomlSection& s = sections[i];
    B b;
    read_table(s, drawbead_fields(), b);
    for (std::size_t j = 0; j < i; ++j) {
      if (config.drawbeads[j].name == b.name) {
        s.fail_at(*s.find("name"), s.key_path("name"),
                  fmt::format("duplicate drawbead name {} (already used by drawbeads[{}])",
                              quote_toml_string(b.name), j));
      }
    }
    if (!config.find_tool(b.tool)) {
      s.fail_value("tool", "the name of a [[tools]] entry");
    }
    const bool has_contact = std::any_of(config.contacts.begin(), config.contacts.end(),
                                         [&](const ContactConfig& c) { return c.tool == b.tool; });
    if (!has_contact) {
      s.fail_value("tool", fmt::format("a tool with a [[contact]] (the bead acts on the sheet the "
                                       "tool closes on; tool {} has none)",
                                       quote_toml_string(b.tool)));
    }
    if (b.line.empty() && b.line_file.empty()) {
      s.fail_missing("line", "one of line (a polyline) or line_file (a curve of a file)");
    }
    if (!b.line.empty() && !b.line_file.empty()) {
      s.fail_forbidden("line_file", "the bead has a line already: give line or line_file");
    }
    if (!b.line_file.empty() && b.line_group.empty()) {
      b.line_group = b.name;  // the default group is the bead's name
    }
    check_curves(s, b);
    config.drawbeads.push_back(std::move(b));
  }
}

void write_drawbeads(TomlWriter& w, const CaseConfig& config) {
  for (const B& b : config.drawbeads) {
    w.array_header("drawbeads");
    write_fields(drawbead_fields(), w, b);
  }
}

}  // namespace sf
