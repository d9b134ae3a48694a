// The field tables of [[load]] and [[initial_velocity]].
#include <fmt/core.h>

#include <cmath>

#include "casefile/case_fields.hpp"
#include "core/errors.hpp"

namespace sf {

namespace {

// An array of 3 components, each a finite number or a string holding an expression of x, y, z
// (core/expression.hpp); absent: left as it is.
void read_field_vector(const TomlSection& s, std::string_view key,
                       std::array<Expression, 3>& value) {
  const toml::node* node = s.find(key);
  if (!node) {
    return;
  }
  const toml::array* array = node->as_array();
  if (!array || array->size() != 3) {
    s.fail_value(key, "an array of 3 numbers or expressions of x, y, z in quotes");
  }
  for (std::size_t i = 0; i < 3; ++i) {
    const toml::node& component = *array->get(i);
    if (const std::optional<double> v = number_of(component)) {
      if (!std::isfinite(*v)) {
        s.fail_value(key, "finite numbers");
      }
      value[i] = Expression::constant(*v);
    } else if (const auto* text = component.as_string()) {
      try {
        value[i] = Expression::parse(text->get());
      } catch (const InputError& e) {
        s.fail_at(component, s.key_path(key), e.what());
      }
    } else {
      s.fail_value(key, "an array of 3 numbers or expressions of x, y, z in quotes");
    }
  }
}

// [a, b, c]: a constant component as its number, an expression as a quoted string.
std::string format_field_vector(const std::array<Expression, 3>& v) {
  std::string out = "[";
  for (std::size_t i = 0; i < 3; ++i) {
    out += i ? ", " : "";
    out += v[i].is_constant() ? format_toml_number(v[i].evaluate(0.0, 0.0, 0.0))
                              : quote_toml_string(v[i].text());
  }
  return out + "]";
}

Field<InitialVelocityConfig> field_vector_field(std::string key,
                                                std::array<Expression, 3> InitialVelocityConfig::*m,
                                                std::string unit, std::string doc) {
  return custom_field<InitialVelocityConfig>(
      {key, "array of 3 floats or expressions", "`[0.0, 0.0, 0.0]`", unit, std::move(doc)},
      [key, m](const TomlSection& s, InitialVelocityConfig& iv, Presence) {
        read_field_vector(s, key, iv.*m);
      },
      [key, m, unit](TomlWriter& w, const InitialVelocityConfig& iv) {
        w.raw(key, format_field_vector(iv.*m), unit);
      });
}

FieldTable<LoadConfig> make_load_fields() {
  using L = LoadConfig;
  static constexpr std::array<Choice<L::Type>, 3> kTypes{{
      {L::Type::force, "force", "N per node"},
      {L::Type::moment, "moment", "N mm per node"},
      {L::Type::pressure, "pressure", "MPa on the top face (+normal side), pushing along -normal"},
  }};
  const auto pressure = [](const L& l) { return l.type == L::Type::pressure; };
  FieldTable<L> t;
  t.push_back(string_field<L>("group", &L::group,
                              "physical group of blank nodes (force, moment) or elements "
                              "(pressure: those whose four nodes lie in the group)")
                  .required());
  t.push_back(choice_field<L, L::Type>("type", &L::type, kTypes, "").required());
  Field<L> value =
      vector_field<L>("value", &L::value, "N or N mm", "3 components per node, global axes")
          .required()
          .when([pressure](const L& l) { return !pressure(l); },
                "`\"force\"` and `\"moment\"` only", "a pressure load takes `pressure` (MPa)");
  value.read = [](const TomlSection& s, L& l, Presence) {
    if (!s.has("value")) {
      s.fail_missing("value", "an array of 3 numbers (N or N mm per node)");
    }
    read_vector(s, "value", l.value);
  };
  t.push_back(std::move(value));
  t.push_back(number_field<L>("pressure", &L::pressure, NumberRange{.unit = "MPa"},
                              "on the top face (+normal side), pushes along -normal")
                  .required()
                  .when(pressure, "`\"pressure\"` only",
                        "a force or moment load takes `value` (3 numbers per node)"));
  t.push_back(curve_field<L>("curve", &L::curve, "scale factor", "empty = 1"));
  return t;
}

FieldTable<InitialVelocityConfig> make_initial_velocity_fields() {
  using I = InitialVelocityConfig;
  FieldTable<I> t;
  t.push_back(string_field<I>("group", &I::group, "absent = every blank node")
                  .shown_default("every node")
                  .write_if([](const I& iv) { return !iv.group.empty(); }));
  t.push_back(field_vector_field(
      "velocity", &I::velocity, "mm/s",
      "global axes; each component a number or an expression of the node's initial x, y, z (mm) "
      "in quotes; at least one of velocity and angular_velocity"));
  t.push_back(field_vector_field("angular_velocity", &I::angular_velocity, "rad/s",
                                 "the nodes' rotational velocities, as velocity"));
  return t;
}

}  // namespace

const FieldTable<LoadConfig>& load_fields() {
  static const FieldTable<LoadConfig> table = make_load_fields();
  return table;
}

const FieldTable<InitialVelocityConfig>& initial_velocity_fields() {
  static const FieldTable<InitialVelocityConfig> table = make_initial_velocity_fields();
  return table;
}

}  // namespace sf
