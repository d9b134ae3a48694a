#include "casefile/toml_reader.hpp"

#include <fmt/core.h>

#include <cmath>

#include "core/errors.hpp"
#include "core/result_name.hpp"

namespace sf {

namespace {

std::string format_bound(double v) {
  return fmt::format("{}", v);
}

std::string with_unit(std::string text, std::string_view unit) {
  if (!unit.empty()) {
    text += fmt::format(" ({})", unit);
  }
  return text;
}

std::string type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
    default:
      return "a value";
  }
}

}  // namespace

bool NumberRange::contains(double v) const {
  if (!std::isfinite(v)) {
    return false;
  }
  const bool above = lo_open ? v > lo : v >= lo;
  const bool below = hi_open ? v < hi : v <= hi;
  return above && below;
}

std::string NumberRange::describe() const {
  const bool has_lo = std::isfinite(lo);
  const bool has_hi = std::isfinite(hi);
  std::string text = "a number";
  if (has_lo && has_hi) {
    text += fmt::format(" in {}{}, {}{}", lo_open ? "(" : "[", format_bound(lo), format_bound(hi),
                        hi_open ? ")" : "]");
  } else if (has_lo) {
    text += fmt::format(" {} {}", lo_open ? ">" : ">=", format_bound(lo));
  } else if (has_hi) {
    text += fmt::format(" {} {}", hi_open ? "<" : "<=", format_bound(hi));
  }
  return with_unit(text, unit);
}

NumberRange greater_than(double lo, std::string_view unit) {
  return NumberRange{.lo = lo, .lo_open = true, .unit = unit};
}

NumberRange at_least(double lo, std::string_view unit) {
  return NumberRange{.lo = lo, .unit = unit};
}

NumberRange interval(double lo, bool lo_open, double hi, bool hi_open, std::string_view unit) {
  return NumberRange{.lo = lo, .hi = hi, .lo_open = lo_open, .hi_open = hi_open, .unit = unit};
}

std::string IntegerRange::describe() const {
  std::string text = "an integer";
  const bool has_hi = hi < std::numeric_limits<int>::max();
  const bool has_lo = lo > std::numeric_limits<int>::min();
  if (has_lo && has_hi) {
    text += fmt::format(" in [{}, {}]", lo, hi);
  } else if (has_lo) {
    text += fmt::format(" >= {}", lo);
  } else if (has_hi) {
    text += fmt::format(" <= {}", hi);
  }
  return with_unit(text, unit);
}

std::string describe_value(const toml::node& node) {
  if (const auto* v = node.as_floating_point()) {
    return std::isfinite(v->get()) ? format_toml_number(v->get()) : fmt::format("{}", v->get());
  }
  if (const auto* v = node.as_integer()) {
    return fmt::format("{}", v->get());
  }
  if (const auto* v = node.as_string()) {
    return "the string " + quote_toml_string(v->get());
  }
  if (const auto* v = node.as_boolean()) {
    return v->get() ? "true" : "false";
  }
  if (const auto* v = node.as_array(); v && v->size() <= 8) {
    std::string items;
    for (const toml::node& item : *v) {
      items += items.empty() ? "" : ", ";
      items += item.is_string() ? quote_toml_string(item.as_string()->get()) : describe_value(item);
    }
    return fmt::format("[{}]", items);
  }
  return type_name(node);
}

std::string quote_toml_string(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
          out += fmt::format("\\u{:04X}", static_cast<unsigned>(static_cast<unsigned char>(c)));
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string format_toml_number(double value) {
  std::string text = fmt::format("{}", value);
  if (text.find_first_of(".eEn") == std::string::npos) {
    text += ".0";
  }
  return text;
}

std::optional<double> number_of(const toml::node& node) {
  if (const auto* v = node.as_floating_point()) {
    return v->get();
  }
  if (const auto* v = node.as_integer()) {
    return static_cast<double>(v->get());
  }
  return std::nullopt;
}

std::string format_location(const std::string& file, const toml::source_region& region) {
  if (region.path && *region.path != file) {
    return *region.path;  // a value from elsewhere: a command-line override (apply_case_overrides)
  }
  if (region.begin.line == 0) {
    return file;
  }
  return fmt::format("{}:{}:{}", file, region.begin.line, region.begin.column);
}

std::string TomlSection::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : fmt::format("{}.{}", path_, key);
}

