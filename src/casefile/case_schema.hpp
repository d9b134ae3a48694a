#pragma once
// The case schema: per case-file section, one table of fields (key, where it goes in the config
// struct, type, range with unit, required or default, a one-line doc, and when the key applies).
// From these tables come the reader's key checks (unknown keys, types, ranges, required keys,
// keys that do not apply), the resolved-case writer and the key tables of docs/case-file.md
// (`sheetform schema --markdown`). Rules between fields (exactly one of end_time and stroke, a
// name that must exist, ...) stay with each section's reader. Not a public interface.
#include <algorithm>
#include <array>
#include <functional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "casefile/case_config.hpp"
#include "casefile/case_config_common.hpp"
#include "casefile/toml_reader.hpp"
#include "casefile/toml_writer.hpp"
#include "core/choice.hpp"

namespace sf {

/// "first; second" (either may be empty).
std::string join_doc(std::string first, std::string_view second);

/// One row of a section's key table in docs/case-file.md.
struct FieldDoc {
  std::string key;
  std::string type;          ///< "float", "integer", "string", "boolean", "array of 3 floats", ...
  std::string default_text;  ///< "`0.9`", "required", or words ("the tool's `name`")
  std::string unit;          ///< "mm", ...; empty = dimensionless ("—")
  std::string allowed;       ///< the allowed values and the one-line doc
};

template <typename S>
using FieldPredicate = std::function<bool(const S&)>;

/// One key of a section: how it is read into S, written from it and documented.
template <typename S>
struct Field {
  FieldDoc doc;
  Presence presence = Presence::optional;
  FieldPredicate<S> applies;  ///< empty = always; read in table order, so it may test earlier keys
  /// Why the key is refused where it does not apply (of the value read so far).
  std::function<std::string(const S&)> not_applicable;
  std::function<void(const TomlSection&, S&, Presence)> read;
  std::function<void(TomlWriter&, const S&)> write;  ///< empty = not written
  FieldPredicate<S> written;                         ///< empty = whenever it applies

