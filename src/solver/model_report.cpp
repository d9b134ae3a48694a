#include "solver/model_report.hpp"

#include <fmt/core.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

#include "casefile/case_config_operations.hpp"
#include "core/log.hpp"
#include "material/anisotropy_fit.hpp"
#include "model/constraint_assembly.hpp"
#include "model/external_loads.hpp"

namespace sf {
namespace {

// The press line, one line per operation: what it is, the tools in play, what ends it and when
// the plan expects that (a force, gap or rest end: the latest it may take).
void report_operations(const Model& model, const UnitSystem& units) {
  using End = OperationConfig::End;
  const auto tool_name = [&](int t) { return model.tools[static_cast<std::size_t>(t)].name; };
  for (std::size_t k = 0; k < model.operations.size(); ++k) {
    const Operation& op = model.operations[k];
    if (op.kind == OperationConfig::Kind::trim) {
      const Vec3& d = op.trim_direction;
      const std::string line = op.trim_tool >= 0
                                   ? fmt::format("tool '{}''s outline grown by {:g} mm",
                                                 tool_name(op.trim_tool), op.trim_offset)
                                   : fmt::format("a line of {} points", op.trim_line.size());
      const std::string how =
          op.trim_cut ? fmt::format("elements cut along it, no piece below {:g} of its element",
                                    op.sliver_fraction)
                      : std::string("elements whose centre falls there");
      log_info(
          "Operation   {}/{} '{}' (trim): keeps what projects {} {} along ({:.3g}, {:.3g}, "
          "{:.3g}) ({}; no time passes)\n",
          k + 1, model.operations.size(), op.name, op.keep_inside ? "inside" : "outside", line,
          d.x(), d.y(), d.z(), how);
      continue;
    }
    std::string in_play;
    std::string redefined;
    for (std::size_t t = 0; t < model.tools.size(); ++t) {
      if (op.in_play[t]) {
        in_play += fmt::format("{}{}", in_play.empty() ? "" : ", ", model.tools[t].name);
      }
      if (op.motions[t]) {
        redefined += fmt::format("{}{}", redefined.empty() ? "" : ", ", model.tools[t].name);
      }
    }
    std::string end;
    switch (op.end) {
      case End::stroke:
        end = fmt::format("stroke {:g} {} of '{}', at t = {:.6e} {}", op.stroke, units.length,
                          tool_name(op.tool), op.planned_end, units.time);
        break;
      case End::time:
        end = fmt::format("time {:g} {}, at t = {:.6e} {}", op.time, units.time, op.planned_end,
                          units.time);
        break;
      case End::force:
        end = fmt::format("push {:g} {} on '{}', within {:g} {}", op.force, units.force,
                          tool_name(op.tool), op.time, units.time);
        break;
      case End::gap:
        end = fmt::format(
            "gap {:g} {} from '{}' to '{}' ({:.4g} {} at the start of the meshes), "
            "within {:g} {}",
            op.gap, units.length, tool_name(op.tool), tool_name(op.gap_to), op.reference_clearance,
            units.length, op.time, units.time);
        break;
      case End::rest:
        end = fmt::format("rest (kinetic energy below {:g} of its peak), within {:g} {}", op.rest,
                          op.time, units.time);
        break;
      case End::none:
        end = "converged";
        break;
    }
    log_info("Operation   {}/{} '{}' ({}): tools in play: {}{}; damping {:g} 1/{}; ends by {}\n",
             k + 1, model.operations.size(), op.name, operation_kind_name(op.kind),
             in_play.empty() ? "none" : in_play,
             redefined.empty() ? std::string() : fmt::format(" (motions given: {})", redefined),
             op.damping, units.time, end);
  }
}

std::string format_vector(const Vec3& v) {
  return fmt::format("({:.4g}, {:.4g}, {:.4g})", v.x(), v.y(), v.z());
}

std::string format_vector(const std::array<double, 3>& v) {
  return format_vector(Vec3(v[0], v[1], v[2]));
}

bool is_static(const CaseConfig& config) {
  return config.analysis.type == AnalysisConfig::Type::static_equilibrium;
}

void print_analysis(const CaseConfig& config) {
  if (is_static(config)) {
    const ImplicitConfig& c = config.implicit;
    if (config.analysis.linear) {
      log_info("Analysis    static, linear: one solve on the initial geometry\n");
    } else {
      log_info(
          "Analysis    static, nonlinear: Newton-Raphson in {} increment{} (an increment is "
          "halved at most {} times), {} iterations at most each\n",
          c.increments, c.increments == 1 ? "" : "s", c.max_cuts, c.max_iterations);
    }
    return;
  }
  std::string springback;
  if (config.springback) {
    springback = config.springback->method == SpringbackConfig::Method::implicit
                     ? ", then springback by the implicit static step"
                     : ", then springback by dynamic relaxation";
  }
  log_info("Analysis    explicit dynamic (central differences){}\n", springback);
}

// Barlat's criteria: the coefficients in use (fitted or given) and what they give in uniaxial
// tension every 15 deg and in equibiaxial tension, so a user sees the fit before a run.
void print_criterion(const Material& material) {
  const auto* law = std::get_if<GeneralPlasticity>(&material);
  if (!law) {
    return;
  }
  if (const auto* y = std::get_if<Yld2000Criterion>(&law->criterion)) {
    log_info(
        "Yld2000-2d  a = {}, alpha1..8 = {:.6g}, {:.6g}, {:.6g}, {:.6g}, {:.6g}, {:.6g}, {:.6g}, "
        "{:.6g}\n",
        y->a, y->alpha[0], y->alpha[1], y->alpha[2], y->alpha[3], y->alpha[4], y->alpha[5],
        y->alpha[6], y->alpha[7]);
  } else if (const auto* b = std::get_if<Yld89Criterion>(&law->criterion)) {
    log_info("Yld89       M = {}, a = {:.6g}, c = {:.6g}, h = {:.6g}, p = {:.6g}\n", b->M, b->a,
             b->c, b->h, b->p);
  }
  std::string sigma, r;
  const double pi = std::acos(-1.0);
  for (int deg = 0; deg <= 90; deg += 15) {
    sigma += fmt::format(" {:.4f}", uniaxial_yield_ratio(law->criterion, deg * pi / 180.0));
    r += fmt::format(" {:.4f}", lankford_coefficient(law->criterion, deg * pi / 180.0));
  }
  log_info(
      "Directions  0, 15, .., 90 deg: sigma/sigma0{}; r{}; equibiaxial sigma_b/sigma0 {:.4f}, "
      "r_b {:.4f}\n",
      sigma, r, equibiaxial_yield_ratio(law->criterion), equibiaxial_r_value(law->criterion));
  for (int i = 0; i < law->kinematic.count; ++i) {
    log_info("Back stress {}: C = {} MPa, gamma = {} (saturates at C/gamma = {:.6g} MPa)\n", i + 1,
             law->kinematic.terms[i].C, law->kinematic.terms[i].gamma,
             law->kinematic.terms[i].gamma > 0.0
                 ? law->kinematic.terms[i].C / law->kinematic.terms[i].gamma
                 : std::numeric_limits<double>::infinity());
  }
}

void print_material(const CaseConfig& config, const MaterialConfig& m, const Material& material,
                    const UnitSystem& units) {
  using Type = MaterialConfig::Type;
  using Law = HardeningConfig::Law;
  std::string law = "elastic";
  const auto& d = config.blank.rolling_direction;
  const std::string axes =
      fmt::format("rolling direction ({:.3g}, {:.3g}, {:.3g})", d[0], d[1], d[2]);
  if (m.type == Type::hill48) {
    law = fmt::format("Hill48 (r0 {}, r45 {}, r90 {}; {})", m.r0, m.r45, m.r90, axes);
  } else if (m.type == Type::von_mises) {
    law = "von Mises";
  } else if (m.type == Type::yld2000) {
    law = fmt::format("Yld2000-2d ({}; {})", m.alpha.empty() ? "fitted to the data" : "alpha given",
                      axes);
  } else if (m.type == Type::yld89) {
    law = fmt::format("Yld89 (r0 {}, r45 {}, r90 {}; {})", m.r0, m.r45, m.r90, axes);
  }
  if (!m.kinematic.C.empty()) {
    law += fmt::format(", {} Armstrong-Frederick back stress{}", m.kinematic.C.size(),
                       m.kinematic.C.size() > 1 ? "es" : "");
  }
  if (m.cowper_symonds.D > 0.0) {
    const auto factor = [&](double rate) {
      return 1.0 + std::pow(rate / m.cowper_symonds.D, 1.0 / m.cowper_symonds.q);
    };
    law += fmt::format(
        ", Cowper-Symonds rate dependence (D {} 1/s, q {}: flow stress x {:.3g} at 1 /s, x {:.3g} "
        "at 100 /s of plastic strain rate)",
        m.cowper_symonds.D, m.cowper_symonds.q, factor(1.0), factor(100.0));
  }
  if (m.type != Type::elastic) {
    static constexpr const char* names[] = {"Swift",     "linear",         "Voce",      "Ludwik",
                                            "tabulated", "Hockett-Sherby", "Swift-Voce"};
    law += fmt::format(", {} hardening", names[static_cast<int>(m.hardening.law)]);
    if (m.hardening.law == Law::tabulated) {
      law += fmt::format(" ({})", m.hardening.table_file.string());
    }
  }
  log_info("Material    '{}': E = {} {}, nu = {}, density {} {}, {}\n", m.name, m.young,
           units.stress, m.poisson, m.density, units.density(), law);
  print_criterion(material);
}

void print_mass(const Model& model, const UnitSystem& units) {
  const Blank& blank = model.blank;
  log_info(
      "Mass        {:.6e} {} physical, {:.6e} {} added by mass scaling ({:.2f} %, {} elements)\n",
      blank.physical_mass, units.mass, blank.scaling.added_mass, units.mass,
      100.0 * blank.scaling.added_mass / blank.physical_mass, blank.scaling.scaled_elements);
  if (blank.scaling.enabled()) {
    log_info("Mass scale  target step {:.4e} {}; elements below it get mass during the run too\n",
             blank.scaling.target_dt, units.time);
  }
}

/// The groups the case chose by position ([[node_group]]): how many nodes each holds, and where
/// the first one is (a single node's position is what a point group is for).
void print_node_groups(const CaseConfig& config, const Model& model, const UnitSystem& units) {
  for (const NodeGroupConfig& g : config.node_groups) {
    const NodeGroup& group = model.blank.group(g.name);
    const Vec3 first = model.blank.mesh.nodes.col(group.nodes.front());
    log_info("Node group  '{}': {} {}, {} at ({:.6g}, {:.6g}, {:.6g}) {}\n", g.name,
             group.nodes.size(), group.nodes.size() == 1 ? "node" : "nodes",
             group.nodes.size() == 1 ? "the node" : "the first", first.x(), first.y(), first.z(),
             units.length);
  }
}

void print_boundaries(const CaseConfig& config, const Model& model, const UnitSystem& units) {
  for (const BoundaryConfig& b : config.boundaries) {
    log_info("Boundary    '{}': {} nodes, {}\n", b.group, model.blank.group(b.group).nodes.size(),
             describe_boundary(b));
  }
  for (const PrescribedMotion& p : model.prescribed_motions) {
    const bool displacement = p.kind == PrescribedMotion::Kind::displacement;
    const std::string unit =
        p.rotation ? (displacement ? std::string("rad") : fmt::format("rad/{}", units.time))
                   : (displacement ? std::string(units.length) : units.velocity());
    log_info("Prescribed  '{}': {} nodes, {} {} ({}) along ({:.3g}, {:.3g}, {:.3g}) ({})\n",
             p.group, p.nodes.size(), p.rotation ? "rotation" : "translation",
             displacement ? "displacement" : "velocity", unit, p.direction.x(), p.direction.y(),
             p.direction.z(), p.entry);
  }
  if (model.constraints.frames.count() > 0) {
    const int framed = model.constraints.frames.count();
    log_info("Node axes   {} node{} in axes of {} own (from the constraints there)\n", framed,
             framed == 1 ? "" : "s", framed == 1 ? "its" : "their");
  }
}

/// How a load or prescription is scaled over time: its curve, or (static, no curve) the ramp.
std::string describe_scale(const CaseConfig& config, const CurveConfig& curve,
                           const UnitSystem& units) {
  if (!curve.times.empty()) {
    return fmt::format("scaled by a curve of {} point{} (factor {} at {} {} .. {} from {} {})",
                       curve.times.size(), curve.times.size() == 1 ? "" : "s", curve.values.front(),
                       curve.times.front(), units.time, curve.values.back(), curve.times.back(),
                       units.time);
  }
  if (is_static(config)) {
    return fmt::format("ramped from 0 to its value over the pseudo-time 0..{} {}",
                       config.control.end_time, units.time);
  }
  return "constant";
}

void print_pressure(const CaseConfig& config, const Model& model, const LoadConfig& lc,
                    const PressureLoad& load, const UnitSystem& units) {
  const PressureDirection d = compute_pressure_direction(model, load, model.blank.mesh.nodes);
  log_info(
      "Load        '{}': pressure {} {} on the top side of {} elements ({:.6g} {}), {}\n"
      "            their top side's mean normal {}; the pressure pushes along {}: resultant {} "
      "{} at full value\n",
      lc.group, lc.pressure, units.stress, load.elements.size(), d.area, units.area(),
      describe_scale(config, lc.curve, units), format_vector(d.top_normal), format_vector(d.push),
      format_vector(d.resultant), units.force);
}

void print_loads(const CaseConfig& config, const Model& model, const UnitSystem& units) {
  std::size_t pressure = 0;
  for (const LoadConfig& lc : config.loads) {
    if (lc.type == LoadConfig::Type::pressure) {
      print_pressure(config, model, lc, model.loads.pressures.at(pressure++), units);
      continue;
    }
    const bool moment = lc.type == LoadConfig::Type::moment;
    log_info("Load        '{}': {} {} {} per node on {} nodes, {}\n", lc.group,
             moment ? "moment" : "force", format_vector(lc.value),
             moment ? units.moment() : units.force, model.blank.group(lc.group).nodes.size(),
             describe_scale(config, lc.curve, units));
  }
  for (const PrescribedVelocityConfig& pv : config.prescribed_velocities) {
    std::string held;
    for (int c = 0; c < 3; ++c) {
      if (pv.components[static_cast<std::size_t>(c)]) {
        held += fmt::format("{}{} = {}", held.empty() ? "" : ", ", "xyz"[c],
                            pv.velocity[static_cast<std::size_t>(c)]);
      }
    }
    log_info("Prescribed  '{}': velocity {} {} held on {} nodes, {}\n", pv.group, held,
             units.velocity(), model.blank.group(pv.group).nodes.size(),
             describe_scale(config, pv.curve, units));
  }
  for (const InitialVelocityConfig& iv : config.initial_velocities) {
    // A component is a number or an expression of the initial coordinates (a field).
    const auto text = [](const std::array<Expression, 3>& v) {
      return fmt::format("({}, {}, {})", v[0].text(), v[1].text(), v[2].text());
    };
    const auto zero = [](const std::array<Expression, 3>& v) {
      return std::all_of(v.begin(), v.end(), [](const Expression& e) {
        return e.is_constant() && e.evaluate(0.0, 0.0, 0.0) == 0.0;
      });
    };
    const std::string angular =
        zero(iv.angular_velocity)
            ? std::string()
            : fmt::format(", angular velocity {} rad/{}", text(iv.angular_velocity), units.time);
    log_info("Initial     {}: velocity {} {}{}\n",
             iv.group.empty() ? std::string("every node") : fmt::format("'{}'", iv.group),
             text(iv.velocity), units.velocity(), angular);
  }
  const auto& g = config.control.gravity;
  if (g[0] != 0.0 || g[1] != 0.0 || g[2] != 0.0) {
    log_info("Gravity     {} {} on the physical mass, {}\n", format_vector(g), units.acceleration(),
             is_static(config) ? "ramped like the loads" : std::string("constant"));
  }
  if (config.control.damping > 0.0 && !is_static(config)) {
    log_info("Damping     {} {}, mass-proportional\n", config.control.damping, units.rate());
  }
}

void print_tools(const Model& model, const UnitSystem& units) {
  for (std::size_t i = 0; i < model.tools.size(); ++i) {
    const Tool& t = model.tools[i];
    std::string motion = "fixed";
    if (t.force_control) {
      // Its frequency on the contact springs of its pair, against the bound build_model checks.
      double k_sum = 0.0;
      for (const ContactInterface& c : model.contacts) {
        if (c.tool == static_cast<int>(i)) {
          k_sum += c.pair.stiffness.sum();
        }
      }
      motion = fmt::format(
          "force-controlled along {}, mass {:.4e} {}, damping {} {}; sqrt(sum k / mass) dt = "
          "{:.3f}",
          format_vector(t.direction()), t.force_control->mass(), units.mass,
          t.force_control->damping(), units.rate(),
          std::sqrt(k_sum / t.force_control->mass()) * model.time.time_step);
    } else if (t.motion.moves()) {
      motion = fmt::format("moves along {}", format_vector(t.direction()));
    }
    if (t.motion.turns()) {
      motion += fmt::format(
          "{} turns about {} through ({:g}, {:g}, {:g}) {}, {:.6g} deg at t = {:.6g} {}",
          t.motion.moves() ? ";" : ",", format_vector(t.motion.axis()), t.motion.pivot().x(),
          t.motion.pivot().y(), t.motion.pivot().z(), units.length,
          t.motion.angle(model.time.end_time) * (180.0 / std::numbers::pi), model.time.end_time,
          units.time);
    }
    log_info("Tool        '{}': {} nodes, {} triangles, {}\n", t.name, t.mesh.nodes.cols(),
             t.mesh.triangles.cols(), motion);
  }
}

// The tools moved to touch the blank (position = "touch"), with the distance.
void print_tool_positions(const CaseConfig& config, const Model& model, const UnitSystem& units) {
  for (std::size_t i = 0; i < model.tools.size() && i < config.tools.size(); ++i) {
    if (config.tools[i].position == ToolConfig::Position::touch) {
      const Tool& t = model.tools[i];
      log_info("Position    '{}' moved {:.6g} {} along {} to touch the blank\n", t.name,
               t.touch_shift, units.length, format_vector(t.direction()));
    }
  }
}

// The laws beyond Coulomb, appended to its description (docs/contact.md, "Friction laws").
std::string describe_friction_shaping(const ContactConfig& c, const UnitSystem& units) {
  std::string text;
  if (c.friction_pressure_exponent != 1.0) {
    text += fmt::format(" x (p / {} {})^({} - 1)", c.friction_reference_pressure, units.stress,
                        c.friction_pressure_exponent);
  }
  if (!c.friction_speed_table.empty()) {
    text += fmt::format(" x a slip-speed table of {} points", c.friction_speed_table.size());
  }
  if (c.friction_across_ratio != 1.0) {
    text += fmt::format(", across the rolling direction x {}", c.friction_across_ratio);
  }
  return text;
}

std::string describe_friction(const ContactConfig& c, const UnitSystem& units) {
  if (!c.friction_pressure_table.empty()) {
    return fmt::format("friction mu from a pressure table of {} points ({} to {} {}){}",
                       c.friction_pressure_table.size(), c.friction_pressure_table.front()[0],
                       c.friction_pressure_table.back()[0], units.stress,
                       describe_friction_shaping(c, units));
  }
  if (!(c.friction_static > 0.0)) {
    return "frictionless";
  }
  if (c.friction_dynamic == c.friction_static && c.friction_decay == 0.0) {
    return fmt::format("Coulomb friction mu = {}{}", c.friction_static,
                       describe_friction_shaping(c, units));
  }
  return fmt::format("Coulomb friction mu_s = {}, mu_d = {}, decay {} {}/{}{}", c.friction_static,
                     c.friction_dynamic, c.friction_decay, units.time, units.length,
                     describe_friction_shaping(c, units));
}

void print_contacts(const CaseConfig& config, const Model& model, const UnitSystem& units) {
  for (std::size_t k = 0; k < model.contacts.size(); ++k) {
    const ContactInterface& c = model.contacts[k];
    const ContactConfig& cc = config.contacts[k];  // build_model keeps the case's order
    log_info(
        "Contact     blank nodes vs '{}': search '{}', {} projection, penalty {} {:.4g} to "
        "{:.4g} {}, {}\n",
        model.tools[static_cast<std::size_t>(c.tool)].name,
        choice_name<ContactSearchKind>(kContactSearchNames, cc.search),
        choice_name<ContactProjection>(kContactProjectionNames, cc.projection),
        cc.penalty_stiffness > 0.0 ? std::string("stiffness")
                                   : fmt::format("scale {}, stiffness", cc.penalty_scale),
        c.pair.stiffness.minCoeff(), c.pair.stiffness.maxCoeff(), units.stiffness(),
        describe_friction(cc, units));
  }
}

void print_drawbeads(const Model& model, const UnitSystem& units) {
  const std::string& mm = units.length;
  const std::string per_length = units.stiffness();  // force per length: N/mm
  for (const DrawbeadInterface& b : model.drawbeads) {
    const DrawbeadLine& line = b.line;
    const std::string force =
        line.locking ? std::string("locking")
                     : fmt::format("restraining {:.4g} {}", line.restraining_at(1.0), per_length);
    log_info(
        "Drawbead    '{}' on '{}': {:.4g} {} long, {:.4g} {} wide, closes over {:.4g} {}; at "
        "full closure {}, uplift {:.4g} {} ({})\n",
        line.name, model.tools[static_cast<std::size_t>(b.tool)].name, line.length(), mm,
        line.width, mm, line.height, mm, force, line.uplift_at(1.0), per_length, b.source);
  }
}

void print_formability(const Model& model) {
  const FormabilityConfig& th = model.formability.thresholds;
  for (std::size_t i = 0; i < model.formability.part_curves.size(); ++i) {
    const FormingLimitCurve& curve = model.formability.part_curves[i];
    log_info("FLC         part '{}': {}\n", model.blank.parts.at(i).name,
             curve.empty() ? std::string("none (no forming_limit_curve and no Swift n): no margin, "
                                         "no crack zones")
                           : curve.source);
  }
  log_info(
      "Formability {} surface; risk of cracks within {:.4g} of the FLC, severe thinning from "
      "{:.4g} %, wrinkling tendency beyond {:.4g} thickening, insufficient stretching below "
      "{:.4g} major strain\n",
      choice_name<FormabilityConfig::Surface>(kFormabilitySurfaceNames, th.surface),
      th.safety_margin, th.severe_thinning, th.wrinkle_thickening, th.insufficient_stretch);
}

void print_mesh_parameters(const CaseConfig& config) {
  const auto print = [](const std::string& part, const MeshSourceConfig& mesh) {
    if (mesh.parameters.empty()) {
      return;
    }
    std::string list;
    for (const GeoParameter& p : mesh.parameters) {
      list += fmt::format("{}{} = {}", list.empty() ? "" : ", ", p.name, p.value);
    }
    log_info("Parameters  {} ({}): {}\n", part, mesh.file.filename().string(), list);
  };
  print("blank", config.blank.mesh);
  for (const ToolConfig& t : config.tools) {
    print(fmt::format("tool '{}'", t.name), t.mesh);
  }
}

void print_history_groups(const CaseConfig& config, const Model& model) {
  for (const HistoryGroupConfig& h : model.output.history_groups) {
    std::string quantities;
    const std::pair<bool, const char*> flags[] = {{h.displacement, "mean displacement"},
                                                  {h.velocity, "mean velocity"},
                                                  {h.rotation, "mean rotation"},
                                                  {h.reaction, "summed reaction"}};
    for (const auto& [on, name] : flags) {
      if (on) {
        quantities += fmt::format("{}{}", quantities.empty() ? "" : ", ", name);
      }
    }
    log_info("History     '{}' ({} nodes): {}\n", h.group, model.blank.group(h.group).nodes.size(),
             quantities);
  }
}

void print_time_control(const CaseConfig& config, const Model& model, const UnitSystem& units) {
  const ControlConfig& control = config.control;
  if (is_static(config)) {
    log_info(
        "Output      {} frames at the load factors k / {}, k = 1 .. {} (each at the first "
        "converged increment at or past it), a history row per converged increment\n",
        control.output_frames, control.output_frames, control.output_frames);
    return;
  }
  log_info("Time step   {:.4e} {} (safety {} x critical, limited by element {})\n",
           model.time.time_step, units.time, control.time_step_safety, model.time.limiting_element);
  log_info("End time    {:.6e} {}{}\n", model.time.end_time, units.time,
           control.stroke > 0.0 ? fmt::format(" (stroke {} {} of '{}')", control.stroke,
                                              units.length, control.stroke_tool)
                                : std::string());
  report_operations(model, units);
  log_info("Cycles      about {:.0f}\n", model.time.end_time / model.time.time_step);
  log_info("Output      {} frames, a history row every {} cycles\n", control.output_frames,
           control.history_interval);
}

}  // namespace

std::string describe_shell_formulation(const ShellPart& part, bool static_step) {
  const ShellSection& s = part.section;
  std::string text;
  if (part.formulation == ShellFormulation::assumed_strain) {
    if (part.quads.cols() > 0) {
      text = fmt::format(
          "{} assumed-strain quadrilaterals (one in-plane point, directors, MITC4 transverse "
          "shear, physical hourglass stabilisation)",
          part.quads.cols());
    }
    if (part.triangles.cols() > 0) {
      text += fmt::format("{}{} assumed-strain triangles (directors, DSG3 transverse shear)",
                          text.empty() ? "" : ", ", part.triangles.cols());
    }
  } else if (part.quads.cols() > 0) {
    const bool stiffness = static_step || part.hourglass_form == HourglassForm::stiffness;
    text = fmt::format(
        "{} Belytschko-Lin-Tsay quadrilaterals (one in-plane point, {} hourglass control, "
        "coefficient {}{})",
        part.quads.cols(), stiffness ? "stiffness" : "viscous", part.hourglass_coefficient,
        static_step && part.hourglass_form == HourglassForm::viscous
            ? "; the case's viscous form has no static stiffness"
            : "");
  }
  if (part.formulation != ShellFormulation::assumed_strain && part.triangles.cols() > 0) {
    text += fmt::format("{}{} C0 triangles (DSG3 transverse shear)", text.empty() ? "" : ", ",
                        part.triangles.cols());
  }
  return text + fmt::format("; {} {} points through the thickness", s.n_points,
                            s.rule == ThroughThicknessRule::lobatto ? "Lobatto" : "Gauss");
}

void print_model(const CaseConfig& config, const Model& model) {
  const UnitSystem units = parse_unit_system(config.units);
  log_info("Case        {}\n", config.file.string());
  if (!config.title.empty()) {
    log_info("Title       {}\n", config.title);
  }
  log_info("Units       {}: length {}, time {}, mass {}, force {}, stress {}\n", config.units,
           units.length, units.time, units.mass, units.force, units.stress);
  print_analysis(config);
  const Blank& blank = model.blank;
  const std::vector<BlankPartConfig> parts = config.blank_parts();
  if (config.blank.parts.empty()) {
    log_info("Blank       {} nodes, {} elements, t = {} {}, material '{}'\n",
             blank.mesh.nodes.cols(), element_count(blank.part), config.blank.thickness,
             units.length, config.blank.material);
  } else {
    log_info("Blank       {} nodes, {} elements, {} parts joined along shared nodes\n",
             blank.mesh.nodes.cols(), element_count(blank.part), parts.size());
    std::vector<int> elements(parts.size(), 0);
    for (int e = 0; e < element_count(blank.part); ++e) {
      ++elements[static_cast<std::size_t>(material_index(blank.part, e))];
    }
    for (std::size_t i = 0; i < parts.size(); ++i) {
      log_info("  part      '{}': group '{}', {} elements, t = {} {}, material '{}'\n",
               parts[i].name, parts[i].group, elements[i], parts[i].thickness, units.length,
               parts[i].material);
    }
  }
  log_info("Elements    {}\n", describe_shell_formulation(blank.part, is_static(config)));
  print_mesh_parameters(config);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const bool first_use =
        std::none_of(parts.begin(), parts.begin() + static_cast<long>(i),
                     [&](const auto& p) { return p.material == parts[i].material; });
    if (first_use) {
      print_material(config, config.material_named(parts[i].material), blank.part.materials[i].law,
                     units);
    }
  }
  if (!is_static(config)) {
    print_mass(model, units);
  }
  print_node_groups(config, model, units);
  print_boundaries(config, model, units);
  print_loads(config, model, units);
  print_tools(model, units);
  print_tool_positions(config, model, units);
  print_contacts(config, model, units);
  print_drawbeads(model, units);
  print_formability(model);
  print_history_groups(config, model);
  print_time_control(config, model, units);
}

}  // namespace sf
