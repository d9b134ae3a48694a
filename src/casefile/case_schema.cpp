#include "casefile/case_schema.hpp"

#include <fmt/core.h>

#include <cmath>
#include <limits>

namespace sf {

namespace {

std::string bound(double v) {
  return fmt::format("{:g}", v);
}

/// A table cell: '|' escaped so that it does not end the cell.
std::string cell(std::string_view text) {
  std::string out;
  for (const char c : text) {
    out += c == '|' ? std::string("\\|") : std::string(1, c);
  }
  return out;
}

}  // namespace

std::string range_text(const NumberRange& r) {
  const bool has_lo = std::isfinite(r.lo);
  const bool has_hi = std::isfinite(r.hi);
  if (has_lo && has_hi) {
    return fmt::format("in {}{}, {}{}", r.lo_open ? "(" : "[", bound(r.lo), bound(r.hi),
                       r.hi_open ? ")" : "]");
  }
  if (has_lo) {
    return fmt::format("{} {}", r.lo_open ? ">" : ">=", bound(r.lo));
  }
  if (has_hi) {
    return fmt::format("{} {}", r.hi_open ? "<" : "<=", bound(r.hi));
  }
  return "finite";
}

std::string range_text(const IntegerRange& r) {
  const bool has_lo = r.lo > std::numeric_limits<int>::min();
  const bool has_hi = r.hi < std::numeric_limits<int>::max();
  if (has_lo && has_hi) {
    return fmt::format("{} … {}", r.lo, r.hi);
  }
  if (has_lo) {
    return fmt::format(">= {}", r.lo);
  }
  if (has_hi) {
    return fmt::format("<= {}", r.hi);
  }
  return "any";
}

std::string shown_number(double value) {
  return fmt::format("`{}`", format_toml_number(value));
}

std::string join_doc(std::string first, std::string_view second) {
  if (second.empty()) {
    return first;
  }
  if (first.empty()) {
    return std::string(second);
  }
  return fmt::format("{}; {}", first, second);
}

std::string markdown_table(const std::vector<FieldDoc>& docs) {
  std::string text = "| key | type | default | unit | allowed / notes |\n|---|---|---|---|---|\n";
  for (const FieldDoc& d : docs) {
    text += fmt::format("| `{}` | {} | {} | {} | {} |\n", d.key, cell(d.type), cell(d.default_text),
                        d.unit.empty() ? "—" : cell(d.unit), cell(d.allowed));
  }
  return text;
}

}  // namespace sf
