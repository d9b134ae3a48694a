#include "casefile/case_overrides.hpp"

#include <fmt/core.h>

#include <charconv>
#include <cmath>
#include <memory>
#include <string_view>

#include "casefile/toml_reader.hpp"
#include "core/errors.hpp"

namespace sf {
namespace {

/// One part of a key path: a key, and an index when it names an element of an array of tables.
struct KeyPart {
  std::string key;
  long index = -1;  ///< -1: no index
};

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) {
    return {};
  }
  const auto last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

bool is_bare_key(std::string_view key) {
  return !key.empty() && key.find_first_not_of(
                             "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
                             "abcdefghijklmnopqrstuvwxyz"
                             "0123456789_-") == std::string_view::npos;
}

/// "tools[1].parameters.n" -> {tools, 1}, {parameters}, {n}; nullopt-like empty on a bad path.
std::vector<KeyPart> split_key_path(std::string_view path, const std::string& override_text) {
  const auto fail = [&](std::string_view why) -> std::vector<KeyPart> {
    throw InputError(fmt::format("--set {}: {}", override_text, why));
  };
  std::vector<KeyPart> parts;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t dot = std::min(path.find('.', start), path.size());
    std::string_view part = path.substr(start, dot - start);
    KeyPart kp;
    if (const auto open = part.find('['); open != std::string_view::npos) {
      if (part.back() != ']') {
        return fail(fmt::format("'{}': expected KEY[INDEX]", part));
      }
      const std::string_view digits = part.substr(open + 1, part.size() - open - 2);
      const auto [end, error] =
          std::from_chars(digits.data(), digits.data() + digits.size(), kp.index);
      if (error != std::errc() || end != digits.data() + digits.size() || kp.index < 0) {
        return fail(fmt::format("'{}': expected an index >= 0 in [ ]", part));
      }
      part = part.substr(0, open);
    }
    if (!is_bare_key(part)) {
      return fail(fmt::format("'{}' is not a key (letters, digits, '_', '-')", part));
    }
    kp.key = std::string(part);
    parts.push_back(std::move(kp));
    start = dot + 1;
  }
  if (parts.back().index >= 0) {
    return fail("the last part of KEY must be a key, not an array element");
  }
  return parts;
}

/// The table KEY's last part goes into, created where missing.
toml::table& parent_table(toml::table& root, const std::vector<KeyPart>& parts,
                          const std::string& override_text) {
  toml::table* table = &root;
  std::string walked;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    const KeyPart& part = parts[i];
    walked += (walked.empty() ? "" : ".") + part.key;
    toml::node* node = table->get(part.key);
    if (part.index >= 0) {
      toml::array* array = node ? node->as_array() : nullptr;
      const std::size_t size = array ? array->size() : 0;
      if (!array || static_cast<std::size_t>(part.index) >= size ||
          !array->get(static_cast<std::size_t>(part.index))->is_table()) {
        throw InputError(fmt::format("--set {}: the case has no {}[{}] (it has {} [[{}]] table{})",
                                     override_text, walked, part.index, size, part.key,
                                     size == 1 ? "" : "s"));
      }
      table = array->get(static_cast<std::size_t>(part.index))->as_table();
      walked += fmt::format("[{}]", part.index);
      continue;
    }
    if (!node) {
      node = table->insert_or_assign(part.key, toml::table{}).first->second.as_table();
    }
    if (!node->is_table()) {
      throw InputError(
          fmt::format("--set {}: {} is not a table in the case", override_text, walked));
    }
    table = node->as_table();
  }
  return *table;
}

/// Moves `node` (a parsed value, keeping its source for messages) to the key `parts` names.
void insert_value(toml::table& root, const std::vector<KeyPart>& parts, const std::string& text,
                  toml::node& node) {
  toml::table& parent = parent_table(root, parts, text);
  node.visit([&](auto&& v) { parent.insert_or_assign(parts.back().key, std::move(v)); });
}

/// Sets a run option's value as an override, its source the option (for messages).
void set_option(toml::table& root, std::string_view option, std::string_view key,
                std::string_view value) {
  const std::string text = fmt::format("{}={}", key, value);
  toml::table parsed =
      toml::parse(fmt::format("value = {}", value),
                  std::string_view(fmt::format("command line ({} {})", option, value)));
  insert_value(root, split_key_path(key, text), text, *parsed.get("value"));
}

void check_positive(std::string_view option, double value, std::string_view unit) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InputError(fmt::format("{} {}: expected a finite value > 0 ({})", option, value, unit));
  }
}

}  // namespace

void apply_run_options(toml::table& root, const CaseOptions& options, const std::string& file) {
  if (options.stroke && options.end_time) {
    throw InputError("give --stroke or --end-time, not both");
  }
  if (options.stroke) {
    check_positive("--stroke", *options.stroke, "mm of the moving tool's travel");
    set_option(root, "--stroke", "control.stroke", format_toml_number(*options.stroke));
    root["control"].as_table()->erase("end_time");
  }
  if (options.end_time) {
    check_positive("--end-time", *options.end_time, "s");
    set_option(root, "--end-time", "control.end_time", format_toml_number(*options.end_time));
    root["control"].as_table()->erase("stroke");
  }
  if (options.search) {
    toml::array* contacts = root["contact"].as_array();
    if (!contacts || contacts->empty()) {
      throw InputError(file + ": --search needs a [[contact]] (the case has none)");
    }
    const std::string_view name =
        choice_name<ContactSearchKind>(kContactSearchNames, *options.search);
    for (std::size_t i = 0; i < contacts->size(); ++i) {
      set_option(root, "--search", fmt::format("contact[{}].search", i), quote_toml_string(name));
      if (*options.search != ContactSearchKind::cached) {
        contacts->get(i)->as_table()->erase("search_margin");  // a cached-search option only
      }
    }
  }
}

void apply_case_overrides(toml::table& root, const std::vector<std::string>& overrides) {
  for (const std::string& text : overrides) {
    const auto equals = text.find('=');
    if (equals == std::string::npos) {
      throw InputError(
          fmt::format("--set {}: expected KEY=VALUE, e.g. blank.parameters.n=32", text));
    }
    const std::string_view key = trim(std::string_view(text).substr(0, equals));
    const std::string_view value = trim(std::string_view(text).substr(equals + 1));
    const std::vector<KeyPart> parts = split_key_path(key, text);
    const std::string source = fmt::format("command line (--set {})", text);
    toml::table parsed;
    try {
      parsed = toml::parse(fmt::format("value = {}", value), std::string_view(source));
    } catch (const toml::parse_error& error) {
      throw InputError(
          fmt::format("--set {}: '{}' is not a TOML value ({}); write strings in quotes, e.g. "
                      "--set 'title=\"run 2\"'",
                      text, value, error.description()));
    }
    toml::node* node = parsed.get("value");
    if (!node || parsed.size() != 1) {
      throw InputError(fmt::format("--set {}: expected one TOML value after '='", text));
    }
    insert_value(root, parts, text, *node);
  }
}

}  // namespace sf