void TomlSection::check_keys(std::initializer_list<std::string_view> accepted) const {
  check_keys(std::span<const std::string_view>(accepted.begin(), accepted.size()));
}

void TomlSection::check_keys(std::span<const std::string_view> accepted) const {
  for (const auto& [key, node] : *table_) {
    bool known = false;
    for (const auto name : accepted) {
      known = known || key.str() == name;
    }
    if (known) {
      continue;
    }
    std::string list;
    for (const auto name : accepted) {
      list += list.empty() ? "" : ", ";
      list += name;
    }
    const auto& region = key.source().begin.line != 0 ? key.source() : node.source();
    throw InputError(fmt::format("{}: {}: unknown key; accepted keys here: {}",
                                 format_location(*file_, region), key_path(key.str()), list));
  }
}

bool TomlSection::read_number(std::string_view key, double& value, const NumberRange& range,
                              Presence presence) const {
  const toml::node* node = find(key);
  if (!node) {
    if (presence == Presence::required) {
      fail_missing(key, range.describe());
    }
    return false;
  }
  const std::optional<double> number = number_of(*node);
  if (!number || !range.contains(*number)) {
    fail_value(key, range.describe());
  }
  value = *number;
  return true;
}

bool TomlSection::read_integer(std::string_view key, int& value, const IntegerRange& range,
                               Presence presence) const {
  const toml::node* node = find(key);
  if (!node) {
    if (presence == Presence::required) {
      fail_missing(key, range.describe());
    }
    return false;
  }
  const auto* integer = node->as_integer();
  if (integer && integer->get() > range.hi && range.hi == std::numeric_limits<int>::max()) {
    // The range's text leaves out the type's own bound; a value beyond it is told the bound.
    fail_value(key, fmt::format("{}, at most {} (the largest this key holds{}{})", range.describe(),
                                range.hi, range.limit_note.empty() ? "" : "; ", range.limit_note));
  }
  if (!integer || !range.contains(integer->get())) {
    fail_value(key, range.describe());
  }
  value = static_cast<int>(integer->get());
  return true;
}

bool TomlSection::read_bool(std::string_view key, bool& value) const {
  const toml::node* node = find(key);
  if (!node) {
    return false;
  }
  const auto* boolean = node->as_boolean();
  if (!boolean) {
    fail_value(key, "true or false");
  }
  value = boolean->get();
  return true;
}

bool TomlSection::read_string(std::string_view key, std::string& value, Presence presence,
                              bool allow_empty) const {
  const std::string_view expected = allow_empty ? "a string" : "a non-empty string";
  const toml::node* node = find(key);
  if (!node) {
    if (presence == Presence::required) {
      fail_missing(key, expected);
    }
    return false;
  }
  const auto* text = node->as_string();
  if (!text || (!allow_empty && text->get().empty())) {
    fail_value(key, expected);
  }
  // A NUL cuts a path short where the system reads it (a mesh "blank\u0000.msh" made gmsh wait):
  // no case-file text has one.
  if (text->get().find('\0') != std::string::npos) {
    fail_value(key, std::string(expected) + " without a NUL character (\\u0000)");
  }
  value = text->get();
  return true;
}

bool TomlSection::read_name(std::string_view key, std::string& value, Presence presence) const {
  if (!read_string(key, value, presence)) {
    return false;
  }
  if (!is_plain_name(value)) {
    fail_value(key, "a name of " + std::string(kPlainNameRule));
  }
  return true;
}

