#include "casefile/case_config_operations.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "casefile/case_fields.hpp"
#include "meshing/mesh_import.hpp"

namespace sf {
namespace {

namespace fs = std::filesystem;
using Op = OperationConfig;
using Kind = OperationConfig::Kind;
using End = OperationConfig::End;

constexpr std::array<Choice<Kind>, 5> kKinds{{
    {Kind::gravity, "gravity",
     "the blank settles under control.gravity onto the tools in play until at rest; first only"},
    {Kind::closing, "closing", "a tool (the binder) closes, by its motion or its force"},
    {Kind::forming, "forming", "tools draw the blank"},
    {Kind::trim, "trim",
     "the elements on the scrap side of `line` are removed from the part as it stands (no time "
     "passes); the operations after it go on with the trimmed part"},
    {Kind::springback, "springback",
     "the case's [springback] (its defaults when absent) on the part as it stands; last only"},
}};

constexpr std::array<Choice<End>, 6> kEnds{{
    {End::stroke, "stroke", "`tool`'s travel since the case's start reaches `stroke`"},
    {End::time, "time", "after `time`"},
    {End::force, "force", "`tool`'s push against its motion reaches `force`"},
    {End::gap, "gap", "the clearance from `tool` to `gap_to` along `tool`'s motion is `gap`"},
    {End::rest, "rest",
     "the kinetic energy falls below `rest` × its peak in the operation and the out-of-balance "
     "force below √`rest` × the applied force"},
    {End::none, "none",
     "springback and trim only: a springback ends when it has converged, a trim at once"},
}};

End default_end(Kind kind) {
  switch (kind) {
    case Kind::gravity:
      return End::rest;
    case Kind::closing:
      return End::gap;
    case Kind::forming:
      return End::stroke;
    case Kind::trim:
    case Kind::springback:
      break;
  }
  return End::none;
}

bool moves(const Op& o) {
  return o.kind != Kind::springback && o.kind != Kind::trim;
}
bool trims(const Op& o) {
  return o.kind == Kind::trim;
}

constexpr std::array<Choice<OperationConfig::TrimMode>, 2> kTrimModes{{
    {OperationConfig::TrimMode::remove, "remove",
     "the elements whose centre projects on the scrap side go whole: the part's edge follows the "
     "elements, within half an element of the line"},
    {OperationConfig::TrimMode::cut, "cut",
     "the elements the line crosses are cut along it into quadrilaterals and triangles (their "
     "state inherited, turned into each piece's frame): the part's edge is the line"},
}};

constexpr std::array<Choice<OperationConfig::Keep>, 2> kKeeps{{
    {OperationConfig::Keep::inside, "inside", "the part inside the line stays"},
    {OperationConfig::Keep::outside, "outside", "the part outside the line stays (a hole)"},
}};

// [[x, y, z], ...] or [[x, y], ...] (z = 0): a closed polyline of at least 3 points.
void read_line(const TomlSection& s, Op& o, Presence presence) {
  if (!read_polyline(s, "line", 3, o.line) && presence == Presence::required) {
    s.fail_missing("line", "an array of at least 3 points [x, y] or [x, y, z] (mm)");
  }
}

// The formats a trim line's file may have: a .geo or .msh with a physical curve, or CAD curves.
bool is_line_format(const fs::path& file) {
  const std::optional<MeshFormat> format = find_mesh_format(file);
  return format && (*format == MeshFormat::geo || *format == MeshFormat::msh || is_cad(*format));
}

bool line_file_is(const Op& o, bool (*test)(MeshFormat)) {
  const std::optional<MeshFormat> format = find_mesh_format(o.line_file);
  return trims(o) && format && test(*format);
}

bool named_curve_format(MeshFormat f) {
  return f == MeshFormat::geo || f == MeshFormat::msh;
}

// A trim's line comes from exactly one of `line`, `line_file` and `line_tool`.
void check_line_source(const TomlSection& s, const Op& o, const CaseConfig& config) {
  const int given = !o.line.empty() + !o.line_file.empty() + !o.line_tool.empty();
  const char* expected = "one of line (a polyline), line_file (a curve of a file) or line_tool";
  if (given == 0) {
    s.fail_missing("line", expected);
  }
  if (given > 1) {
    s.fail_value(o.line.empty() ? "line_file" : "line", fmt::format("{}, not more", expected));
  }
  if (!o.line_tool.empty() && !config.find_tool(o.line_tool)) {
    s.fail_value("line_tool", "the name of a [[tools]] entry");
  }
}

void write_line(TomlWriter& w, const Op& o) {
  w.raw("line", format_polyline(o.line));
}
bool ends_by(const Op& o, std::initializer_list<End> ends) {
  return std::find(ends.begin(), ends.end(), o.end) != ends.end();
}

void read_tool_list(const TomlSection& s, Op& o, Presence) {
  const toml::node* node = s.find("tools");
  if (!node) {
    return;
  }
  const toml::array* array = node->as_array();
  if (!array) {
    s.fail_value("tools", "an array of tool names");
  }
  o.all_tools = false;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const auto* text = array->get(i)->as_string();
    if (!text) {
      s.fail_value("tools", "an array of tool names (strings)");
    }
    o.tools.push_back(text->get());
  }
}

void write_tool_list(TomlWriter& w, const Op& o) {
  if (o.all_tools) {
    w.comment("tools: all");
    return;
  }
  std::string names;
  for (const std::string& name : o.tools) {
    names += fmt::format("{}{}", names.empty() ? "" : ", ", quote_toml_string(name));
  }
  w.raw("tools", "[" + names + "]");
}

FieldTable<Op> make_operation_fields() {
  FieldTable<Op> t;
  t.push_back(name_field<Op>("name", &Op::name,
                             "unique among operations, e.g. `\"OP10-draw\"`; names its results "
                             "group and its summary entry")
                  .required());
  t.push_back(choice_field<Op, Kind>("kind", &Op::kind, kKinds, "").required());
  t.push_back(custom_field<Op>({"tools",
                                "array of strings",
                                "all tools",
                                {},
                                "the tools in play: their contact acts and they move. A tool "
                                "left out stands still where it is, out of contact"},
                               read_tool_list, write_tool_list)
                  .when(moves, "not for `\"springback\"` or `\"trim\"`",
                        "springback and trim have no tools in play"));
  Field<Op> end = choice_field<Op, End>("end", &Op::end, kEnds, "")
                      .shown_default(
                          "by kind: gravity `\"rest\"`, closing `\"gap\"`, forming "
                          "`\"stroke\"`, trim and springback `\"none\"`");
  end.read = [](const TomlSection& s, Op& o, Presence) {
    o.end = default_end(o.kind);
    s.read_choice<End>("end", o.end, kEnds);
  };
  t.push_back(std::move(end));
  t.push_back(string_field<Op>("tool", &Op::tool,
                               "the tool whose travel, push or clearance ends the operation; a "
                               "stroke's default is control.stroke_tool")
                  .shown_default("stroke: `control.stroke_tool`; required for force and gap")
                  .when(
                      [](const Op& o) {
                        return ends_by(o, {End::stroke, End::force, End::gap});
                      },
                      "end `\"stroke\"`, `\"force\"`, `\"gap\"`",
                      "only a stroke, force or gap end names a tool"));
  t.push_back(number_field<Op>("stroke", &Op::stroke, greater_than(0.0, "mm"),
                               "`tool`'s travel counted from the case's start (not from the "
                               "operation's)")
                  .required()
                  .when([](const Op& o) { return o.end == End::stroke; }, "end `\"stroke\"` only",
                        "only a stroke end has a stroke"));
  t.push_back(number_field<Op>("time", &Op::time, greater_than(0.0, "s"),
                               "end `\"time\"`: the operation's duration; force, gap and rest: the "
                               "longest it may take (the run stops with an error past it)")
                  .required()
                  .when([](const Op& o) { return moves(o) && o.end != End::stroke; },
                        "not for a stroke end or springback",
                        "a stroke end's time follows from the tool's motion"));
  t.push_back(number_field<Op>("force", &Op::force, greater_than(0.0, "N"), "")
                  .required()
                  .when([](const Op& o) { return o.end == End::force; }, "end `\"force\"` only",
                        "only a force end has a force"));
  t.push_back(number_field<Op>("gap", &Op::gap, at_least(0.0, "mm"),
                               "e.g. the blank's thickness: the binder has closed on it")
                  .required()
                  .when([](const Op& o) { return o.end == End::gap; }, "end `\"gap\"` only",
                        "only a gap end has a gap"));
  t.push_back(string_field<Op>("gap_to", &Op::gap_to, "the tool the gap is measured to (the die)")
                  .required()
                  .when([](const Op& o) { return o.end == End::gap; }, "end `\"gap\"` only",
                        "only a gap end has a gap"));
  t.push_back(number_field<Op>("rest", &Op::rest, interval(0.0, true, 1.0, true), "")
                  .when([](const Op& o) { return o.end == End::rest; }, "end `\"rest\"` only",
                        "only a rest end has a rest ratio"));
  t.push_back(custom_field<Op>(
                  {"damping", "float", "`control.damping`", "1/s",
                   ">= 0, mass-proportional damping during the operation (a gravity operation "
                   "needs some to come to rest: of the order of the blank's lowest bending "
                   "frequency, rad/s)"},
                  [](const TomlSection& s, Op& o, Presence) {
                    double damping = 0.0;
                    if (s.read_number("damping", damping, at_least(0.0, "1/s"))) {
                      o.damping = damping;
                    }
                  },
                  [](TomlWriter& w, const Op& o) {
                    if (o.damping) {
                      w.number("damping", *o.damping, "1/s");
                    } else {
                      w.comment("damping: control.damping");
                    }
                  })
                  .when(moves, "not for `\"springback\"` or `\"trim\"`",
                        "springback is implicit and a trim takes no time"));
  t.push_back(custom_field<Op>({"line", "array of [x, y] or [x, y, z]", "", "mm",
                                "a trim's line: a closed polyline of at least 3 points (the last "
                                "joins the first) around the part to keep, projected along "
                                "`direction` onto the part as it stands (`mode`: how the "
                                "elements it crosses are trimmed)"},
                               read_line, write_line)
                  .when(trims, "`\"trim\"` only", "only a trim has a line")
                  .shown_default("one of `line`, `line_file`, `line_tool`")
                  .write_if([](const Op& o) { return !o.line.empty(); }));
  t.push_back(custom_field<Op>(
                  {"line_file",
                   "string",
                   "",
                   {},
                   "a trim's line from a file, relative to the case file's folder "
                   "(stored absolute), must exist: a `.geo` or `.msh` file's 1-D "
                   "physical group `line_group`, or the curves `line_curves` of a "
                   "CAD file (`.step`, `.stp`, `.iges`, `.igs`, `.brep`); gmsh "
                   "meshes the curves into points `line_element_size` apart, which "
                   "join into one closed line (ends within a hundredth of "
                   "`line_element_size` are one point)"},
                  [](const TomlSection& s, Op& o, Presence) {
                    if (s.has("line_file")) {
                      o.line_file = read_existing_file(
                          s, "line_file", is_line_format,
                          "a .geo, .msh, .step, .stp, .iges, .igs or .brep file");
                    }
                  },
                  [](TomlWriter& w, const Op& o) { w.string("line_file", o.line_file.string()); })
                  .when(trims, "`\"trim\"` only", "only a trim has a line")
                  .shown_default("none")
                  .write_if([](const Op& o) { return !o.line_file.empty(); }));
  t.push_back(string_field<Op>("line_group", &Op::line_group,
                               "the 1-D physical group (`Physical Curve`) of `line_file` that is "
                               "the line")
                  .when([](const Op& o) { return line_file_is(o, named_curve_format); },
                        "`line_file` `.geo` or `.msh` only",
                        "a CAD file's curves are chosen by line_curves"));
  t.push_back(custom_field<Op>(
                  {"line_curves",
                   "array of integers",
                   "all",
                   {},
                   "the CAD file's curve tags that form the line (open the file in "
                   "the gmsh GUI to see its curve tags)"},
                  [](const TomlSection& s, Op& o, Presence p) {
                    read_entity_tags(s, "line_curves", "curve", o.line_curves, p);
                  },
                  [](TomlWriter& w, const Op& o) {
                    w.numbers("line_curves",
                              std::vector<double>(o.line_curves.begin(), o.line_curves.end()),
                              "the CAD file's curve tags");
                  })
                  .when([](const Op& o) { return line_file_is(o, is_cad); }, "`line_file` CAD only",
                        "a .geo or .msh names its line by line_group")
                  .write_if([](const Op& o) { return !o.line_curves.empty(); }));
  t.push_back(number_field<Op>("line_element_size", &Op::line_element_size, greater_than(0.0, "mm"),
                               "the spacing of the line's points along the curves (gmsh's "
                               "largest element size)")
                  .when([](const Op& o) { return line_file_is(o, is_meshed); },
                        "`line_file` `.geo` or CAD only", "a .msh file's line is read as it is"));
  t.push_back(string_field<Op>("line_tool", &Op::line_tool,
                               "a trim's line as the outline of this tool: its surface, where it "
                               "stands at the trim, projected along `direction`; a point is "
                               "inside when it projects within `line_offset` of it")
                  .when(trims, "`\"trim\"` only", "only a trim has a line")
                  .shown_default("none")
                  .write_if([](const Op& o) { return !o.line_tool.empty(); }));
  t.push_back(number_field<Op>("line_offset", &Op::line_offset, at_least(0.0, "mm"),
                               "the tool's outline grown outwards by it (a trim at a distance "
                               "from the punch's outline)")
                  .when([](const Op& o) { return trims(o) && !o.line_tool.empty(); },
                        "with `line_tool` only", "only a tool's outline is grown"));
  t.push_back(direction_field<Op>("direction", &Op::direction,
                                  "a trim's direction of projection (the press direction)")
                  .when(trims, "`\"trim\"` only", "only a trim has a direction"));
  t.push_back(choice_field<Op, OperationConfig::Keep>("keep", &Op::keep, kKeeps, "")
                  .when(trims, "`\"trim\"` only", "only a trim keeps a side"));
  t.push_back(choice_field<Op, OperationConfig::TrimMode>("mode", &Op::mode, kTrimModes, "")
                  .when(trims, "`\"trim\"` only", "only a trim cuts"));
  t.push_back(
      number_field<Op>("sliver_fraction", &Op::sliver_fraction, interval(0.0, false, 0.5, true),
                       "no piece of a cut element smaller than this fraction of its area: a "
                       "crossing nearer than it (as a fraction of the edge) to a node moves the "
                       "node onto the line instead, as does a piece still too small")
          .when([](const Op& o) { return trims(o) && o.mode == OperationConfig::TrimMode::cut; },
                "with `mode = \"cut\"` only", "only a cut makes pieces"));
  return t;
}

FieldTable<OperationMotionConfig> make_operation_motion_fields() {
  using M = OperationMotionConfig;
  FieldTable<M> t;
  t.push_back(string_field<M>("tool", &M::tool,
                              "a tool in play in the operation, not force-controlled; its "
                              "motion's time counts from the operation's start and its travel "
                              "adds to where it stands")
                  .required());
  for (Field<M>& f : embed_fields<M>(motion_fields(), &M::motion)) {
    t.push_back(std::move(f));
  }
  return t;
}

const FieldTable<OperationMotionConfig>& operation_motion_fields_impl() {
  static const FieldTable<OperationMotionConfig> table = make_operation_motion_fields();
  return table;
}

const ToolConfig& named_tool(const TomlSection& s, std::string_view key, const std::string& name,
                             const CaseConfig& config) {
  const ToolConfig* tool = config.find_tool(name);
  if (!tool) {
    std::string names;
    for (const auto& t : config.tools) {
      names += fmt::format("{}{}", names.empty() ? "" : ", ", quote_toml_string(t.name));
    }
    s.fail_value(key, fmt::format("the name of a [[tools]] entry ({})",
                                  names.empty() ? "none defined" : names));
  }
  return *tool;
}

bool in_play(const Op& o, const std::string& tool) {
  return o.all_tools || std::find(o.tools.begin(), o.tools.end(), tool) != o.tools.end();
}

void check_tools(const TomlSection& s, const Op& o, const CaseConfig& config) {
  for (std::size_t i = 0; i < o.tools.size(); ++i) {
    named_tool(s, "tools", o.tools[i], config);
    if (std::find(o.tools.begin(), o.tools.begin() + static_cast<std::ptrdiff_t>(i), o.tools[i]) !=
        o.tools.begin() + static_cast<std::ptrdiff_t>(i)) {
      s.fail_value("tools", fmt::format("distinct tool names ({} is given twice)",
                                        quote_toml_string(o.tools[i])));
    }
  }
  if (o.end == End::stroke && o.tool.empty()) {
    return;  // control.stroke_tool, checked by read_operations
  }
  if (ends_by(o, {End::stroke, End::force, End::gap})) {
    if (o.tool.empty()) {
      s.fail_missing("tool", "the name of the tool whose push or clearance ends the operation");
    }
    named_tool(s, "tool", o.tool, config);
    if (!in_play(o, o.tool)) {
      s.fail_value("tool", "a tool in play in this operation (listed in `tools`)");
    }
  }
  if (o.end == End::gap) {
    named_tool(s, "gap_to", o.gap_to, config);
    if (o.gap_to == o.tool) {
      s.fail_value("gap_to", "another tool than `tool`");
    }
  }
}

void read_motions(const TomlSection& s, const CaseConfig& config, Op& o) {
  for (const TomlSection& m : s.table_array("motion")) {
    OperationMotionConfig motion;
    read_table(m, operation_motion_fields_impl(), motion);
    const ToolConfig& tool = named_tool(m, "tool", motion.tool, config);
    if (!in_play(o, motion.tool)) {
      m.fail_value("tool", "a tool in play in this operation (listed in the operation's `tools`)");
    }
    if (tool.motion.type == MotionConfig::Type::force ||
        motion.motion.type == MotionConfig::Type::force) {
      m.fail_value("type",
                   "a prescribed motion (\"velocity\", \"displacement\" or \"fixed\") of a tool "
                   "that is not force-controlled: a force-controlled tool keeps its force in "
                   "every operation");
    }
    for (const auto& other : o.motions) {
      if (other.tool == motion.tool) {
        m.fail_value("tool", "a tool whose motion this operation has not redefined already");
      }
    }
    o.motions.push_back(std::move(motion));
  }
}

// A stroke end needs a tool with a prescribed motion (its own or the operation's).
void check_stroke_tool(const TomlSection& s, const Op& o, const CaseConfig& config) {
  if (o.end != End::stroke) {
    return;
  }
  const bool redefined = std::any_of(o.motions.begin(), o.motions.end(),
                                     [&](const auto& m) { return m.tool == o.tool; });
  if (!redefined && config.find_tool(o.tool)->motion.type == MotionConfig::Type::force) {
    s.fail_at(s.has("tool") ? *s.find("tool") : s.table(), s.key_path("tool"),
              fmt::format("tool {} is force-controlled: its travel follows from the force, so it "
                          "cannot give a stroke end; expected a tool with a prescribed motion",
                          quote_toml_string(o.tool)));
  }
}

void check_sequence(const TomlSection& top, const std::vector<TomlSection>& sections,
                    const CaseConfig& config) {
  const auto& ops = config.operations;
  for (std::size_t i = 0; i < ops.size(); ++i) {
    const TomlSection& s = sections[i];
    for (std::size_t j = 0; j < i; ++j) {
      if (ops[j].name == ops[i].name) {
        s.fail_value("name", fmt::format("a name not used by operations[{}]", j));
      }
    }
    if (ops[i].kind == Kind::springback && i + 1 != ops.size()) {
      s.fail_value("kind",
                   "\"springback\" only for the last operation (a trimmed part's "
                   "springback comes with trimming, docs/process-chain.md)");
    }
    if (ops[i].kind == Kind::trim && i == 0) {
      s.fail_value("kind", "\"trim\" after an operation that forms the blank, not first");
    }
    if (ops[i].kind == Kind::gravity && i != 0) {
      s.fail_value("kind",
                   "\"gravity\" only for the first operation (gravity then acts in "
                   "every operation after it)");
    }
    if (ops[i].kind == Kind::gravity &&
        config.control.gravity == std::array<double, 3>{0.0, 0.0, 0.0}) {
      s.fail_value("kind",
                   "\"gravity\" with control.gravity set, e.g. gravity = [0, 0, -9810] "
                   "(mm/s^2)");
    }
  }
  if (ops.size() == 1 && ops[0].kind == Kind::springback) {
    sections[0].fail_value("kind", "a springback after an operation that forms the blank");
  }
  if (config.springback && ops.back().kind != Kind::springback) {
    top.fail_at(top.table(), "springback",
                "[springback] with [[operations]] sets up a springback operation: expected the "
                "last operation to be of kind \"springback\"");
  }
  if (config.control.end_time > 0.0 || config.control.stroke > 0.0) {
    top.fail_at(top.table(), "control",
                "control.end_time and control.stroke are for a case without [[operations]]: "
                "each operation gives its own end (and --stroke, --end-time do not apply)");
  }
}

}  // namespace

