#include "io/case_config_implicit.hpp"

#include <fmt/core.h>

#include <cmath>

namespace sf {

namespace {

// An array [lo, hi] of two finite numbers with lo < hi (mm); absent = required error.
void read_range(const TomlSection& s, std::string_view key, std::array<double, 2>& range) {
  const toml::node* node = s.find(key);
  if (!node) {
    s.fail_missing(key, "[lo, hi] in mm");
  }
  const toml::array* array = node->as_array();
  if (!array || array->size() != 2) {
    s.fail_value(key, "an array [lo, hi] of 2 numbers (mm)");
  }
  for (std::size_t i = 0; i < 2; ++i) {
    const std::optional<double> v = number_of(*array->get(i));
    if (!v || !std::isfinite(*v)) {
      s.fail_value(key, "an array [lo, hi] of 2 finite numbers (mm)");
    }
    range[i] = *v;
  }
  if (!(range[0] < range[1])) {
    s.fail_value(key, "[lo, hi] with lo < hi (mm)");
  }
}

void read_analysis(const TomlSection& top, AnalysisConfig& analysis) {
  const auto s = top.sub_table("analysis", Presence::optional);
  if (!s) {
    return;
  }
  s->check_keys({"type", "geometry"});
  using Type = AnalysisConfig::Type;
  s->read_choice("type", analysis.type,
                 {{"explicit", Type::explicit_dynamic}, {"static", Type::static_equilibrium}});
  if (s->has("geometry") && analysis.type != Type::static_equilibrium) {
    s->fail_forbidden("geometry", "it belongs to a static analysis (type = \"static\")");
  }
  s->read_choice("geometry", analysis.linear, {{"linear", true}, {"nonlinear", false}});
}

void read_implicit(const TomlSection& top, ImplicitConfig& implicit) {
  const auto s = top.sub_table("implicit", Presence::optional);
  if (!s) {
    return;
  }
  s->check_keys({"increments", "max_iterations", "max_cuts", "force_tolerance",
                 "displacement_tolerance", "line_search", "linear_solver", "rigid_body_modes"});
  s->read_integer("increments", implicit.increments, IntegerRange{.lo = 1, .hi = 100000});
  s->read_integer("max_iterations", implicit.max_iterations, IntegerRange{.lo = 1, .hi = 1000});
  s->read_integer("max_cuts", implicit.max_cuts, IntegerRange{.lo = 0, .hi = 30});
  s->read_number("force_tolerance", implicit.force_tolerance, interval(0.0, true, 1.0, true));
  s->read_number("displacement_tolerance", implicit.displacement_tolerance,
                 interval(0.0, true, 1.0, true));
  s->read_bool("line_search", implicit.line_search);
  using Solver = ImplicitConfig::LinearSolver;
  s->read_choice(
      "linear_solver", implicit.linear_solver,
      {{"auto", Solver::automatic}, {"cholmod", Solver::cholmod}, {"umfpack", Solver::umfpack}});
  using Modes = ImplicitConfig::RigidBodyModes;
  s->read_choice("rigid_body_modes", implicit.rigid_body_modes,
                 {{"auto", Modes::automatic}, {"error", Modes::error}});
}

void read_u_channel(const TomlSection& s, UChannelMeasureConfig& u) {
  s.check_keys({"section", "bottom", "wall", "flange"});
  s.read_string("section", u.section, Presence::required);
  read_range(s, "bottom", u.bottom);
  read_range(s, "wall", u.wall);
  read_range(s, "flange", u.flange);
  if (!(u.bottom[1] <= u.flange[0])) {
    s.fail_value("flange", fmt::format("an x range beyond the bottom's (which ends at {} mm)",
                                       format_toml_number(u.bottom[1])));
  }
}

void read_springback(const TomlSection& top, std::optional<SpringbackConfig>& springback) {
  const auto s = top.sub_table("springback", Presence::optional);
  if (!s) {
    return;
  }
  s->check_keys(
      {"method", "release_time", "max_time", "kinetic_tolerance", "stabilization", "u_channel"});
  SpringbackConfig sb;
  using Method = SpringbackConfig::Method;
  s->read_choice(
      "method", sb.method,
      {{"implicit", Method::implicit}, {"dynamic_relaxation", Method::dynamic_relaxation}});
  if (sb.method == Method::implicit) {
    for (const std::string_view key : {"release_time", "max_time", "kinetic_tolerance"}) {
      if (s->has(key)) {
        s->fail_forbidden(key,
                          "it belongs to method = \"dynamic_relaxation\" (the implicit method "
                          "takes its controls from [implicit])");
      }
    }
    s->read_number("stabilization", sb.stabilization, interval(0.0, false, 1e-2, false));
  } else {
    if (s->has("stabilization")) {
      s->fail_forbidden("stabilization",
                        "it belongs to method = \"implicit\" (dynamic relaxation releases the "
                        "tool forces over release_time instead)");
    }
    s->read_number("release_time", sb.release_time, greater_than(0.0, "s"), Presence::required);
    s->read_number("max_time", sb.max_time, at_least(0.0, "s"));
    s->read_number("kinetic_tolerance", sb.kinetic_tolerance, interval(0.0, true, 1.0, true));
    if (sb.max_time == 0.0) {
      sb.max_time = 10.0 * sb.release_time;
    }
  }
  if (const auto u = s->sub_table("u_channel", Presence::optional)) {
    read_u_channel(*u, sb.u_channel.emplace());
  }
  springback = std::move(sb);
}

}  // namespace

void read_implicit_sections(const TomlSection& top, CaseConfig& config) {
  read_analysis(top, config.analysis);
  read_implicit(top, config.implicit);
  read_springback(top, config.springback);
  if (config.analysis.type == AnalysisConfig::Type::static_equilibrium) {
    if (!config.tools.empty()) {
      top.fail_at(top.table(), "analysis.type",
                  fmt::format("a static analysis has no tools (contact is explicit only), but "
                              "the case has {} [[tools]] entries: remove them, or use type = "
                              "\"explicit\"",
                              config.tools.size()));
    }
    if (config.springback) {
      top.fail_at(top.table(), "springback",
                  "[springback] follows an explicit forming run; a static analysis "
                  "(analysis.type = \"static\") has none");
    }
    for (const std::string_view key : {"prescribed_velocity", "initial_velocity"}) {
      const std::vector<TomlSection> tables = top.table_array(key);
      if (!tables.empty()) {
        top.fail_at(tables.front().table(), tables.front().path(),
                    "[[prescribed_velocity]] and [[initial_velocity]] belong to explicit runs; a "
                    "static analysis is loaded by [[load]] tables and driven by "
                    "[[prescribed_motion]] displacements");
      }
    }
  }
  if (config.springback && config.tools.empty()) {
    top.fail_at(top.table(), "springback",
                "[springback] releases the tools at the end of forming, but the case has no "
                "[[tools]]");
  }
}

}  // namespace sf