  /// Required (where it applies).
  Field required() && {
    presence = Presence::required;
    doc.default_text = "required";
    return std::move(*this);
  }
  /// Applies only where `p` holds; elsewhere the key is an error saying `why`. `condition` is
  /// what the docs show first ("`type = \"force\"` only").
  Field when(FieldPredicate<S> p, std::string condition, std::string why) && {
    applies = std::move(p);
    not_applicable = [why = std::move(why)](const S&) { return why; };
    doc.allowed = join_doc(std::move(condition), doc.allowed);
    return std::move(*this);
  }
  /// The same, with a reason that depends on the keys read before it.
  Field when(FieldPredicate<S> p, std::string condition,
             std::function<std::string(const S&)> why) && {
    applies = std::move(p);
    not_applicable = std::move(why);
    doc.allowed = join_doc(std::move(condition), doc.allowed);
    return std::move(*this);
  }
  /// Written only where `p` holds (e.g. a value that means "not given").
  Field write_if(FieldPredicate<S> p) && {
    written = std::move(p);
    return std::move(*this);
  }
  /// The default as the docs show it, when it is not the struct's value ("the tool's `name`").
  Field shown_default(std::string text) && {
    doc.default_text = std::move(text);
    return std::move(*this);
  }
};

template <typename S>
using FieldTable = std::vector<Field<S>>;

/// The keys of `table` and then `others` (the sub-tables a section reads itself).
template <typename S>
std::vector<std::string_view> field_keys(const FieldTable<S>& table,
                                         std::initializer_list<std::string_view> others = {}) {
  std::vector<std::string_view> keys;
  for (const Field<S>& f : table) {
    if (std::find(keys.begin(), keys.end(), f.doc.key) == keys.end()) {
      keys.push_back(f.doc.key);
    }
  }
  keys.insert(keys.end(), others.begin(), others.end());
  return keys;
}

template <typename S>
std::vector<FieldDoc> field_docs(const FieldTable<S>& table) {
  std::vector<FieldDoc> docs;
  for (const Field<S>& f : table) {
    docs.push_back(f.doc);
  }
  return docs;
}

/// Whether some field of `table` called `key` applies to `value` (one key may be two fields
/// with exclusive conditions: Swift's and Ludwik's `n`).
template <typename S>
bool key_applies(const FieldTable<S>& table, std::string_view key, const S& value) {
  for (const Field<S>& f : table) {
    if (f.doc.key == key && (!f.applies || f.applies(value))) {
      return true;
    }
  }
  return false;
}

/// Reads every field of `table` that applies into `value`, in table order; a key given where it
/// does not apply is an error. Unknown keys are checked by the caller (field_keys).
template <typename S>
void read_fields(const FieldTable<S>& table, const TomlSection& s, S& value) {
  for (const Field<S>& f : table) {
    if (f.applies && !f.applies(value)) {
      if (s.has(f.doc.key) && !key_applies(table, f.doc.key, value)) {
        s.fail_forbidden(f.doc.key, f.not_applicable(value));
      }
      continue;
    }
    f.read(s, value, f.presence);
  }
}

/// Checks the keys of `s` against `table` (and `others`, the sub-tables its caller reads) and
/// reads its fields into `value`.
template <typename S>
void read_table(const TomlSection& s, const FieldTable<S>& table, S& value,
                std::initializer_list<std::string_view> others = {}) {
  s.check_keys(field_keys(table, others));
  read_fields(table, s, value);
}

/// Writes every field of `table` that applies (and is to be written) from `value`.
template <typename S>
void write_fields(const FieldTable<S>& table, TomlWriter& w, const S& value) {
  for (const Field<S>& f : table) {
    const bool applies = !f.applies || f.applies(value);
    if (applies && f.write && (!f.written || f.written(value))) {
      f.write(w, value);
    }
  }
}

/// The fields of a struct T held in S's `member`, as fields of S (a mesh source in a blank).
template <typename S, typename T>
FieldTable<S> embed_fields(const FieldTable<T>& table, T S::*member) {
  FieldTable<S> out;
  for (const Field<T>& f : table) {
    Field<S> g;
    g.doc = f.doc;
    g.presence = f.presence;
    if (f.applies) {
      g.applies = [p = f.applies, member](const S& s) { return p(s.*member); };
      g.not_applicable = [w = f.not_applicable, member](const S& s) { return w(s.*member); };
    }
    g.read = [r = f.read, member](const TomlSection& t, S& s, Presence presence) {
      r(t, s.*member, presence);
    };
    if (f.write) {
      g.write = [w = f.write, member](TomlWriter& writer, const S& s) { w(writer, s.*member); };
    }
    if (f.written) {
      g.written = [p = f.written, member](const S& s) { return p(s.*member); };
    }
    out.push_back(std::move(g));
  }
  return out;
}

// Texts for the docs.
std::string range_text(const NumberRange& range);
std::string range_text(const IntegerRange& range);
/// "`0.9`"
std::string shown_number(double value);
/// doc + ": " + each name with its doc.
template <typename E>
std::string choices_text(std::span<const Choice<E>> table, std::string_view doc) {
  std::string text(doc);
  for (const Choice<E>& c : table) {
    text += fmt::format("{}`\"{}\"`{}", text.empty() ? "" : (&c == table.data() ? ": " : "; "),
                        c.name, c.doc.empty() ? "" : fmt::format(" ({})", c.doc));
  }
  return text;
}
// Field factories. `doc` is the one-line note after the allowed values.

template <typename S>
Field<S> number_field(std::string key, double S::*m, NumberRange range, std::string doc = {}) {
  Field<S> f;
  f.doc = {std::move(key), "float", shown_number(S{}.*m), std::string(range.unit),
           join_doc(range_text(range), doc)};
  f.read = [key = f.doc.key, m, range](const TomlSection& s, S& v, Presence p) {
    s.read_number(key, v.*m, range, p);
  };
  f.write = [key = f.doc.key, m, unit = f.doc.unit](TomlWriter& w, const S& v) {
    w.number(key, v.*m, unit);
  };
  return f;
}

/// A number whose range depends on keys read before it (`range_doc` describes it).
template <typename S>
Field<S> number_field(std::string key, double S::*m, std::function<NumberRange(const S&)> range,
                      std::string unit, std::string range_doc, std::string doc = {}) {
  Field<S> f = number_field<S>(std::move(key), m, NumberRange{}, {});
  f.doc.unit = std::move(unit);
  f.doc.allowed = join_doc(std::move(range_doc), doc);
  f.read = [key = f.doc.key, m, range](const TomlSection& s, S& v, Presence p) {
    s.read_number(key, v.*m, range(v), p);
  };
  return f;
}

template <typename S>
Field<S> integer_field(std::string key, int S::*m, IntegerRange range, std::string doc = {}) {
  Field<S> f;
  f.doc = {std::move(key), "integer", fmt::format("`{}`", S{}.*m), std::string(range.unit),
           join_doc(range_text(range), doc)};
  f.read = [key = f.doc.key, m, range](const TomlSection& s, S& v, Presence p) {
    s.read_integer(key, v.*m, range, p);
  };
  f.write = [key = f.doc.key, m, unit = f.doc.unit](TomlWriter& w, const S& v) {
    w.integer(key, v.*m, unit);
  };
  return f;
}

/// An integer whose range depends on keys read before it (`range_doc` describes it).
template <typename S>
Field<S> integer_field(std::string key, int S::*m, std::function<IntegerRange(const S&)> range,
                       std::string range_doc, std::string doc = {}) {
  Field<S> f = integer_field<S>(std::move(key), m, IntegerRange{}, {});
  f.doc.allowed = join_doc(std::move(range_doc), doc);
  f.read = [key = f.doc.key, m, range](const TomlSection& s, S& v, Presence p) {
    s.read_integer(key, v.*m, range(v), p);
  };
  return f;
}

template <typename S>
Field<S> bool_field(std::string key, bool S::*m, std::string doc) {
  Field<S> f;
  f.doc = {std::move(key), "boolean", (S{}.*m) ? "`true`" : "`false`", {}, std::move(doc)};
  f.read = [key = f.doc.key, m](const TomlSection& s, S& v, Presence) { s.read_bool(key, v.*m); };
  f.write = [key = f.doc.key, m](TomlWriter& w, const S& v) { w.boolean(key, v.*m); };
  return f;
}

/// A string; `allow_empty` lets "" through (a title, a source).
template <typename S>
Field<S> string_field(std::string key, std::string S::*m, std::string doc,
                      bool allow_empty = false) {
  Field<S> f;
  f.doc = {
      std::move(key), "string", fmt::format("`{}`", quote_toml_string(S{}.*m)), {}, std::move(doc)};
  f.read = [key = f.doc.key, m, allow_empty](const TomlSection& s, S& v, Presence p) {
    s.read_string(key, v.*m, p, allow_empty);
  };
  f.write = [key = f.doc.key, m](TomlWriter& w, const S& v) { w.string(key, v.*m); };
  return f;
}

/// A string that names results (core/result_name.hpp).
template <typename S>
Field<S> name_field(std::string key, std::string S::*m, std::string doc) {
  Field<S> f = string_field<S>(std::move(key), m, std::move(doc));
  f.read = [key = f.doc.key, m](const TomlSection& s, S& v, Presence p) {
    s.read_name(key, v.*m, p);
  };
  return f;
}

template <typename S, typename E>
Field<S> choice_field(std::string key, E S::*m, std::span<const Choice<E>> table, std::string doc) {
  Field<S> f;
  f.doc = {std::move(key),
           "string",
           fmt::format("`\"{}\"`", choice_name(table, S{}.*m)),
           {},
           choices_text(table, doc)};
  f.read = [key = f.doc.key, m, table](const TomlSection& s, S& v, Presence p) {
    s.read_choice(key, v.*m, table, p);
  };
  f.write = [key = f.doc.key, m, table](TomlWriter& w, const S& v) {
    w.string(key, choice_name(table, v.*m));
  };
  return f;
}

/// An array of 3 numbers, not all zero, normalised on reading.
template <typename S>
Field<S> direction_field(std::string key, std::array<double, 3> S::*m, std::string doc) {
  Field<S> f;
  const S defaults{};
  const std::array<double, 3>& d = defaults.*m;
  f.doc = {std::move(key),
           "array of 3 floats",
           fmt::format("`[{}, {}, {}]`", format_toml_number(d[0]), format_toml_number(d[1]),
                       format_toml_number(d[2])),
           {},
           join_doc("not all zero, normalised on reading", doc)};
  f.read = [key = f.doc.key, m](const TomlSection& s, S& v, Presence) {
    s.read_direction(key, v.*m);
  };
  f.write = [key = f.doc.key, m](TomlWriter& w, const S& v) { w.vector(key, v.*m); };
  return f;
}

/// An array of 3 finite numbers (any values).
template <typename S>
Field<S> vector_field(std::string key, std::array<double, 3> S::*m, std::string unit,
                      std::string doc) {
  Field<S> f = direction_field<S>(std::move(key), m, {});
  f.doc.unit = std::move(unit);
  f.doc.allowed = std::move(doc);
  f.read = [key = f.doc.key, m](const TomlSection& s, S& v, Presence p) {
    if (p == Presence::required && !s.has(key)) {
      s.fail_missing(key, "an array of 3 numbers");
    }
    read_vector(s, key, v.*m);
  };
  f.write = [key = f.doc.key, m, unit = f.doc.unit](TomlWriter& w, const S& v) {
    w.vector(key, v.*m, unit);
  };
  return f;
}

/// [[time (s), value], ...] points; written when it has any.
template <typename S>
Field<S> curve_field(std::string key, CurveConfig S::*m, std::string value_unit, std::string doc) {
  Field<S> f;
  f.doc = {std::move(key), "array of [time, value]", "none", "s, " + value_unit,
           join_doc("times >= 0, strictly increasing", doc)};
  f.read = [key = f.doc.key, m](const TomlSection& s, S& v, Presence p) {
    if (p == Presence::required || s.has(key)) {
      read_curve(s, key, v.*m);
    }
  };
  f.write = [key = f.doc.key, m, value_unit](TomlWriter& w, const S& v) {
    w.curve(key, v.*m, fmt::format("[[time (s), {}], ...]", value_unit));
  };
  f.written = [m](const S& v) { return !(v.*m).times.empty(); };
  return f;
}

/// An array of min_count..max_count numbers in `range`; written when it has any.
template <typename S>
Field<S> numbers_field(std::string key, std::vector<double> S::*m, NumberRange range,
                       std::size_t min_count, std::size_t max_count, std::string doc) {
  Field<S> f;
  const std::string count = min_count == max_count ? fmt::format("{}", min_count)
                                                   : fmt::format("{} to {}", min_count, max_count);
  f.doc = {std::move(key), fmt::format("array of {} floats", count), "none",
           std::string(range.unit), join_doc(range_text(range), doc)};
  f.read = [key = f.doc.key, m, range, min_count, max_count](const TomlSection& s, S& v,
                                                             Presence p) {
    s.read_numbers(key, v.*m, range, min_count, max_count, p);
  };
  f.write = [key = f.doc.key, m, unit = f.doc.unit](TomlWriter& w, const S& v) {
    w.numbers(key, v.*m, unit);
  };
  f.written = [m](const S& v) { return !(v.*m).empty(); };
  return f;
}

/// A key with its own reader and writer (a table of .geo parameters, local axes, ...).
template <typename S>
Field<S> custom_field(FieldDoc doc, std::function<void(const TomlSection&, S&, Presence)> read,
                      std::function<void(TomlWriter&, const S&)> write) {
  Field<S> f;
  f.doc = std::move(doc);
  f.read = std::move(read);
  f.write = std::move(write);
  return f;
}

/// A section's key table in docs/case-file.md.
std::string markdown_table(const std::vector<FieldDoc>& docs);

}  // namespace sf
