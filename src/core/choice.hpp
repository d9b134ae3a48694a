#pragma once
// A choice's one name table: each value of an enum with the name a case file, the command line
// and the messages use for it, and a one-line doc (docs/case-file.md is generated from it). The
// table lives beside its enum; everything that reads or prints the choice goes through it.
#include <fmt/core.h>

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sf {

template <typename E>
struct Choice {
  E value;
  std::string_view name;
  std::string_view doc;  ///< one line, shown in docs/case-file.md; may be empty
};

/// The name of `value` in `table` ("?" if it is not there: a table missing a value is a bug that
/// test_choices.cpp catches).
template <typename E>
std::string_view choice_name(std::span<const Choice<E>> table, E value) {
  for (const Choice<E>& c : table) {
    if (c.value == value) {
      return c.name;
    }
  }
  return "?";
}

/// The value named `name`, or nullopt.
template <typename E>
std::optional<E> find_choice(std::span<const Choice<E>> table, std::string_view name) {
  for (const Choice<E>& c : table) {
    if (c.name == name) {
      return c.value;
    }
  }
  return std::nullopt;
}

/// The names, each in `quote` marks, separated by ", ": "\"a\", \"b\"" or "a, b".
template <typename E>
std::string choice_list(std::span<const Choice<E>> table, std::string_view quote = "\"") {
  std::string text;
  for (const Choice<E>& c : table) {
    text += fmt::format("{}{}{}{}", text.empty() ? "" : ", ", quote, c.name, quote);
  }
  return text;
}

/// The names alone, e.g. for a command-line option's accepted values.
template <typename E>
std::vector<std::string> choice_names(std::span<const Choice<E>> table) {
  std::vector<std::string> names;
  for (const Choice<E>& c : table) {
    names.emplace_back(c.name);
  }
  return names;
}

}  // namespace sf
