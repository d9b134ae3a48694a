// The field tables of the top level, [control], [output], [formability], [limits] and
// [[draw_in]].
#include <fmt/core.h>

#include <stdexcept>

#include "casefile/case_fields.hpp"
#include "casefile/unit_system.hpp"

namespace sf {

namespace {

FieldTable<CaseConfig> make_top_level_fields() {
  using C = CaseConfig;
  FieldTable<C> t;
  t.push_back(string_field<C>("title", &C::title, "free text", true));
  t.push_back(custom_field<C>(
      {"units",
       "string",
       "`\"mm-s-tonne-N-MPa\"`",
       {},
       "`\"LENGTH-TIME-MASS-FORCE-STRESS\"`, a consistent system (below), or `\"consistent\"`"},
      [](const TomlSection& s, C& c, Presence) {
        if (!s.read_string("units", c.units)) {
          return;
        }
        try {
          parse_unit_system(c.units);
        } catch (const std::invalid_argument& error) {
          s.fail_at(*s.find("units"), s.key_path("units"),
                    fmt::format("{}; got {}", error.what(), quote_toml_string(c.units)));
        }
      },
      [](TomlWriter& w, const C& c) { w.string("units", c.units); }));
  return t;
}

FieldTable<ControlConfig> make_control_fields() {
  using C = ControlConfig;
  FieldTable<C> t;
  t.push_back(number_field<C>("end_time", &C::end_time, at_least(0.0, "s"),
                              "0 = run until the stroke is reached"));
  t.push_back(number_field<C>("stroke", &C::stroke, at_least(0.0, "mm"),
                              "travel of `stroke_tool` at which the run stops; 0 = run until "
                              "`end_time`"));
  t.push_back(custom_field<C>(
      {"stroke_tool",
       "string",
       "the first tool with a prescribed motion (`\"velocity\"` or `\"displacement\"`)",
       {},
       "must name a tool, not a force-controlled one; when `stroke` > 0 it must be a moving tool "
       "(and one must exist)"},
      [](const TomlSection& s, C& c, Presence) { s.read_string("stroke_tool", c.stroke_tool); },
      [](TomlWriter& w, const C& c) {
        if (c.stroke_tool.empty()) {
          w.comment("stroke_tool: none (no tool moves)");
        } else {
          w.string("stroke_tool", c.stroke_tool);
        }
      }));
  t.push_back(integer_field<C>(
      "output_frames", &C::output_frames,
      IntegerRange{.lo = 1, .limit_note = "a run is held to limits.max_frames, 10000 by default"},
      "frames at evenly spaced times (plus the initial one), each written at the first step end "
      "at or past its time (the step is not cut to it: docs/time-integration.md); the last at "
      "the end time"));
  t.push_back(integer_field<C>("history_interval", &C::history_interval,
                               IntegerRange{.lo = 1, .unit = "cycles"},
                               "cycles between history rows"));
  t.push_back(integer_field<C>("progress_interval", &C::progress_interval,
                               IntegerRange{.lo = 0, .unit = "cycles"},
                               "0 = a progress line about every 2 s of wall time"));
  t.push_back(number_field<C>("time_step_safety", &C::time_step_safety,
                              interval(0.0, true, 1.0, false), "factor on the critical time step"));
  t.push_back(number_field<C>("mass_scaling_dt", &C::mass_scaling_dt, at_least(0.0, "s"),
                              "target time step for selective mass scaling, 0 = off (below)"));
  t.push_back(number_field<C>(
      "mass_scaling_max_added", &C::mass_scaling_max_added, at_least(0.0),
      "largest added mass as a fraction of the blank's physical mass (0.05 = 5 %, the default "
      "1.0 = as much again as the blank's own mass); beyond it the run stops, or is refused at "
      "the start; 0 = no limit"));
  t.push_back(bool_field<C>(
      "land_on_end", &C::land_on_end,
      "true: the last step is cut short so that the run ends exactly at the end time (or "
      "stroke); false: it ends at the first whole step at or past it, so that another case "
      "starting from its formed part (`blank.formed_part`) continues with the bits of one "
      "uninterrupted run (docs/process-chain.md)"));
  t.push_back(number_field<C>("energy_blowup_ratio", &C::energy_blowup_ratio, greater_than(1.0),
                              "the run stops when the total energy exceeds this times the "
                              "external work"));
  t.push_back(integer_field<C>(
      "checkpoint_cycles", &C::checkpoint_cycles, IntegerRange{.lo = 0, .unit = "cycles"},
      "a checkpoint (results folder's `checkpoint.h5`) every this many cycles; 0 = none by count "
      "(docs/restart.md)"));
  t.push_back(number_field<C>(
      "checkpoint_minutes", &C::checkpoint_minutes, at_least(0.0, "min"),
      "a checkpoint every this many minutes of wall time; 0 = none by time. A checkpoint is also "
      "written on SIGUSR1, on a clean stop (Ctrl-C, SIGTERM) and at the end of the forming"));
  t.push_back(vector_field<C>("gravity", &C::gravity, "mm/s^2",
                              "acceleration of gravity on every node's physical mass (forming "
                              "cases: none, or `[0, 0, -9810]`)"));
  t.push_back(number_field<C>("damping", &C::damping, at_least(0.0, "1/s"),
                              "mass-proportional damping: a force −damping × m × v on every "
                              "node"));
  return t;
}

FieldTable<OutputConfig> make_output_fields() {
  using O = OutputConfig;
  FieldTable<O> t;
  t.push_back(string_field<O>("directory", &O::directory,
                              "results folder, relative to the case file's folder (stored "
                              "absolute); `sheetform run -o DIR` overrides it"));
  t.push_back(bool_field<O>("stress_layers", &O::stress_layers,
                            "write mid, top and bottom stress per "
                            "element"));
  return t;
}

FieldTable<FormabilityConfig> make_formability_fields() {
  using F = FormabilityConfig;
  FieldTable<F> t;
  t.push_back(choice_field<F, F::Surface>("surface", &F::surface, kFormabilitySurfaceNames,
                                          "the strains that decide `flc_margin` and the zone"));
  t.push_back(number_field<F>("safety_margin", &F::safety_margin, at_least(0.0),
                              "true strain: an element less than this below its FLC is at "
                              "risk of cracks"));
  t.push_back(number_field<F>("insufficient_stretch", &F::insufficient_stretch, at_least(0.0),
                              "true strain: a major strain below this is insufficient "
                              "stretching"));
  t.push_back(number_field<F>("wrinkle_thickening", &F::wrinkle_thickening, at_least(0.0),
                              "true strain: -(major + minor) above this (the minor strain "
                              "compressive beyond the major) is a wrinkling tendency"));
  t.push_back(number_field<F>("severe_thinning", &F::severe_thinning,
                              interval(0.0, true, 100.0, false, "%"),
                              "thinning, per cent of the initial thickness, from which an "
                              "element is severely thinned"));
  return t;
}

FieldTable<LimitsConfig> make_limits_fields() {
  using L = LimitsConfig;
  FieldTable<L> t;
  t.push_back(number_field<L>("max_cycles", &L::max_cycles, greater_than(0.0, "cycles"),
                              "the explicit cycles, end time / initial time step"));
  t.push_back(number_field<L>(
      "max_elements", &L::max_elements, greater_than(0.0, "elements"),
      "of one part. For a `.geo` with `element_size`, estimated before gmsh meshes it (each "
      "surface's area taken as the product of its bounding box's two longest sides; 2.3 "
      "triangles or 1 quad per element_size²)"));
  t.push_back(integer_field<L>("max_frames", &L::max_frames,
                               IntegerRange{.lo = 1, .unit = "frames"}, "`control.output_frames`"));
  t.push_back(number_field<L>("max_output_gb", &L::max_output_gb, greater_than(0.0, "GB"),
                              "the estimated size of results.h5 (every frame's arrays, 8 bytes "
                              "per value, and the history)"));
  t.push_back(number_field<L>(
      "max_memory_gb", &L::max_memory_gb, at_least(0.0, "GB"),
      "the estimated memory (100 MB + 6 kB per blank element + 0.5 kB per tool triangle, from "
      "the measured peaks of the square cups, 900 to 22,500 quads); 0 = this machine's memory"));
  t.push_back(number_field<L>(
      "mesh_seconds", &L::mesh_seconds, at_least(0.0, "s"),
      "the wall time gmsh may take to read and mesh one part; past it gmsh is stopped and the "
      "run ends with exit code 2 and a message naming the file (a `.geo` loop without end, a "
      "far too fine mesh). 0 = scaled with the job: 60 s + 4 s per MB of the file to read it, "
      "then 60 s + 2 ms per element estimated to mesh it (docs/security.md)"));
  t.push_back(number_field<L>(
      "mesh_memory_gb", &L::mesh_memory_gb, at_least(0.0, "GB"),
      "the memory gmsh may allocate reading and meshing one part, in its sandboxed process "
      "(docs/security.md); 0 = this machine's memory"));
  t.push_back(number_field<L>(
      "max_initial_penetration", &L::max_initial_penetration, at_least(0.0),
      "the deepest penetration of a tool into the blank at the start (half the thickness less "
      "the node's signed distance to the tool, within the contact cutoff), as a fraction of the "
      "blank thickness"));
  return t;
}

FieldTable<DrawInConfig> make_draw_in_fields() {
  using D = DrawInConfig;
  FieldTable<D> t;
  t.push_back(name_field<D>("name", &D::name,
                            "unique among draw-ins, e.g. `\"DX\"`; letters, digits, `_`, `-`, "
                            "`.`, not starting with `.` (it names a history column)")
                  .required());
  t.push_back(
      string_field<D>("group", &D::group, "physical group holding one blank node").required());
  t.push_back(direction_field<D>("direction", &D::direction, ""));
  t.push_back(number_field<D>("measured", &D::measured, at_least(0.0, "mm"),
                              "absent = no measured value (stored as -1)")
                  .shown_default("none")
                  .write_if([](const D& d) { return d.measured >= 0.0; }));
  t.push_back(number_field<D>(
                  "measured_stroke", &D::measured_stroke, at_least(0.0, "mm"),
                  "the stroke tool's travel at which `measured` was taken; 0 = at the end of the "
                  "run. A run that ends at another stroke (`--stroke`) prints the measured value "
                  "without comparing it (`compared: false` in summary.json); the draw-in at any "
                  "stroke is in the history column `draw_in_<name>`")
                  .when([](const D& d) { return d.measured >= 0.0; }, "only with `measured`",
                        "it is the stroke of the `measured` value, which is absent"));
  t.push_back(string_field<D>("source", &D::source, "where the measured value comes from", true));
  return t;
}

}  // namespace

const FieldTable<CaseConfig>& top_level_fields() {
  static const FieldTable<CaseConfig> table = make_top_level_fields();
  return table;
}

const FieldTable<ControlConfig>& control_fields() {
  static const FieldTable<ControlConfig> table = make_control_fields();
  return table;
}

const FieldTable<OutputConfig>& output_fields() {
  static const FieldTable<OutputConfig> table = make_output_fields();
  return table;
}

const FieldTable<FormabilityConfig>& formability_fields() {
  static const FieldTable<FormabilityConfig> table = make_formability_fields();
  return table;
}

const FieldTable<LimitsConfig>& limits_fields() {
  static const FieldTable<LimitsConfig> table = make_limits_fields();
  return table;
}

const FieldTable<DrawInConfig>& draw_in_fields() {
  static const FieldTable<DrawInConfig> table = make_draw_in_fields();
  return table;
}

}  // namespace sf
