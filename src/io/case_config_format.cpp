// format_resolved_case: CaseConfig -> TOML text that read_case reads back to the same CaseConfig.
// Every key is written (defaults included, paths absolute); the units go in comments.
#include <fmt/core.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "core/dof_names.hpp"
#include "io/case_config.hpp"
#include "io/toml_reader.hpp"

namespace sf {

namespace {

/// Appends TOML lines to a string.
class TomlWriter {
 public:
  void comment(std::string_view text) { line(fmt::format("# {}", text)); }
  void header(std::string_view name) { line(fmt::format("\n[{}]", name)); }
  void array_header(std::string_view name) { line(fmt::format("\n[[{}]]", name)); }

  void string(std::string_view key, std::string_view value) {
    entry(key, quote_toml_string(value), {});
  }
  void number(std::string_view key, double value, std::string_view unit = {}) {
    entry(key, format_toml_number(value), unit);
  }
  void integer(std::string_view key, long long value, std::string_view unit = {}) {
    entry(key, fmt::format("{}", value), unit);
  }
  void raw(std::string_view key, std::string_view value, std::string_view unit = {}) {
    entry(key, value, unit);
  }
  void boolean(std::string_view key, bool value) { entry(key, value ? "true" : "false", {}); }
  void vector(std::string_view key, const std::array<double, 3>& v,
              std::string_view unit = "unit vector") {
    entry(key,
          fmt::format("[{}, {}, {}]", format_toml_number(v[0]), format_toml_number(v[1]),
                      format_toml_number(v[2])),
          unit);
  }
  void curve(std::string_view key, const CurveConfig& curve, std::string_view unit) {
    std::string points;
    for (std::size_t i = 0; i < curve.times.size(); ++i) {
      points += fmt::format("{}[{}, {}]", i == 0 ? "" : ", ", format_toml_number(curve.times[i]),
                            format_toml_number(curve.values[i]));
    }
    entry(key, fmt::format("[{}]", points), unit);
  }

  void points(std::string_view key, const std::vector<std::array<double, 2>>& points,
              std::string_view unit) {
    std::string text;
    for (std::size_t i = 0; i < points.size(); ++i) {
      text += fmt::format("{}[{}, {}]", i == 0 ? "" : ", ", format_toml_number(points[i][0]),
                          format_toml_number(points[i][1]));
    }
    entry(key, fmt::format("[{}]", text), unit);
  }

  void numbers(std::string_view key, const std::vector<double>& values,
               std::string_view unit = {}) {
    std::string text;
    for (std::size_t i = 0; i < values.size(); ++i) {
      text += fmt::format("{}{}", i == 0 ? "" : ", ", format_toml_number(values[i]));
    }
    entry(key, fmt::format("[{}]", text), unit);
  }

  std::string take() { return std::move(text_); }

 private:
  void line(std::string_view text) {
    text_ += text;
    text_ += '\n';
  }
  void entry(std::string_view key, std::string_view value, std::string_view unit) {
    std::string text = fmt::format("{} = {}", key, value);
    if (!unit.empty()) {
      text = fmt::format("{:<32}# {}", text + " ", unit);
    }
    line(text);
  }

