#include "casefile/case_config_constraints.hpp"

#include <fmt/core.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "casefile/case_config_common.hpp"
#include "casefile/case_fields.hpp"
#include "core/dof_names.hpp"

namespace sf {

namespace {

constexpr std::string_view kDofChoices = R"("ux", "uy", "uz", "rx", "ry", "rz")";

/// Axes less than asin(0.1) = 5.7 degrees apart are taken for a mistake, not a frame.
constexpr double kMinimumAxesSine = 0.1;
/// Axes closer to perpendicular than this cosine are kept as given (a resolved case's axes, already
/// made perpendicular, then read back bit for bit).
constexpr double kPerpendicularCosine = 1e-14;

using Vector = std::array<double, 3>;

/// The index 0..5 of a degree-of-freedom name ("ux" ... "rz"), or -1.
int dof_index(std::string_view name) {
  for (int k = 0; k < 6; ++k) {
    if (name == kDofNames[k]) {
      return k;
    }
  }
  return -1;
}

double dot(const Vector& a, const Vector& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// v scaled to unit length; a vector already of unit length (to rounding) is kept as it is, so
/// that normalising is idempotent (as read_direction).
Vector normalised(Vector v) {
  const double length = std::sqrt(dot(v, v));
  if (std::abs(length - 1.0) > 4.0 * std::numeric_limits<double>::epsilon()) {
    for (double& c : v) {
      c /= length;
    }
  }
  return v;
}

/// One axis of `axes`: 3 finite numbers, not all zero, normalised.
Vector read_axis(const TomlSection& s, const toml::node& item, int index) {
  const std::string path = fmt::format("{}[{}]", s.key_path("axes"), index);
  const char* name = index == 0 ? "x" : "y";
  const auto* array = item.as_array();
  bool ok = array && array->size() == 3;
  Vector v{};
  for (std::size_t c = 0; ok && c < 3; ++c) {
    const std::optional<double> number = number_of(*array->get(c));
    ok = number && std::isfinite(*number);
    v[c] = ok ? *number : 0.0;
  }
  if (!ok) {
    s.fail_at(item, path,
              fmt::format("expected the local {} axis as 3 finite numbers (global components), "
                          "got {}",
                          name, describe_value(item)));
  }
  if (!(dot(v, v) > 0.0) || !std::isfinite(dot(v, v))) {
    s.fail_at(item, path,
              fmt::format("expected the local {} axis, a vector not all zero, got {}", name,
                          describe_value(item)));
  }
  return normalised(v);
}

/// `axes = [[x1, x2, x3], [y1, y2, y3]]`: the local x axis, and a second vector whose part
/// perpendicular to x is the local y axis (both normalised); z = x cross y. Axes less than 5.7
/// degrees apart are refused.
void read_axes(const TomlSection& s, std::optional<AxesConfig>& axes) {
  const toml::node* node = s.find("axes");
  if (!node) {
    return;
  }
  const auto* pair = node->as_array();
  if (!pair || pair->size() != 2) {
    s.fail_value("axes",
                 "[[x1, x2, x3], [y1, y2, y3]]: the local x and y axes in global components");
  }
  const Vector x = read_axis(s, *pair->get(0), 0);
  Vector y = read_axis(s, *pair->get(1), 1);
  const double cosine = dot(x, y);
  const double sine = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
  if (sine < kMinimumAxesSine) {
    s.fail_at(*node, s.key_path("axes"),
              fmt::format("expected two axes at least 5.7 degrees apart (the local x axis and a "
                          "vector in the local x-y plane), got axes {:.3g} degrees apart",
                          std::asin(sine) * 180.0 / std::numbers::pi));
  }
  if (std::abs(cosine) > kPerpendicularCosine) {
    for (std::size_t c = 0; c < 3; ++c) {
      y[c] -= cosine * x[c];
    }
    y = normalised(y);
  }
  axes = AxesConfig{.x = x, .y = y};
}

/// `hold = ["ux", "rz", ...]`: a non-empty list of distinct degree-of-freedom names.
void read_hold(const TomlSection& s, std::array<bool, 6>& hold) {
  const toml::node* node = s.find("hold");
  const auto* names = node ? node->as_array() : nullptr;
  if (!names || names->empty()) {
    s.fail_value("hold", fmt::format("a non-empty array of {}", kDofChoices));
  }
  for (std::size_t i = 0; i < names->size(); ++i) {
    const toml::node& item = *names->get(i);
    const std::string path = fmt::format("{}[{}]", s.key_path("hold"), i);
    const auto* text = item.as_string();
    const int k = text ? dof_index(text->get()) : -1;
    if (k < 0) {
      s.fail_at(item, path,
                fmt::format("expected one of {}, got {}", kDofChoices, describe_value(item)));
    }
    if (hold[static_cast<std::size_t>(k)]) {
      s.fail_at(item, path, fmt::format("{} is listed twice", quote_toml_string(kDofNames[k])));
    }
    hold[static_cast<std::size_t>(k)] = true;
  }
}

/// The local frame of `axes`, written as two unit vectors.
void write_axes(TomlWriter& w, const std::optional<AxesConfig>& axes) {
  const auto vector = [](const std::array<double, 3>& v) {
    return fmt::format("[{}, {}, {}]", format_toml_number(v[0]), format_toml_number(v[1]),
                       format_toml_number(v[2]));
  };
  w.raw("axes", fmt::format("[{}, {}]", vector(axes->x), vector(axes->y)));
  w.comment("  local x and y axes (unit, perpendicular); z = x cross y");
}

template <typename S>
Field<S> axes_field(std::string doc) {
  return custom_field<S>(
             {"axes", "`[[x1, x2, x3], [y1, y2, y3]]`", "the global axes", {}, std::move(doc)},
             [](const TomlSection& s, S& v, Presence) { read_axes(s, v.axes); },
             [](TomlWriter& w, const S& v) { write_axes(w, v.axes); })
      .write_if([](const S& v) { return v.axes.has_value(); });
}

constexpr std::array<Choice<int>, 3> kAxisNames{{{0, "x", ""}, {1, "y", ""}, {2, "z", ""}}};
constexpr std::array<Choice<int>, 6> kDofChoiceNames{
    {{0, "ux", ""}, {1, "uy", ""}, {2, "uz", ""}, {3, "rx", ""}, {4, "ry", ""}, {5, "rz", ""}}};

FieldTable<BoundaryConfig> make_boundary_fields() {
  using B = BoundaryConfig;
  using Type = B::Type;
  static constexpr std::array<Choice<Type>, 4> kTypes{{
      {Type::fixed, "fixed", "all six held"},
      {Type::symmetry, "symmetry",
       "the translation along the plane's normal and the rotations about the two in-plane axes"},
      {Type::diaphragm, "diaphragm",
       "the two translations in the plane (rotations free: a diaphragm end)"},
      {Type::hold, "hold", "the degrees of freedom listed in `hold`"},
  }};
  const auto plane = [](const B& b) {
    return b.type == Type::symmetry || b.type == Type::diaphragm;
  };
  // Why a key is refused, by the entry's type (and its normal).
  const auto refused = [](std::string_view key) {
    return [key](const B& b) -> std::string {
      switch (b.type) {
        case Type::fixed:
          return "a fixed boundary holds every degree of freedom (axis and normal are for "
                 "symmetry or diaphragm, hold and axes for type = \"hold\")";
        case Type::hold:
          return "type = \"hold\" lists its degrees of freedom in `hold` (axis and normal are "
                 "for symmetry or diaphragm)";
        default:
          if (key == "hold") {
            return "a symmetry plane or a diaphragm holds its own degrees of freedom (type = "
                   "\"hold\" holds a list)";
          }
          return key == "axis" ? "give the plane's normal either as axis or as normal, not both"
                               : "normal is in global components (axes go with axis)";
      }
    };
  };
  FieldTable<B> t;
  t.push_back(string_field<B>("group", &B::group,
                              "physical group name (points, curve or surface) of blank nodes")
                  .required());
  Field<B> type = choice_field<B, Type>("type", &B::type, kTypes, "")
                      .shown_default("`\"fixed\"`, or `\"hold\"` when `hold` is given");
  type.read = [](const TomlSection& s, B& b, Presence) {
    b.type = s.has("hold") ? Type::hold : Type::fixed;
    s.read_choice<Type>("type", b.type, kTypes);
  };
  t.push_back(std::move(type));
  t.push_back(custom_field<B>(
                  {"hold",
                   "array of strings",
                   "required",
                   {},
                   "the degrees of freedom held, distinct names among " + std::string(kDofChoices) +
                       ", along `axes` when given"},
                  [](const TomlSection& s, B& b, Presence) {
                    if (!s.has("hold")) {
                      s.fail_missing("hold", fmt::format("a non-empty array of {}", kDofChoices));
                    }
                    read_hold(s, b.hold);
                  },
                  [](TomlWriter& w, const B& b) {
                    std::string names;
                    for (int k = 0; k < 6; ++k) {
                      if (b.hold[static_cast<std::size_t>(k)]) {
                        names += fmt::format("{}\"{}\"", names.empty() ? "" : ", ", kDofNames[k]);
                      }
                    }
                    w.raw("hold", "[" + names + "]");
                  })
                  .required()
                  .when([](const B& b) { return b.type == Type::hold; }, "`\"hold\"` only",
                        refused("hold")));
  t.push_back(custom_field<B>(
                  {"normal",
                   "array of 3 floats",
                   "none",
                   {},
                   "instead of `axis`: the plane's normal in global components, for "
                   "a plane not aligned with the global axes. Not all zero; "
                   "normalised on reading. Not with `axes`"},
                  [](const TomlSection& s, B& b, Presence) {
                    if (s.has("normal")) {
                      std::array<double, 3> normal{};
                      s.read_direction("normal", normal);
                      b.normal = normal;
                    }
                  },
                  [](TomlWriter& w, const B& b) {
                    w.vector("normal", *b.normal, "unit vector, the plane's normal");
                  })
                  .when(plane, "`\"symmetry\"` and `\"diaphragm\"` only", refused("normal"))
                  .write_if([](const B& b) { return b.normal.has_value(); }));
  const auto plane_by_axis = [plane](const B& b) { return plane(b) && !b.normal; };
  t.push_back(
      custom_field<B>(
          {"axis",
           "string",
           "required",
           {},
           "`\"x\"`, `\"y\"` or `\"z\"`: the plane's normal, an axis of "
           "`axes` when they are given, else a global axis"},
          [](const TomlSection& s, B& b, Presence) {
            if (!s.has("axis")) {
              s.fail_missing("axis", R"(one of "x", "y", "z" (or a `normal` vector))");
            }
            s.read_choice<int>("axis", b.axis, kAxisNames);
          },
          [](TomlWriter& w, const B& b) { w.string("axis", choice_name<int>(kAxisNames, b.axis)); })
          .when(plane_by_axis, "`\"symmetry\"` and `\"diaphragm\"` without `normal`",
                refused("axis")));
  t.push_back(
      axes_field<B>("a local frame in global components: the first vector is the local x axis; the "
                    "local y axis is the part of the second perpendicular to x; z = x × y. Both "
                    "normalised on reading, neither all zero, at least 5.7° apart")
          .when([plane_by_axis](const B& b) { return b.type == Type::hold || plane_by_axis(b); },
                "with `axis` or `hold`", refused("axes")));
  return t;
}

FieldTable<PrescribedVelocityConfig> make_prescribed_velocity_fields() {
  using P = PrescribedVelocityConfig;
  FieldTable<P> t;
  t.push_back(string_field<P>("group", &P::group, "physical group name of blank nodes").required());
  Field<P> velocity =
      vector_field<P>("velocity", &P::velocity, "mm/s", "the prescribed velocity").required();
  velocity.read = [](const TomlSection& s, P& p, Presence) {
    if (!s.has("velocity")) {
      s.fail_missing("velocity", "an array of 3 numbers (mm/s)");
    }
    read_vector(s, "velocity", p.velocity);
  };
  t.push_back(std::move(velocity));
  t.push_back(custom_field<P>(
      {"components",
       "array of strings",
       "`[\"x\", \"y\", \"z\"]`",
       {},
       "which of `\"x\"`, `\"y\"`, `\"z\"` are prescribed"},
      [](const TomlSection& s, P& p, Presence) {
        const toml::node* node = s.find("components");
        if (!node) {
          return;
        }
        const toml::array* array = node->as_array();
        p.components = {false, false, false};
        bool any = false;
        for (std::size_t i = 0; array && i < array->size(); ++i) {
          const auto* name = array->get(i)->as_string();
          const std::string text = name ? name->get() : "";
          if (text != "x" && text != "y" && text != "z") {
            s.fail_value("components", "an array of \"x\", \"y\", \"z\"");
          }
          p.components[static_cast<std::size_t>(text[0] - 'x')] = true;
          any = true;
        }
        if (!array || !any) {
          s.fail_value("components", "a non-empty array of \"x\", \"y\", \"z\"");
        }
      },
      [](TomlWriter& w, const P& p) {
        std::string components;
        for (int i = 0; i < 3; ++i) {
          if (p.components[static_cast<std::size_t>(i)]) {
            components += fmt::format("{}\"{}\"", components.empty() ? "" : ", ", "xyz"[i]);
          }
        }
        w.raw("components", "[" + components + "]");
      }));
  t.push_back(curve_field<P>("curve", &P::curve, "scale factor", "empty = 1"));
  return t;
}

std::string_view motion_unit(const PrescribedMotionConfig& pm) {
  const bool rotation = pm.dof >= 3;
  if (pm.type == PrescribedMotionConfig::Type::displacement) {
    return rotation ? "rad" : "mm";
  }
  return rotation ? "rad/s" : "mm/s";
}

FieldTable<PrescribedMotionConfig> make_prescribed_motion_fields() {
  using P = PrescribedMotionConfig;
  static constexpr std::array<Choice<P::Type>, 2> kTypes{{
      {P::Type::displacement, "displacement", "mm, or rad for a rotation, from the initial state"},
      {P::Type::velocity, "velocity", "mm/s, rad/s"},
  }};
  FieldTable<P> t;
  t.push_back(string_field<P>("group", &P::group, "physical group name of blank nodes").required());
  t.push_back(choice_field<P, P::Type>("type", &P::type, kTypes, ""));
  t.push_back(choice_field<P, int>("dof", &P::dof, kDofChoiceNames,
                                   "along `axes` when given (a rotation `r*` is about that axis)")
                  .required());
  t.push_back(custom_field<P>(
                  {"value", "float", "none", "mm, rad, mm/s or rad/s",
                   "a constant instead of `curve`: a velocity is held at it; a displacement ramps "
                   "linearly from 0 at time 0 to it at `control.end_time`, in static analyses "
                   "only"},
                  [](const TomlSection& s, P& p, Presence) {
                    if (s.has("value") && s.has("curve")) {
                      s.fail_forbidden("value",
                                       "give either a constant value or a curve, not both");
                    }
                    s.read_number("value", p.value, NumberRange{.unit = motion_unit(p)});
                  },
                  [](TomlWriter& w, const P& p) { w.number("value", p.value, motion_unit(p)); })
                  .write_if([](const P& p) { return p.curve.times.empty(); }));
  t.push_back(
      custom_field<P>(
          {"curve", "array of [time, value]", "none", "s, and mm, rad, mm/s or rad/s",
           "exactly one of `curve` and `value`; times >= 0 and strictly increasing; a "
           "displacement curve starts at 0"},
          [](const TomlSection& s, P& p, Presence) {
            if (s.has("value")) {
              return;
            }
            if (!s.has("curve")) {
              s.fail_missing("curve", fmt::format("an array of [time (s), value ({})] points, or a "
                                                  "constant `value`",
                                                  motion_unit(p)));
            }
            read_curve(s, "curve", p.curve);
            if (p.type == P::Type::displacement && p.curve.values.front() != 0.0) {
              const toml::node& first = *s.find("curve")->as_array()->get(0);
              s.fail_at(first, fmt::format("{}[0]", s.key_path("curve")),
                        fmt::format("expected a displacement curve that starts at 0 {} "
                                    "(the initial state; the first value is held before "
                                    "the first point), got {}",
                                    motion_unit(p), format_toml_number(p.curve.values.front())));
            }
          },
          [](TomlWriter& w, const P& p) {
            w.curve("curve", p.curve, fmt::format("[[time (s), value ({})], ...]", motion_unit(p)));
          })
          .write_if([](const P& p) { return !p.curve.times.empty(); }));
  t.push_back(axes_field<P>("as for `[[boundary]]`"));
  return t;
}

}  // namespace

const FieldTable<BoundaryConfig>& boundary_fields() {
  static const FieldTable<BoundaryConfig> table = make_boundary_fields();
  return table;
}

const FieldTable<PrescribedVelocityConfig>& prescribed_velocity_fields() {
  static const FieldTable<PrescribedVelocityConfig> table = make_prescribed_velocity_fields();
  return table;
}

const FieldTable<PrescribedMotionConfig>& prescribed_motion_fields() {
  static const FieldTable<PrescribedMotionConfig> table = make_prescribed_motion_fields();
  return table;
}

/// Each table of the array of tables `key`, read by `fields` (with its line for messages).
template <typename S>
void read_entries(const TomlSection& top, std::string_view key, const FieldTable<S>& fields,
                  std::vector<S>& out) {
  for (const TomlSection& s : top.table_array(key)) {
    S entry;
    entry.line = static_cast<int>(s.table().source().begin.line);
    read_table(s, fields, entry);
    out.push_back(std::move(entry));
  }
}

void read_constraint_sections(const TomlSection& top, CaseConfig& config) {
  read_entries(top, "boundary", boundary_fields(), config.boundaries);
  read_entries(top, "prescribed_velocity", prescribed_velocity_fields(),
               config.prescribed_velocities);
  read_entries(top, "prescribed_motion", prescribed_motion_fields(), config.prescribed_motions);
}

void check_constraints_for_analysis(const TomlSection& top, const CaseConfig& config) {
  const bool is_static = config.analysis.type == AnalysisConfig::Type::static_equilibrium;
  const std::vector<TomlSection> sections = top.table_array("prescribed_motion");
  for (std::size_t i = 0; i < sections.size() && i < config.prescribed_motions.size(); ++i) {
    const TomlSection& s = sections[i];
    const PrescribedMotionConfig& pm = config.prescribed_motions[i];
    if (is_static && pm.type == PrescribedMotionConfig::Type::velocity) {
      s.fail_at(*s.find("type"), s.key_path("type"),
                "a static analysis prescribes displacements and rotations (its pseudo-time has "
                "no velocities): use type = \"displacement\"");
    }
    if (!is_static && pm.type == PrescribedMotionConfig::Type::displacement &&
        pm.curve.times.empty()) {
      s.fail_at(*s.find("value"), s.key_path("value"),
                "an explicit run needs a `curve` for a prescribed displacement (a constant value "
                "would be a jump at time 0), e.g. curve = [[0.0, 0.0], [t, value]]; a constant "
                "`value` ramps from 0 in static analyses only");
    }
  }
}

}  // namespace sf
