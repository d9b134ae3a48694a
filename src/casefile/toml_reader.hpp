#pragma once
// Checked access to a parsed TOML table, for input readers: every failure throws InputError with
// "file:line:col: dotted.key: expected ..., got ...". Used by read_case; not a public interface.
#include <toml++/toml.h>

#include <array>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/choice.hpp"

namespace sf {

enum class Presence { optional, required };

/// An allowed interval of real numbers, with the unit shown in messages.
struct NumberRange {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;
  std::string_view unit{};  ///< e.g. "mm"; empty = dimensionless

  bool contains(double v) const;
  /// "a number > 0 (mm)", "a number in (0, 1]", ...
  std::string describe() const;
};

NumberRange greater_than(double lo, std::string_view unit = {});
NumberRange at_least(double lo, std::string_view unit = {});
NumberRange interval(double lo, bool lo_open, double hi, bool hi_open, std::string_view unit = {});

/// An allowed interval of integers.
struct IntegerRange {
  std::int64_t lo = std::numeric_limits<int>::min();
  std::int64_t hi = std::numeric_limits<int>::max();
  std::string_view unit{};
  /// Said to a value above hi, besides hi itself: a tighter limit elsewhere ("limits.max_frames").
  std::string_view limit_note{};

  bool contains(std::int64_t v) const { return v >= lo && v <= hi; }
  std::string describe() const;
};

/// A value in a message: 0.81, "abc", true, an array, a table.
std::string describe_value(const toml::node& node);
/// A string as a TOML basic string (quoted and escaped).
std::string quote_toml_string(std::string_view text);
/// A number as the shortest text that reads back exactly, always with a fraction or exponent.
std::string format_toml_number(double value);
/// The number held by an integer or floating-point node.
std::optional<double> number_of(const toml::node& node);

/// One table of the input, with its dotted path ("tools[1].motion") and the file it came from.
class TomlSection {
 public:
  TomlSection(const toml::table& table, std::string path, const std::string& file)
      : table_(&table), path_(std::move(path)), file_(&file) {}

  const toml::table& table() const { return *table_; }
  const std::string& path() const { return path_; }
  const std::string& file() const { return *file_; }
  /// "path.key" (or "key" at the top level).
  std::string key_path(std::string_view key) const;

  const toml::node* find(std::string_view key) const { return table_->get(key); }
  bool has(std::string_view key) const { return find(key) != nullptr; }

  /// Every key of this table must be one of `accepted`.
  void check_keys(std::initializer_list<std::string_view> accepted) const;
  void check_keys(std::span<const std::string_view> accepted) const;

  // Scalar readers: an absent optional key leaves `value` as it is (the struct's default). Each
  // returns whether the key was present.
  bool read_number(std::string_view key, double& value, const NumberRange& range,
                   Presence presence = Presence::optional) const;
  bool read_integer(std::string_view key, int& value, const IntegerRange& range,
                    Presence presence = Presence::optional) const;
  bool read_bool(std::string_view key, bool& value) const;
  /// A string; unless `allow_empty`, it must not be empty.
  bool read_string(std::string_view key, std::string& value, Presence presence = Presence::optional,
                   bool allow_empty = false) const;
  /// A string that names results (core/result_name.hpp): plain letters, digits, '_', '-', '.'.
  bool read_name(std::string_view key, std::string& value,
                 Presence presence = Presence::optional) const;
  /// A string that must be the name of one of `table`'s choices; stores its value.
  template <typename E>
  bool read_choice(std::string_view key, E& value, std::span<const Choice<E>> table,
                   Presence presence = Presence::optional) const;
  /// An array of min_count..max_count numbers, each in `range`.
  bool read_numbers(std::string_view key, std::vector<double>& values, const NumberRange& range,
                    std::size_t min_count, std::size_t max_count,
                    Presence presence = Presence::optional) const;
  /// An array of three numbers, not all zero, normalised to unit length.
  bool read_direction(std::string_view key, std::array<double, 3>& value) const;

  /// The sub-table `key`, or nullopt when absent and optional.
  std::optional<TomlSection> sub_table(std::string_view key, Presence presence) const;
  /// The tables of the array of tables `key` ([[key]]), each with path "key[i]"; empty if absent.
  std::vector<TomlSection> table_array(std::string_view key) const;

  /// Throws InputError located at `node`, for the key path `key_path`.
  [[noreturn]] void fail_at(const toml::node& node, std::string_view key_path,
                            std::string_view message) const;
  /// Throws "expected <expected>, got <node's value>" for `key` of this table.
  [[noreturn]] void fail_value(std::string_view key, std::string_view expected) const;
  /// Throws "missing required key (expected ...)" for `key` of this table.
  [[noreturn]] void fail_missing(std::string_view key, std::string_view expected) const;
  /// Throws for a key that is present but not allowed here (why = the reason).
  [[noreturn]] void fail_forbidden(std::string_view key, std::string_view why) const;

 private:
  [[noreturn]] void fail_choice(std::string_view key, std::string_view accepted) const;

  const toml::table* table_;
  std::string path_;
  const std::string* file_;
};

/// "file:line:col" when the region is known, else "file"; a region from another source (a
/// command-line override) is named by that source instead.
std::string format_location(const std::string& file, const toml::source_region& region);

template <typename E>
bool TomlSection::read_choice(std::string_view key, E& value, std::span<const Choice<E>> table,
                              Presence presence) const {
  const toml::node* node = find(key);
  if (!node) {
    if (presence == Presence::required) {
      fail_missing(key, "one of " + choice_list(table));
    }
    return false;
  }
  if (const auto* text = node->as_string()) {
    if (const std::optional<E> choice = find_choice(table, text->get())) {
      value = *choice;
      return true;
    }
  }
  fail_choice(key, choice_list(table));
}

}  // namespace sf
