#include "casefile/case_config_history.hpp"

#include <fmt/core.h>

#include <array>
#include <string_view>

#include "casefile/case_fields.hpp"
#include "core/result_name.hpp"

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

std::string accepted_quantities() {
  std::string accepted;
  for (const auto name : kQuantities) {
    accepted += fmt::format("{}{}", accepted.empty() ? "" : ", ", quote_toml_string(name));
  }
  return accepted;
}

// `quantities`: a non-empty list of distinct quantity names (a static analysis's refusal of
// "velocity" is read_history_groups', which knows the analysis).
void read_quantities(const TomlSection& s, HistoryGroupConfig& h) {
  const toml::node* node = s.find("quantities");
  if (!node) {
    return;
  }
  const toml::array* array = node->as_array();
  if (!array || array->empty()) {
    s.fail_value("quantities", fmt::format("a non-empty array of {}", accepted_quantities()));
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
      s.fail_at(
          item, path,
          fmt::format("expected one of {}, got {}", accepted_quantities(), describe_value(item)));
    }
    bool& flag = quantity_flag(h, found);
    if (flag) {
      s.fail_at(item, path, fmt::format("{} is listed twice", quote_toml_string(text->get())));
    }
    flag = true;
  }
}

void write_quantities(TomlWriter& w, const HistoryGroupConfig& h) {
  std::string quantities;
  for (std::size_t q = 0; q < kQuantities.size(); ++q) {
    if (const std::array on{h.displacement, h.velocity, h.rotation, h.reaction}; on[q]) {
      quantities += fmt::format("{}\"{}\"", quantities.empty() ? "" : ", ", kQuantities[q]);
    }
  }
  w.raw("quantities", "[" + quantities + "]");
}

FieldTable<HistoryGroupConfig> make_history_group_fields() {
  using H = HistoryGroupConfig;
  FieldTable<H> t;
  t.push_back(string_field<H>("group", &H::group,
                              "physical group of blank nodes (points, curves or surfaces); used "
                              "once among the `[[history]]` tables; letters, digits, `_`, and "
                              "`-` or `.` after the first character (it names the columns)")
                  .required());
  t.push_back(custom_field<H>(
      {"quantities",
       "array of strings",
       "all (a static analysis: all but `\"velocity\"`)",
       {},
       "any of `\"displacement\"` (mm), `\"velocity\"` (mm/s; explicit runs only), "
       "`\"rotation\"` (rad), `\"reaction\"` (N and N mm), each once"},
      [](const TomlSection& s, H& h, Presence) { read_quantities(s, h); }, write_quantities));
  return t;
}

}  // namespace

const FieldTable<HistoryGroupConfig>& history_group_fields() {
  static const FieldTable<HistoryGroupConfig> table = make_history_group_fields();
  return table;
}

void read_history_groups(const TomlSection& top, CaseConfig& config) {
  const bool is_static = config.analysis.type == AnalysisConfig::Type::static_equilibrium;
  const std::vector<TomlSection> sections = top.table_array("history");
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const TomlSection& s = sections[i];
    HistoryGroupConfig h;
    h.velocity = !is_static;  // the default: every quantity the analysis has
    read_table(s, history_group_fields(), h);
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
    if (is_static && s.has("quantities") && h.velocity) {
      const toml::array& array = *s.find("quantities")->as_array();
      for (std::size_t k = 0; k < array.size(); ++k) {
        if (array.get(k)->value<std::string>() == "velocity") {
          s.fail_at(*array.get(k), fmt::format("{}[{}]", s.key_path("quantities"), k),
                    "a static analysis has no velocities (analysis.type = \"static\"); "
                    "expected \"displacement\", \"rotation\" or \"reaction\"");
        }
      }
    }
    config.history_groups.push_back(std::move(h));
  }
}

}  // namespace sf