  std::string text_;
};

/// A key as TOML writes it: bare when it can be, quoted otherwise.
std::string format_key(std::string_view key) {
  const bool bare = !key.empty() && key.find_first_not_of(
                                        "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                        "abcdefghijklmnopqrstuvwxyz"
                                        "0123456789_-") == std::string::npos;
  return bare ? std::string(key) : quote_toml_string(key);
}

void write_mesh_source(TomlWriter& w, const MeshSourceConfig& mesh) {
  w.string("mesh", mesh.file.string());
  w.string("group", mesh.group);
  w.number("element_size", mesh.element_size, "mm; 0 = the .geo file's own sizes");
  if (!mesh.parameters.empty()) {
    std::string table;
    for (const GeoParameter& p : mesh.parameters) {
      table +=
          fmt::format("{}{} = {}", table.empty() ? "" : ", ", p.name, format_toml_number(p.value));
    }
    w.raw("parameters", "{ " + table + " }");
  }
  if (mesh.scale != 1.0) {
    w.number("scale", mesh.scale, "lengths of the file multiplied by it");
  }
  if (mesh.curvature_elements > 0) {
    w.integer("curvature_elements", mesh.curvature_elements, "elements per 2 pi of curvature");
  }
  if (!mesh.surfaces.empty()) {
    std::vector<double> tags(mesh.surfaces.begin(), mesh.surfaces.end());
    w.numbers("surfaces", tags, "the file's surface tags that form the part");
  }
}

void write_blank(TomlWriter& w, const BlankConfig& blank) {
  w.header("blank");
  write_mesh_source(w, blank.mesh);
  w.string("element", blank.element);
  w.number("thickness", blank.thickness, "mm");
  w.integer("integration_points", blank.integration_points, "through the thickness");
  const bool lobatto = blank.integration_rule == BlankConfig::IntegrationRule::lobatto;
  w.string("integration_rule", lobatto ? "lobatto" : "gauss");
  w.string("material", blank.material);
  if (blank.formulation == BlankConfig::Formulation::assumed_strain) {
    w.string("formulation", "assumed_strain");
  } else {
    w.string("formulation", "belytschko_tsay");
    w.number("hourglass", blank.hourglass_coefficient, "hourglass coefficient");
    const bool stiffness = blank.hourglass_form == BlankConfig::HourglassForm::stiffness;
    w.string("hourglass_form", stiffness ? "stiffness" : "viscous");
  }
  w.vector("rolling_direction", blank.rolling_direction, "unit vector; used by hill48 only");
}

std::string_view material_type_name(MaterialConfig::Type type) {
  switch (type) {
    case MaterialConfig::Type::elastic:
      return "elastic";
    case MaterialConfig::Type::von_mises:
      return "von_mises";
    case MaterialConfig::Type::hill48:
      return "hill48";
    case MaterialConfig::Type::yld2000:
      return "yld2000";
    case MaterialConfig::Type::yld89:
      return "yld89";
  }
  return "von_mises";
}

void write_hardening(TomlWriter& w, const HardeningConfig& h) {
  switch (h.law) {
    case HardeningConfig::Law::swift:
      w.string("law", "swift");
      w.number("K", h.swift_k, "MPa; sigma_y = K (eps0 + eps_p)^n");
      w.number("eps0", h.swift_eps0);
      w.number("n", h.swift_n);
      return;
    case HardeningConfig::Law::linear:
      w.string("law", "linear");
      w.number("yield_stress", h.yield_stress, "MPa; sigma_y = yield_stress + modulus eps_p");
      w.number("modulus", h.modulus, "MPa");
      return;
    case HardeningConfig::Law::voce:
      w.string("law", "voce");
      w.number("sigma0", h.voce_sigma0, "MPa; sigma_y = sigma0 + Q (1 - exp(-b eps_p))");
      w.number("Q", h.voce_q, "MPa");
      w.number("b", h.voce_b);
      return;
    case HardeningConfig::Law::ludwik:
      w.string("law", "ludwik");
      w.number("A", h.ludwik_a, "MPa; sigma_y = A + B eps_p^n");
      w.number("B", h.ludwik_b, "MPa");
      w.number("n", h.ludwik_n);
      return;
    case HardeningConfig::Law::hockett_sherby:
      w.string("law", "hockett_sherby");
      w.number("sigma_s", h.hs_sigma_s,
               "MPa; sigma_y = sigma_s - (sigma_s - sigma_i) exp(-N eps_p^p)");
      w.number("sigma_i", h.hs_sigma_i, "MPa");
      w.number("N", h.hs_n);
      w.number("p", h.hs_p);
      return;
    case HardeningConfig::Law::swift_voce:
      w.string("law", "swift_voce");
      w.number("weight", h.sv_weight, "sigma_y = weight Swift + (1 - weight) Voce");
      w.number("K", h.swift_k, "MPa; Swift: K (eps0 + eps_p)^n");
      w.number("eps0", h.swift_eps0);
      w.number("n", h.swift_n);
      w.number("sigma0", h.voce_sigma0, "MPa; Voce: sigma0 + Q (1 - exp(-b eps_p))");
      w.number("Q", h.voce_q, "MPa");
      w.number("b", h.voce_b);
      return;
    case HardeningConfig::Law::tabulated:
      w.string("law", "tabulated");
      w.string("file", h.table_file.string());
      return;
  }
}

void write_anisotropy(TomlWriter& w, const MaterialConfig& material) {
  using Type = MaterialConfig::Type;
  if (material.type == Type::yld2000 || material.type == Type::yld89) {
    w.number("exponent", material.exponent, "Barlat's exponent (a, or M for Yld89)");
  }
  if (material.type == Type::yld2000 && !material.alpha.empty()) {
    w.numbers("alpha", material.alpha, "Yld2000-2d alpha_1..alpha_8, given directly");
    return;
  }
  if (material.type == Type::yld2000) {
    w.number("sigma0", material.sigma0,
             "the data Yld2000-2d is fitted to (stresses: ratios count)");
    w.number("sigma45", material.sigma45);
    w.number("sigma90", material.sigma90);
    w.number("sigma_b", material.sigma_b);
  }
  if (material.type == Type::hill48 || material.type == Type::yld89 ||
      material.type == Type::yld2000) {
    w.number("r0", material.r0, "Lankford coefficient at 0 deg to the rolling direction");
    w.number("r45", material.r45);
    w.number("r90", material.r90);
  }
  if (material.type == Type::yld2000) {
    w.number("r_b", material.r_b, "equibiaxial d eps_yy / d eps_xx");
  }
}

void write_material(TomlWriter& w, const MaterialConfig& material) {
  const std::string table = fmt::format("materials.{}", format_key(material.name));
  w.header(table);
  w.string("type", material_type_name(material.type));
  w.number("density", material.density, "tonne/mm^3");
  w.number("young", material.young, "MPa");
  w.number("poisson", material.poisson);
  write_anisotropy(w, material);
  if (!material.forming_limit_curve.empty()) {
    w.points("forming_limit_curve", material.forming_limit_curve,
             "[[minor, major], ...] true strains; used by scripts/plot_forming_limit.py only");
  }
  if (material.type == MaterialConfig::Type::elastic) {
    return;
  }
  w.header(table + ".hardening");
  write_hardening(w, material.hardening);
  if (!material.kinematic.C.empty()) {
    w.header(table + ".kinematic");
    w.numbers(
        "C", material.kinematic.C,
        "MPa; Armstrong-Frederick back stresses: d alpha = C m d eps_p - gamma alpha d eps_p");
    w.numbers("gamma", material.kinematic.gamma);
  }
  if (material.cowper_symonds.D > 0.0) {
    w.header(table + ".cowper_symonds");
    w.number("D", material.cowper_symonds.D,
             "1/s; sigma_y (1 + (plastic strain rate / D)^(1/q)), Cowper-Symonds");
    w.number("q", material.cowper_symonds.q);
  }
}

void write_tool(TomlWriter& w, const ToolConfig& tool) {
  w.array_header("tools");
  w.string("name", tool.name);
  write_mesh_source(w, tool.mesh);
  w.header("tools.motion");
  switch (tool.motion.type) {
    case MotionConfig::Type::fixed:
      w.string("type", "fixed");
      return;
    case MotionConfig::Type::velocity:
      w.string("type", "velocity");
      w.vector("direction", tool.motion.direction);
      w.curve("curve", tool.motion.curve, "[[time (s), velocity (mm/s)], ...]");
      return;
    case MotionConfig::Type::displacement:
      w.string("type", "displacement");
      w.vector("direction", tool.motion.direction);
      w.curve("curve", tool.motion.curve, "[[time (s), displacement (mm)], ...]");
      return;
    case MotionConfig::Type::force:
      w.string("type", "force");
      w.vector("direction", tool.motion.direction, "unit vector, the force's direction");
      w.curve("curve", tool.motion.curve, "[[time (s), force (N)], ...]");
      if (tool.motion.mass) {
        w.number("mass", *tool.motion.mass, "tonne");
      } else {
        w.comment("mass: not given, the blank's mass at the start (set when the model is built)");
      }
      w.number("damping", tool.motion.damping, "1/s, mass-proportional, on the tool");
      return;
  }
}

void write_contact(TomlWriter& w, const ContactConfig& contact) {
  w.array_header("contact");
  w.string("tool", contact.tool);
  w.string("search", contact.search);
  w.string("projection", contact.projection == ContactConfig::Projection::interpolated
                             ? "interpolated"
                             : "orthogonal");
  if (contact.penalty_stiffness > 0.0) {
    w.number("penalty_stiffness", contact.penalty_stiffness, "N/mm per blank node");
  } else {
    w.number("penalty_scale", contact.penalty_scale);
  }
  w.number("friction_static", contact.friction_static, "Coulomb coefficient at rest");
  w.number("friction_dynamic", contact.friction_dynamic, "Coulomb coefficient sliding");
  w.number("friction_decay", contact.friction_decay, "s/mm");
  w.boolean("audit", contact.audit);
  if (contact.search == "cached") {
    w.number("search_margin", contact.search_margin, "mm; 0 = the default");
  }
}

void write_axes(TomlWriter& w, const std::optional<AxesConfig>& axes) {
  if (!axes) {
    return;
  }
  const auto vector = [](const std::array<double, 3>& v) {
    return fmt::format("[{}, {}, {}]", format_toml_number(v[0]), format_toml_number(v[1]),
                       format_toml_number(v[2]));
  };
  w.raw("axes", fmt::format("[{}, {}]", vector(axes->x), vector(axes->y)));
  w.comment("  local x and y axes (unit, perpendicular); z = x cross y");
}

void write_boundary(TomlWriter& w, const BoundaryConfig& boundary) {
  using Type = BoundaryConfig::Type;
  w.array_header("boundary");
  w.string("group", boundary.group);
  static constexpr std::array<std::string_view, 3> axis_names{"x", "y", "z"};
  switch (boundary.type) {
    case Type::fixed:
      w.string("type", "fixed");
      return;
    case Type::symmetry:
    case Type::diaphragm:
      w.string("type", boundary.type == Type::symmetry ? "symmetry" : "diaphragm");
      if (boundary.normal) {
        w.vector("normal", *boundary.normal, "unit vector, the plane's normal");
        return;
      }
      w.string("axis", axis_names.at(static_cast<std::size_t>(boundary.axis)));
      write_axes(w, boundary.axes);
      return;
    case Type::hold: {
      w.string("type", "hold");
      std::string names;
      for (int k = 0; k < 6; ++k) {
        if (boundary.hold[static_cast<std::size_t>(k)]) {
          names += fmt::format("{}\"{}\"", names.empty() ? "" : ", ", kDofNames[k]);
        }
      }
      w.raw("hold", "[" + names + "]");
      write_axes(w, boundary.axes);
      return;
    }
  }
}

void write_prescribed_motion(TomlWriter& w, const PrescribedMotionConfig& pm) {
  w.array_header("prescribed_motion");
  w.string("group", pm.group);
  const bool displacement = pm.type == PrescribedMotionConfig::Type::displacement;
  w.string("type", displacement ? "displacement" : "velocity");
  w.string("dof", kDofNames[pm.dof]);
  const bool rotation = pm.dof >= 3;
  const std::string_view unit =
      displacement ? (rotation ? "rad" : "mm") : (rotation ? "rad/s" : "mm/s");
  if (pm.curve.times.empty()) {
    w.number("value", pm.value, unit);
  } else {
    w.curve("curve", pm.curve, fmt::format("[[time (s), value ({})], ...]", unit));
  }
  write_axes(w, pm.axes);
}

void write_draw_in(TomlWriter& w, const DrawInConfig& draw_in) {
  w.array_header("draw_in");
  w.string("name", draw_in.name);
  w.string("group", draw_in.group);
  w.vector("direction", draw_in.direction);
  if (draw_in.measured >= 0.0) {
    w.number("measured", draw_in.measured, "mm");
    w.number("measured_stroke", draw_in.measured_stroke, "mm of stroke; 0 = at the end of the run");
  } else {
    w.comment("measured: none");
  }
  w.string("source", draw_in.source);
}

void write_history_group(TomlWriter& w, const HistoryGroupConfig& h) {
  w.array_header("history");
  w.string("group", h.group);
  std::string quantities;
  const std::pair<bool, const char*> flags[] = {{h.displacement, "displacement"},
                                                {h.velocity, "velocity"},
                                                {h.rotation, "rotation"},
                                                {h.reaction, "reaction"}};
  for (const auto& [on, name] : flags) {
    if (on) {
      quantities += fmt::format("{}\"{}\"", quantities.empty() ? "" : ", ", name);
    }
  }
  w.raw("quantities", "[" + quantities + "]");
}

void write_load(TomlWriter& w, const LoadConfig& load) {
  w.array_header("load");
  w.string("group", load.group);
  switch (load.type) {
    case LoadConfig::Type::force:
      w.string("type", "force");
      w.vector("value", load.value, "N per node");
      break;
    case LoadConfig::Type::moment:
      w.string("type", "moment");
      w.vector("value", load.value, "N mm per node");
      break;
    case LoadConfig::Type::pressure:
      w.string("type", "pressure");
      w.number("pressure", load.pressure, "MPa on the top face");
      break;
  }
  if (!load.curve.times.empty()) {
    w.curve("curve", load.curve, "[[time (s), scale factor], ...]");
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

void write_initial_velocity(TomlWriter& w, const InitialVelocityConfig& iv) {
  w.array_header("initial_velocity");
  if (!iv.group.empty()) {
    w.string("group", iv.group);
  }
  w.raw("velocity", format_field_vector(iv.velocity), "mm/s");
  w.raw("angular_velocity", format_field_vector(iv.angular_velocity),
        "rad/s, of the nodes' rotations");
}

void write_prescribed_velocity(TomlWriter& w, const PrescribedVelocityConfig& pv) {
  w.array_header("prescribed_velocity");
  w.string("group", pv.group);
  w.vector("velocity", pv.velocity, "mm/s");
  std::string components;
  for (int i = 0; i < 3; ++i) {
    if (pv.components[static_cast<std::size_t>(i)]) {
      components += fmt::format("{}\"{}\"", components.empty() ? "" : ", ", "xyz"[i]);
    }
  }
  w.raw("components", "[" + components + "]");
  if (!pv.curve.times.empty()) {
    w.curve("curve", pv.curve, "[[time (s), scale factor], ...]");
  }
}

void write_control(TomlWriter& w, const ControlConfig& c) {
  w.header("control");
  w.number("end_time", c.end_time, "s; 0 = run until the stroke is reached");
  w.number("stroke", c.stroke, "mm; 0 = run until end_time");
  if (c.stroke_tool.empty()) {
    w.comment("stroke_tool: none (no tool moves)");
  } else {
    w.string("stroke_tool", c.stroke_tool);
  }
  w.integer("output_frames", c.output_frames);
  w.integer("history_interval", c.history_interval, "cycles");
  w.integer("progress_interval", c.progress_interval, "cycles; 0 = about every 2 s");
  w.number("time_step_safety", c.time_step_safety);
  w.number("mass_scaling_dt", c.mass_scaling_dt, "s; 0 = no mass scaling");
  w.number("mass_scaling_max_added", c.mass_scaling_max_added,
           "fraction of the physical mass; 0 = no limit");
  w.number("energy_blowup_ratio", c.energy_blowup_ratio);
  w.integer("checkpoint_cycles", c.checkpoint_cycles, "cycles; 0 = none by cycle count");
  w.number("checkpoint_minutes", c.checkpoint_minutes, "min of wall time; 0 = none by time");
  w.vector("gravity", c.gravity, "mm/s^2");
  w.number("damping", c.damping, "1/s, mass-proportional");
}

std::string format_range(const std::array<double, 2>& r) {
  return fmt::format("[{}, {}]", format_toml_number(r[0]), format_toml_number(r[1]));
}

void write_implicit_sections(TomlWriter& w, const CaseConfig& config) {
  const bool is_static = config.analysis.type == AnalysisConfig::Type::static_equilibrium;
  w.header("analysis");
  w.string("type", is_static ? "static" : "explicit");
  if (is_static) {
    w.string("geometry", config.analysis.linear ? "linear" : "nonlinear");
  }
  const ImplicitConfig& c = config.implicit;
  w.header("implicit");
  w.integer("increments", c.increments);
  w.integer("max_iterations", c.max_iterations, "per increment");
  w.integer("max_cuts", c.max_cuts, "halvings of one increment");
  w.number("force_tolerance", c.force_tolerance, "residual / reference force");
  w.number("displacement_tolerance", c.displacement_tolerance, "correction / increment");
  w.boolean("line_search", c.line_search);
  static constexpr const char* solvers[] = {"auto", "cholmod", "umfpack"};
  w.string("linear_solver", solvers[static_cast<int>(c.linear_solver)]);
  w.string("rigid_body_modes",
           c.rigid_body_modes == ImplicitConfig::RigidBodyModes::automatic ? "auto" : "error");
  if (!config.springback) {
    return;
  }
  const SpringbackConfig& sb = *config.springback;
  w.header("springback");
  if (sb.method == SpringbackConfig::Method::implicit) {
    w.string("method", "implicit");
    w.number("stabilization", sb.stabilization, "x E t per node, N/mm; 0 = none");
  } else {
    w.string("method", "dynamic_relaxation");
    w.number("release_time", sb.release_time, "s");
    w.number("max_time", sb.max_time, "s");
    w.number("kinetic_tolerance", sb.kinetic_tolerance, "kinetic / internal energy");
  }
  if (sb.u_channel) {
    w.header("springback.u_channel");
    w.string("section", sb.u_channel->section);
    w.raw("bottom", format_range(sb.u_channel->bottom));
    w.raw("wall", format_range(sb.u_channel->wall));
    w.raw("flange", format_range(sb.u_channel->flange));
  }
}

}  // namespace

std::string format_resolved_case(const CaseConfig& config) {
  TomlWriter w;
  w.comment(fmt::format("sheetform resolved case; units: {} (length, time, mass, force, stress)",
                        config.units));
  w.comment(fmt::format("read from {}; every default filled in, every path absolute",
                        quote_toml_string(config.file.string())));
  w.string("title", config.title);
  w.string("units", config.units);
  write_blank(w, config.blank);
  for (const auto& material : config.materials) {
    write_material(w, material);
  }
  for (const auto& tool : config.tools) {
    write_tool(w, tool);
  }
  for (const auto& contact : config.contacts) {
    write_contact(w, contact);
  }
  for (const auto& boundary : config.boundaries) {
    write_boundary(w, boundary);
  }
  for (const auto& draw_in : config.draw_ins) {
    write_draw_in(w, draw_in);
  }
  for (const auto& load : config.loads) {
    write_load(w, load);
  }
  for (const auto& h : config.history_groups) {
    write_history_group(w, h);
  }
  for (const auto& iv : config.initial_velocities) {
    write_initial_velocity(w, iv);
  }
  for (const auto& pv : config.prescribed_velocities) {
    write_prescribed_velocity(w, pv);
  }
  for (const auto& pm : config.prescribed_motions) {
    write_prescribed_motion(w, pm);
  }
  write_control(w, config.control);
  write_implicit_sections(w, config);
  w.header("output");
  w.string("directory", config.output.directory);
  w.boolean("stress_layers", config.output.stress_layers);
  const LimitsConfig& l = config.limits;
  w.header("limits");
  w.number("max_cycles", l.max_cycles, "explicit cycles");
  w.number("max_elements", l.max_elements, "per part");
  w.integer("max_frames", l.max_frames);
  w.number("max_output_gb", l.max_output_gb, "GB of results.h5");
  w.number("max_memory_gb", l.max_memory_gb, "GB; 0 = this machine's memory");
  w.number("mesh_seconds", l.mesh_seconds, "s per part");
  w.number("max_initial_penetration", l.max_initial_penetration, "fraction of the thickness");
  return w.take();
}

}  // namespace sf