bool TomlSection::read_numbers(std::string_view key, std::vector<double>& values,
                               const NumberRange& range, std::size_t min_count,
                               std::size_t max_count, Presence presence) const {
  const std::string expected =
      min_count == max_count ? fmt::format("an array of {} numbers", min_count)
                             : fmt::format("an array of {} to {} numbers", min_count, max_count);
  const toml::node* node = find(key);
  if (!node) {
    if (presence == Presence::required) {
      fail_missing(key, expected);
    }
    return false;
  }
  const auto* array = node->as_array();
  if (!array || array->size() < min_count || array->size() > max_count) {
    fail_value(key, expected);
  }
  std::vector<double> read;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const std::optional<double> number = number_of(*array->get(i));
    if (!number || !range.contains(*number)) {
      fail_at(*array->get(i), fmt::format("{}[{}]", key_path(key), i),
              fmt::format("expected {}, got {}", range.describe(), describe_value(*array->get(i))));
    }
    read.push_back(*number);
  }
  values = std::move(read);
  return true;
}

bool TomlSection::read_direction(std::string_view key, std::array<double, 3>& value) const {
  constexpr std::string_view expected = "an array of 3 numbers, not all zero";
  const toml::node* node = find(key);
  if (!node) {
    return false;
  }
  const auto* array = node->as_array();
  if (!array || array->size() != 3) {
    fail_value(key, expected);
  }
  std::array<double, 3> d{};
  for (std::size_t i = 0; i < 3; ++i) {
    const std::optional<double> number = number_of(*array->get(i));
    if (!number || !std::isfinite(*number)) {
      fail_at(*array->get(i), fmt::format("{}[{}]", key_path(key), i),
              fmt::format("expected a finite number, got {}", describe_value(*array->get(i))));
    }
    d[i] = *number;
  }
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(length > 0.0) || !std::isfinite(length)) {
    fail_value(key, expected);
  }
  // A vector already of unit length (to rounding) is kept as it is, so that normalising is
  // idempotent and a resolved case reads back bit for bit.
  if (std::abs(length - 1.0) > 4.0 * std::numeric_limits<double>::epsilon()) {
    for (double& c : d) {
      c /= length;
    }
  }
  value = d;
  return true;
}

std::optional<TomlSection> TomlSection::sub_table(std::string_view key, Presence presence) const {
  const toml::node* node = find(key);
  if (!node) {
    if (presence == Presence::required) {
      fail_missing(key, "a table");
    }
    return std::nullopt;
  }
  const auto* table = node->as_table();
  if (!table) {
    fail_value(key, "a table");
  }
  return TomlSection(*table, key_path(key), *file_);
}

std::vector<TomlSection> TomlSection::table_array(std::string_view key) const {
  std::vector<TomlSection> sections;
  const toml::node* node = find(key);
  if (!node) {
    return sections;
  }
  const auto* array = node->as_array();
  if (!array) {
    fail_value(key, fmt::format("an array of tables ([[{}]])", key));
  }
  for (std::size_t i = 0; i < array->size(); ++i) {
    const std::string path = fmt::format("{}[{}]", key_path(key), i);
    const auto* table = array->get(i)->as_table();
    if (!table) {
      fail_at(*array->get(i), path,
              fmt::format("expected a table, got {}", describe_value(*array->get(i))));
    }
    sections.emplace_back(*table, path, *file_);
  }
  return sections;
}

void TomlSection::fail_at(const toml::node& node, std::string_view key_path,
                          std::string_view message) const {
  throw InputError(
      fmt::format("{}: {}: {}", format_location(*file_, node.source()), key_path, message));
}

void TomlSection::fail_value(std::string_view key, std::string_view expected) const {
  const toml::node& node = *find(key);
  fail_at(node, key_path(key), fmt::format("expected {}, got {}", expected, describe_value(node)));
}

void TomlSection::fail_missing(std::string_view key, std::string_view expected) const {
  if (path_.empty()) {  // the root table's region is just the start of the file
    throw InputError(fmt::format("{}: {}: missing required key at the top level (expected {})",
                                 *file_, key, expected));
  }
  fail_at(*table_, key_path(key),
          fmt::format("missing required key in [{}] (expected {})", path_, expected));
}

void TomlSection::fail_forbidden(std::string_view key, std::string_view why) const {
  fail_at(*find(key), key_path(key), fmt::format("not allowed here: {}", why));
}

void TomlSection::fail_choice(std::string_view key, std::string_view accepted) const {
  fail_value(key, fmt::format("one of {}", accepted));
}

}  // namespace sf
