#include "io/case_config_constraints.hpp"

#include <fmt/core.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "core/dof_names.hpp"
#include "io/case_config_common.hpp"

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

/// A symmetry plane or a diaphragm: its normal as `axis` (of `axes` when given) or `normal`.
void read_plane(const TomlSection& s, BoundaryConfig& b) {
  if (s.has("hold")) {
    s.fail_forbidden("hold",
                     "a symmetry plane or a diaphragm holds its own degrees of freedom "
                     "(type = \"hold\" holds a list)");
  }
  if (s.has("normal")) {
    if (s.has("axis")) {
      s.fail_forbidden("axis", "give the plane's normal either as axis or as normal, not both");
    }
    if (s.has("axes")) {
      s.fail_forbidden("axes", "normal is in global components (axes go with axis)");
    }
    std::array<double, 3> normal{};
    s.read_direction("normal", normal);
    b.normal = normal;
    return;
  }
  if (!s.has("axis")) {
    s.fail_missing("axis", R"(one of "x", "y", "z" (or a `normal` vector))");
  }
  s.read_choice("axis", b.axis, {{"x", 0}, {"y", 1}, {"z", 2}});
  read_axes(s, b.axes);
}

BoundaryConfig read_boundary(const TomlSection& s) {
  using Type = BoundaryConfig::Type;
  s.check_keys({"group", "type", "axis", "normal", "hold", "axes"});
  BoundaryConfig b;
  b.line = static_cast<int>(s.table().source().begin.line);
  s.read_string("group", b.group, Presence::required);
  b.type = s.has("hold") ? Type::hold : Type::fixed;
  s.read_choice("type", b.type,
                {{"fixed", Type::fixed},
                 {"symmetry", Type::symmetry},
                 {"diaphragm", Type::diaphragm},
                 {"hold", Type::hold}});
  switch (b.type) {
    case Type::fixed:
      for (const auto key : {"axis", "normal", "hold", "axes"}) {
        if (s.has(key)) {
          s.fail_forbidden(key,
                           "a fixed boundary holds every degree of freedom (axis and normal are "
                           "for symmetry or diaphragm, hold and axes for type = \"hold\")");
        }
      }
      break;
    case Type::symmetry:
    case Type::diaphragm:
      read_plane(s, b);
      break;
    case Type::hold:
      for (const auto key : {"axis", "normal"}) {
        if (s.has(key)) {
          s.fail_forbidden(key,
                           "type = \"hold\" lists its degrees of freedom in `hold` (axis "
                           "and normal are for symmetry or diaphragm)");
        }
      }
      if (!s.has("hold")) {
        s.fail_missing("hold", fmt::format("a non-empty array of {}", kDofChoices));
      }
      read_hold(s, b.hold);
      read_axes(s, b.axes);
      break;
  }
  return b;
}

PrescribedVelocityConfig read_prescribed_velocity(const TomlSection& s) {
  s.check_keys({"group", "velocity", "components", "curve"});
  PrescribedVelocityConfig pv;
  pv.line = static_cast<int>(s.table().source().begin.line);
  s.read_string("group", pv.group, Presence::required);
  if (!s.has("velocity")) {
    s.fail_missing("velocity", "an array of 3 numbers (mm/s)");
  }
  read_vector(s, "velocity", pv.velocity);
  if (const toml::node* node = s.find("components")) {
    const toml::array* array = node->as_array();
    pv.components = {false, false, false};
    bool any = false;
    for (std::size_t i = 0; array && i < array->size(); ++i) {
      const auto* name = array->get(i)->as_string();
      const std::string text = name ? name->get() : "";
      if (text != "x" && text != "y" && text != "z") {
        s.fail_value("components", "an array of \"x\", \"y\", \"z\"");
      }
      pv.components[static_cast<std::size_t>(text[0] - 'x')] = true;
      any = true;
    }
    if (!array || !any) {
      s.fail_value("components", "a non-empty array of \"x\", \"y\", \"z\"");
    }
  }
  if (s.has("curve")) {
    read_curve(s, "curve", pv.curve);
  }
  return pv;
}

PrescribedMotionConfig read_prescribed_motion(const TomlSection& s) {
  using Type = PrescribedMotionConfig::Type;
  s.check_keys({"group", "type", "dof", "value", "curve", "axes"});
  PrescribedMotionConfig pm;
  pm.line = static_cast<int>(s.table().source().begin.line);
  s.read_string("group", pm.group, Presence::required);
  s.read_choice("type", pm.type,
                {{"displacement", Type::displacement}, {"velocity", Type::velocity}});
  s.read_choice("dof", pm.dof, {{"ux", 0}, {"uy", 1}, {"uz", 2}, {"rx", 3}, {"ry", 4}, {"rz", 5}},
                Presence::required);
  const bool rotation = pm.dof >= 3;
  const bool displacement = pm.type == Type::displacement;
  const std::string_view unit =
      displacement ? (rotation ? "rad" : "mm") : (rotation ? "rad/s" : "mm/s");
  if (s.has("value") && s.has("curve")) {
    s.fail_forbidden("value", "give either a constant value or a curve, not both");
  }
  if (s.has("value")) {
    s.read_number("value", pm.value, NumberRange{.unit = unit});
  } else if (s.has("curve")) {
    read_curve(s, "curve", pm.curve);
    if (displacement && pm.curve.values.front() != 0.0) {
      const toml::node& first = *s.find("curve")->as_array()->get(0);
      s.fail_at(first, fmt::format("{}[0]", s.key_path("curve")),
                fmt::format("expected a displacement curve that starts at 0 {} (the initial "
                            "state; the first value is held before the first point), got {}",
                            unit, format_toml_number(pm.curve.values.front())));
    }
  } else {
    s.fail_missing("curve", fmt::format("an array of [time (s), value ({})] points, or a constant "
                                        "`value`",
                                        unit));
  }
  read_axes(s, pm.axes);
  return pm;
}

}  // namespace

void read_constraint_sections(const TomlSection& top, CaseConfig& config) {
  for (const TomlSection& s : top.table_array("boundary")) {
    config.boundaries.push_back(read_boundary(s));
  }
  for (const TomlSection& s : top.table_array("prescribed_velocity")) {
    config.prescribed_velocities.push_back(read_prescribed_velocity(s));
  }
  for (const TomlSection& s : top.table_array("prescribed_motion")) {
    config.prescribed_motions.push_back(read_prescribed_motion(s));
  }
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
