#pragma once
// TomlWriter: appends TOML lines (key = value, with the unit in a comment) to a string; the
// resolved-case writer's output (format_resolved_case). Not a public interface.
#include <fmt/core.h>

#include <array>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "casefile/case_config.hpp"
#include "casefile/toml_reader.hpp"

namespace sf {

/// Appends TOML lines to a string.
class TomlWriter {
 public:
  void comment(std::string_view text) { line(fmt::format("# {}", text)); }
  void header(std::string_view name) { line(fmt::format("\n[{}]", name)); }
  void array_header(std::string_view name) { line(fmt::format("\n[[{}]]", name)); }

  void string(std::string_view key, std::string_view value) {
    entry(key, quote_toml_string(value), {});
  }
  void number(std::string_view key, double value, std::string_view unit = {}) {
    entry(key, format_toml_number(value), unit);
  }
  void integer(std::string_view key, long long value, std::string_view unit = {}) {
    entry(key, fmt::format("{}", value), unit);
  }
  void raw(std::string_view key, std::string_view value, std::string_view unit = {}) {
    entry(key, value, unit);
  }
  void boolean(std::string_view key, bool value) { entry(key, value ? "true" : "false", {}); }
  void vector(std::string_view key, const std::array<double, 3>& v,
              std::string_view unit = "unit vector") {
    entry(key,
          fmt::format("[{}, {}, {}]", format_toml_number(v[0]), format_toml_number(v[1]),
                      format_toml_number(v[2])),
          unit);
  }
  void curve(std::string_view key, const CurveConfig& curve, std::string_view unit) {
    std::string points;
    for (std::size_t i = 0; i < curve.times.size(); ++i) {
      points += fmt::format("{}[{}, {}]", i == 0 ? "" : ", ", format_toml_number(curve.times[i]),
                            format_toml_number(curve.values[i]));
    }
    entry(key, fmt::format("[{}]", points), unit);
  }

  void points(std::string_view key, const std::vector<std::array<double, 2>>& points,
              std::string_view unit) {
    std::string text;
    for (std::size_t i = 0; i < points.size(); ++i) {
      text += fmt::format("{}[{}, {}]", i == 0 ? "" : ", ", format_toml_number(points[i][0]),
                          format_toml_number(points[i][1]));
    }
    entry(key, fmt::format("[{}]", text), unit);
  }

  void numbers(std::string_view key, const std::vector<double>& values,
               std::string_view unit = {}) {
    std::string text;
    for (std::size_t i = 0; i < values.size(); ++i) {
      text += fmt::format("{}{}", i == 0 ? "" : ", ", format_toml_number(values[i]));
    }
    entry(key, fmt::format("[{}]", text), unit);
  }

  std::string take() { return std::move(text_); }

 private:
  void line(std::string_view text) {
    text_ += text;
    text_ += '\n';
  }
  void entry(std::string_view key, std::string_view value, std::string_view unit) {
    std::string text = fmt::format("{} = {}", key, value);
    if (!unit.empty()) {
      text = fmt::format("{:<32}# {}", text + " ", unit);
    }
    line(text);
  }

  std::string text_;
};

}  // namespace sf
