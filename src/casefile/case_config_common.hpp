#pragma once
// Readers shared by the case-file sections (case_config*.cpp): not a public interface.
#include <array>
#include <filesystem>
#include <functional>
#include <string_view>
#include <vector>

#include "casefile/case_config.hpp"
#include "casefile/toml_reader.hpp"

namespace sf {

/// Reads `key` (required) as a non-empty array of [time (s), value] points with finite numbers,
/// times >= 0 and strictly increasing, into `curve`.
void read_curve(const TomlSection& s, std::string_view key, CurveConfig& curve);

/// What the points of a table read by read_point_table are, for its checks and messages.
struct PointTableSpec {
  std::string_view point;     ///< a point as the messages show it: "[pressure (MPa), mu]"
  std::string_view abscissa;  ///< what the first numbers are: "pressure"
  NumberRange abscissa_range;
  std::string_view value;  ///< what the second numbers are: "friction coefficient"
  NumberRange value_range;
  std::size_t min_points = 2;
  std::string_view context;  ///< put before each message ("contact with tool 'die': "), or empty
};

/// Reads `key`, when present, as an array of at least spec.min_points points [x, y] of finite
/// numbers, x in spec.abscissa_range and strictly increasing, y in spec.value_range, into
/// `points` (replaced); returns whether it was there. Errors name the file, line and point.
bool read_point_table(const TomlSection& s, std::string_view key, const PointTableSpec& spec,
                      std::vector<std::array<double, 2>>& points);

/// Reads `key` as an array of 3 finite numbers (any values, unlike read_direction); absent leaves
/// `value` as it is.
void read_vector(const TomlSection& s, std::string_view key, std::array<double, 3>& value);

/// Reads `key`, when present, as a polyline: an array of at least `min_points` points [x, y, z]
/// or [x, y] (z = 0) of finite numbers (mm), appended to `points`; returns whether it was there.
bool read_polyline(const TomlSection& s, std::string_view key, std::size_t min_points,
                   std::vector<std::array<double, 3>>& points);

/// A polyline as a TOML array of [x, y, z] points.
std::string format_polyline(const std::vector<std::array<double, 3>>& points);

/// Reads `key` as an array of whole gmsh entity tags >= 1 (`what`: "surface" or "curve", for the
/// message) into `tags`; absent leaves it empty (an error when required).
void read_entity_tags(const TomlSection& s, std::string_view key, std::string_view what,
                      std::vector<int>& tags, Presence presence);

/// Reads `key` as a path (relative to the case file's folder) to a file that must exist and whose
/// name `accepts` (`accepted` says what for the message, e.g. "a .csv file"); returns it absolute.
std::filesystem::path read_existing_file(
    const TomlSection& s, std::string_view key,
    const std::function<bool(const std::filesystem::path&)>& accepts, std::string_view accepted);

}  // namespace sf
