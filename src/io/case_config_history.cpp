#include "io/case_config_history.hpp"

#include <fmt/core.h>

#include <array>
#include <string_view>

#include "io/result_name.hpp"

namespace sf {
namespace {

constexpr std::array<std::string_view, 4> kQuantities{"displacement", "velocity", "rotation",
                                                      "reaction"};

bool& quantity_flag(HistoryGroupConfig& h, std::size_t index) {
  switch (index) {
    case 0:
      return h.displacement;
    case 1:
      return h.velocity;
    case 2:
      return h.rotation;
    default:
      return h.reaction;
  }
}

// The group names a history column: letters, digits, '_', '-', '.' (not first).
bool usable_in_column_names(std::string_view name) {
  return is_plain_name(name) && name.front() != '-';
}

void read_quantities(const TomlSection& s, bool is_static, HistoryGroupConfig& h) {
  const toml::node* node = s.find("quantities");
  if (!node) {
    h.velocity = !is_static;
    return;
  }
  std::string accepted;
  for (const auto name : kQuantities) {
    accepted += fmt::format("{}{}", accepted.empty() ? "" : ", ", quote_toml_string(name));
  }
  const toml::array* array = node->as_array();
  if (!array || array->empty()) {
    s.fail_value("quantities", fmt::format("a non-empty array of {}", accepted));
  }
  h.displacement = h.velocity = h.rotation = h.reaction = false;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& item = *array->get(i);
    const std::string path = fmt::format("{}[{}]", s.key_path("quantities"), i);
    const auto* text = item.as_string();
    std::size_t found = kQuantities.size();
    for (std::size_t q = 0; text && q < kQuantities.size(); ++q) {
      found = text->get() == kQuantities[q] ? q : found;
    }
    if (found == kQuantities.size()) {
      s.fail_at(item, path,
                fmt::format("expected one of {}, got {}", accepted, describe_value(item)));
    }
    bool& flag = quantity_flag(h, found);
    if (flag) {
      s.fail_at(item, path, fmt::format("{} is listed twice", quote_toml_string(text->get())));
    }
    if (found == 1 && is_static) {
      s.fail_at(item, path,
                "a static analysis has no velocities (analysis.type = \"static\"); expected "
                "\"displacement\", \"rotation\" or \"reaction\"");
    }
    flag = true;
  }
}

}  // namespace

void read_history_groups(const TomlSection& top, CaseConfig& config) {
  const bool is_static = config.analysis.type == AnalysisConfig::Type::static_equilibrium;
  const std::vector<TomlSection> sections = top.table_array("history");
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const TomlSection& s = sections[i];
    s.check_keys({"group", "quantities"});
    HistoryGroupConfig h;
    s.read_string("group", h.group, Presence::required);
    if (!usable_in_column_names(h.group)) {
      s.fail_value("group",
                   "a group name that can name history columns (letters, digits, '_', and '-' "
                   "or '.' after the first character)");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (config.history_groups[j].group == h.group) {
        s.fail_at(*s.find("group"), s.key_path("group"),
                  fmt::format("group {} is already recorded by history[{}]",
                              quote_toml_string(h.group), j));
      }
    }
    read_quantities(s, is_static, h);
    config.history_groups.push_back(std::move(h));
  }
}

}  // namespace sf
