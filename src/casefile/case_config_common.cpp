#include "casefile/case_config_common.hpp"

#include <fmt/core.h>

#include <cmath>
#include <optional>
#include <string>

namespace sf {

void read_curve(const TomlSection& s, std::string_view key, CurveConfig& curve) {
  const std::string path = s.key_path(key);
  const toml::node* node = s.find(key);
  if (!node) {
    s.fail_missing(key, "an array of [time, value] points");
  }
  const auto* points = node->as_array();
  if (!points || points->empty()) {
    s.fail_value(key, "a non-empty array of [time, value] points");
  }
  for (std::size_t i = 0; i < points->size(); ++i) {
    const toml::node& point_node = *points->get(i);
    const std::string point_path = fmt::format("{}[{}]", path, i);
    const auto* point = point_node.as_array();
    std::optional<double> t, v;
    if (point && point->size() == 2) {
      t = number_of(*point->get(0));
      v = number_of(*point->get(1));
    }
    if (!t || !v || !std::isfinite(*t) || !std::isfinite(*v)) {
      s.fail_at(point_node, point_path,
                fmt::format("expected a point [time (s), value] of 2 numbers, got {}",
                            describe_value(point_node)));
    }
    if (*t < 0.0) {
      s.fail_at(point_node, point_path, fmt::format("expected a time >= 0 (s), got {}", *t));
    }
    if (!curve.times.empty() && !(*t > curve.times.back())) {
      s.fail_at(point_node, point_path,
                fmt::format("expected times strictly increasing, got {} after {}",
                            format_toml_number(*t), format_toml_number(curve.times.back())));
    }
    curve.times.push_back(*t);
    curve.values.push_back(*v);
  }
}

bool read_point_table(const TomlSection& s, std::string_view key, const PointTableSpec& spec,
                      std::vector<std::array<double, 2>>& points) {
  const toml::node* node = s.find(key);
  if (!node) {
    return false;
  }
  const auto* array = node->as_array();
  if (!array || array->size() < spec.min_points) {
    s.fail_value(key, fmt::format("{}an array of at least {} points {}", spec.context,
                                  spec.min_points, spec.point));
  }
  std::vector<std::array<double, 2>> table;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& point_node = *array->get(i);
    const std::string point_path = fmt::format("{}[{}]", s.key_path(key), i);
    const auto fail = [&](const std::string& message) {
      s.fail_at(point_node, point_path, fmt::format("{}{}", spec.context, message));
    };
    const auto* point = point_node.as_array();
    std::optional<double> x, y;
    if (point && point->size() == 2) {
      x = number_of(*point->get(0));
      y = number_of(*point->get(1));
    }
    if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y)) {
      fail(fmt::format("expected a point {} of 2 finite numbers, got {}", spec.point,
                       describe_value(point_node)));
    }
    if (!spec.abscissa_range.contains(*x)) {
      fail(fmt::format("expected a {} that is {}, got {}", spec.abscissa,
                       spec.abscissa_range.describe(), format_toml_number(*x)));
    }
    if (!table.empty() && !(*x > table.back()[0])) {
      fail(fmt::format("expected the {} to increase strictly from point to point, got {} after {}",
                       spec.abscissa, format_toml_number(*x), format_toml_number(table.back()[0])));
    }
    if (!spec.value_range.contains(*y)) {
      fail(fmt::format("expected a {} that is {}, got {}", spec.value, spec.value_range.describe(),
                       format_toml_number(*y)));
    }
    table.push_back({*x, *y});
  }
  points = std::move(table);
  return true;
}

bool read_polyline(const TomlSection& s, std::string_view key, std::size_t min_points,
                   std::vector<std::array<double, 3>>& points) {
  const std::string expected =
      fmt::format("an array of at least {} points [x, y] or [x, y, z] (mm)", min_points);
  const toml::node* node = s.find(key);
  if (!node) {
    return false;
  }
  const toml::array* array = node->as_array();
  if (!array || array->size() < min_points) {
    s.fail_value(key, expected);
  }
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::array* point = array->get(i)->as_array();
    if (!point || point->size() < 2 || point->size() > 3) {
      s.fail_value(key, expected);
    }
    std::array<double, 3> p{0.0, 0.0, 0.0};
    for (std::size_t c = 0; c < point->size(); ++c) {
      const std::optional<double> v = point->get(c)->value<double>();
      if (!v || !std::isfinite(*v)) {
        s.fail_value(key, fmt::format("{}; point {} holds a value that is not a finite number",
                                      expected, i + 1));
      }
      p[c] = *v;
    }
    points.push_back(p);
  }
  return true;
}

std::string format_polyline(const std::vector<std::array<double, 3>>& points) {
  std::string text;
  for (const auto& p : points) {
    text += fmt::format("{}[{}, {}, {}]", text.empty() ? "" : ", ", format_toml_number(p[0]),
                        format_toml_number(p[1]), format_toml_number(p[2]));
  }
  return "[" + text + "]";
}

void read_vector(const TomlSection& s, std::string_view key, std::array<double, 3>& value) {
  const toml::node* node = s.find(key);
  if (!node) {
    return;
  }
  const toml::array* array = node->as_array();
  if (!array || array->size() != 3) {
    s.fail_value(key, "an array of 3 numbers");
  }
  for (std::size_t i = 0; i < 3; ++i) {
    const std::optional<double> v = number_of(*array->get(i));
    if (!v || !std::isfinite(*v)) {
      s.fail_value(key, "an array of 3 finite numbers");
    }
    value[i] = *v;
  }
}

void read_entity_tags(const TomlSection& s, std::string_view key, std::string_view what,
                      std::vector<int>& tags, Presence presence) {
  std::vector<double> numbers;
  const std::string unit = fmt::format("{} tags", what);
  if (s.read_numbers(key, numbers, at_least(1.0, unit), 1, 100000, presence)) {
    for (const double t : numbers) {
      if (t != std::floor(t) || t > 2147483647.0) {
        s.fail_value(key, fmt::format("whole {} tags (integers >= 1)", what));
      }
      tags.push_back(static_cast<int>(t));
    }
  }
}

std::filesystem::path read_existing_file(
    const TomlSection& s, std::string_view key,
    const std::function<bool(const std::filesystem::path&)>& accepts, std::string_view accepted) {
  namespace fs = std::filesystem;
  std::string text;
  s.read_string(key, text, Presence::required);
  const toml::node& node = *s.find(key);
  const fs::path given(text);
  if (!accepts(given)) {
    s.fail_value(key, accepted);
  }
  const fs::path folder = fs::path(s.file()).parent_path();
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

}  // namespace sf
