#include "casefile/case_config_implicit.hpp"

#include <fmt/core.h>

#include "casefile/case_fields.hpp"

namespace sf {

namespace {

void read_analysis(const TomlSection& top, AnalysisConfig& analysis) {
  if (const auto s = top.sub_table("analysis", Presence::optional)) {
    read_table(*s, analysis_fields(), analysis);
  }
}

void read_implicit(const TomlSection& top, ImplicitConfig& implicit) {
  if (const auto s = top.sub_table("implicit", Presence::optional)) {
    read_table(*s, implicit_fields(), implicit);
  }
}

void read_springback(const TomlSection& top, std::optional<SpringbackConfig>& springback) {
  const auto s = top.sub_table("springback", Presence::optional);
  if (!s) {
    return;
  }
  SpringbackConfig sb;
  read_table(*s, springback_fields(), sb, {"u_channel"});
  if (const auto u_section = s->sub_table("u_channel", Presence::optional)) {
    UChannelMeasureConfig& u = sb.u_channel.emplace();
    read_table(*u_section, u_channel_fields(), u);
    if (!(u.bottom[1] <= u.flange[0])) {
      u_section->fail_value("flange",
                            fmt::format("an x range beyond the bottom's (which ends at {} mm)",
                                        format_toml_number(u.bottom[1])));
    }
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