const FieldTable<OperationConfig>& operation_fields() {
  static const FieldTable<OperationConfig> table = make_operation_fields();
  return table;
}

const FieldTable<OperationMotionConfig>& operation_motion_fields() {
  return operation_motion_fields_impl();
}

void read_operations(const TomlSection& top, CaseConfig& config) {
  const std::vector<TomlSection> sections = top.table_array("operations");
  for (const TomlSection& s : sections) {
    Op o;
    read_table(s, operation_fields(), o, {"motion"});
    check_tools(s, o, config);
    if (o.end == End::stroke && o.tool.empty()) {
      o.tool = config.control.stroke_tool;
      if (o.tool.empty()) {
        s.fail_missing("tool",
                       "the tool whose travel is the stroke (no tool has a prescribed "
                       "motion to be control.stroke_tool)");
      }
    }
    if ((o.kind == Kind::springback || o.kind == Kind::trim) && o.end != End::none) {
      s.fail_value("end", "\"none\" for a springback or a trim (they end by themselves)");
    }
    if (moves(o) && o.end == End::none) {
      s.fail_value("end",
                   "an end for an operation that moves tools (stroke, time, force, gap "
                   "or rest)");
    }
    if (!moves(o) && s.has("motion")) {
      s.fail_forbidden("motion", "springback and trim have no tools in play");
    }
    read_motions(s, config, o);
    check_stroke_tool(s, o, config);
    if (trims(o)) {
      check_line_source(s, o, config);
    }
    config.operations.push_back(std::move(o));
  }
  if (!sections.empty()) {
    check_sequence(top, sections, config);
  }
}

std::string_view operation_kind_name(OperationConfig::Kind kind) {
  return choice_name<Kind>(kKinds, kind);
}

void write_operations(TomlWriter& w, const CaseConfig& config) {
  for (const Op& o : config.operations) {
    w.array_header("operations");
    write_fields(operation_fields(), w, o);
    for (const auto& m : o.motions) {
      w.array_header("operations.motion");
      write_fields(operation_motion_fields(), w, m);
    }
  }
}

}  // namespace sf
