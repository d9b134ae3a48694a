#include "model/operation_plan.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "meshing/curve_loop.hpp"
#include "meshing/gmsh_reader.hpp"
#include "model/tool_clearance.hpp"

namespace sf {
namespace {

using End = OperationConfig::End;
using Kind = OperationConfig::Kind;

int tool_index(const Model& model, const std::string& name) {
  for (std::size_t t = 0; t < model.tools.size(); ++t) {
    if (model.tools[t].name == name) {
      return static_cast<int>(t);
    }
  }
  return -1;
}

// A trim line's points from its file: the curves meshed by gmsh (sandboxed) and joined into one
// closed line. Errors name the case file and the key.
std::vector<Vec3> trim_line_from_file(const CaseConfig& config, const OperationConfig& c,
                                      const std::string& entry) {
  const bool meshed = is_meshed(mesh_format(c.line_file));
  MeshImportOptions import;
  import.group = c.line_group;
  import.curves_only = true;
  import.curves = c.line_curves;
  try {
    const GmshModel curves = load_gmsh_model(c.line_file, meshed ? c.line_element_size : 0.0, false,
                                             {}, import, mesh_limits(config.limits));
    return closed_curve_points(curves, c.line_group, 0.01 * c.line_element_size);
  } catch (const InputError& error) {
    throw InputError(
        fmt::format("{}: {}.line_file: {}", config.file.string(), entry, error.what()));
  }
}

Operation make_operation(const CaseConfig& config, const Model& model, std::size_t k) {
  const OperationConfig& c = config.operations[k];
  Operation op;
  op.name = c.name;
  op.entry = fmt::format("operations[{}] ('{}')", k, c.name);
  op.kind = c.kind;
  op.end = c.end;
  const std::size_t n = model.tools.size();
  const bool tools_in_play = c.kind != Kind::springback && c.kind != Kind::trim;
  op.in_play.assign(n, tools_in_play && c.all_tools ? 1 : 0);
  for (const std::string& name : c.tools) {
    op.in_play[static_cast<std::size_t>(tool_index(model, name))] = 1;
  }
  op.motions.resize(n);
  for (const OperationMotionConfig& m : c.motions) {
    const Tool& tool = model.tools[static_cast<std::size_t>(tool_index(model, m.tool))];
    std::optional<RigidToolMotion>& motion =
        op.motions[static_cast<std::size_t>(tool_index(model, m.tool))];
    motion = RigidToolMotion(m.motion);
    motion->move_pivot(tool.touch_shift * tool.direction());  // pivots as the mesh was moved
  }
  op.tool = c.tool.empty() ? -1 : tool_index(model, c.tool);
  op.gap_to = c.gap_to.empty() ? -1 : tool_index(model, c.gap_to);
  op.stroke = c.stroke;
  op.time = c.time;
  op.force = c.force;
  op.gap = c.gap;
  op.rest = c.rest;
  op.damping = c.damping.value_or(config.control.damping);
  for (const auto& p : c.line) {
    op.trim_line.emplace_back(p[0], p[1], p[2]);
  }
  if (!c.line_file.empty()) {
    op.trim_line = trim_line_from_file(config, c, op.entry);
  }
  op.trim_tool = c.line_tool.empty() ? -1 : tool_index(model, c.line_tool);
  op.trim_offset = c.line_offset;
  op.trim_direction = Vec3(c.direction[0], c.direction[1], c.direction[2]);
  op.keep_inside = c.keep == OperationConfig::Keep::inside;
  op.trim_cut = c.mode == OperationConfig::TrimMode::cut;
  op.sliver_fraction = c.sliver_fraction;
  return op;
}

// Whether tool t turns in the case's motion or in the operations up to `last` (its index).
bool turns_up_to(const Model& model, std::size_t last, int t) {
  const auto i = static_cast<std::size_t>(t);
  bool turns = model.tools[i].motion.turns();
  for (std::size_t k = 0; k <= last && k < model.operations.size(); ++k) {
    const std::optional<RigidToolMotion>& motion = model.operations[k].motions[i];
    turns = turns || (motion && motion->turns());
  }
  return turns;
}

void set_reference_clearance(const CaseConfig& config, const Model& model, Operation& op) {
  const Tool& tool = model.tools[static_cast<std::size_t>(op.tool)];
  const Tool& other = model.tools[static_cast<std::size_t>(op.gap_to)];
  for (const int t : {op.tool, op.gap_to}) {
    if (turns_up_to(model, static_cast<std::size_t>(&op - model.operations.data()), t)) {
      throw InputError(fmt::format(
          "{}: {}.end = \"gap\": tool '{}' turns (its motion has an `angle`), and a gap is "
          "measured between tools that only translate: end the operation by stroke, time or "
          "force",
          config.file.string(), op.entry, model.tools[static_cast<std::size_t>(t)].name));
    }
  }
  const std::optional<double> clearance =
      clearance_along(tool.surface, other.surface, tool.direction());
  if (!clearance) {
    const Vec3& d = tool.direction();
    throw InputError(fmt::format(
        "{}: {}.gap_to: tool '{}' never meets tool '{}' moving along its direction ({:g}, {:g}, "
        "{:g}) from their positions in the meshes: expected a tool beneath it",
        config.file.string(), op.entry, other.name, tool.name, d.x(), d.y(), d.z()));
  }
  op.reference_clearance = *clearance;
}

// The planned end of operation k starting at t0, its stroke tool's origin `origin`.
double planned_end(const Model& model, const Operation& op, const ToolMotionOrigin& origin,
                   double t0) {
  if (op.end == End::time) {
    return t0 + op.time;
  }
  if (op.end != End::stroke) {
    return t0 + op.time;  // the longest it may take
  }
  return checked_stroke_end(model, op, origin, t0, travel_in_effect(model, op.tool, origin, t0));
}

}  // namespace

bool ever_turns(const Model& model, int tool) {
  return turns_up_to(model, model.operations.size(), tool);
}

const RigidToolMotion& motion_in_effect(const Model& model, int tool,
                                        const ToolMotionOrigin& origin) {
  const auto t = static_cast<std::size_t>(tool);
  if (origin.operation >= 0) {
    return *model.operations[static_cast<std::size_t>(origin.operation)].motions[t];
  }
  return model.tools[t].motion;
}

// The case's motion from time 0 is taken as it is (no origin added), so that a case without
// operations keeps its bits (0.0 + -0.0 would be +0.0).
double travel_in_effect(const Model& model, int tool, const ToolMotionOrigin& origin, double t) {
  const RigidToolMotion& motion = motion_in_effect(model, tool, origin);
  if (origin.operation < 0 && origin.start == 0.0) {
    return motion.travel(t);
  }
  return origin.travel + motion.travel(t - origin.start);
}

Vec3 displacement_in_effect(const Model& model, int tool, const ToolMotionOrigin& origin,
                            double t) {
  const RigidToolMotion& motion = motion_in_effect(model, tool, origin);
  if (origin.operation < 0 && origin.start == 0.0) {
    return motion.displacement(t);
  }
  return origin.displacement + motion.displacement(t - origin.start);
}

double speed_in_effect(const Model& model, int tool, const ToolMotionOrigin& origin, double t) {
  return motion_in_effect(model, tool, origin).speed(t - origin.start);
}

// (The case's motion from time 0 keeps its own time, as in travel_in_effect.)
ToolPlacement placement_in_effect(const Model& model, int tool, const ToolMotionOrigin& origin,
                                  double t) {
  const RigidToolMotion& motion = motion_in_effect(model, tool, origin);
  ToolPlacement p{origin.rotation, displacement_in_effect(model, tool, origin, t)};
  if (!motion.turns()) {
    return p;
  }
  const double since = origin.operation < 0 && origin.start == 0.0 ? t : t - origin.start;
  const Vec3 pivot = origin.rotation * motion.pivot() + origin.displacement;
  const Mat3 turn = rotation_about(origin.rotation * motion.axis(), motion.angle(since));
  p.rotation = turn * origin.rotation;
  p.translation = turn * (origin.displacement - pivot) + pivot + motion.displacement(since);
  return p;
}

double angle_in_effect(const Model& model, int tool, const ToolMotionOrigin& origin, double t) {
  const RigidToolMotion& motion = motion_in_effect(model, tool, origin);
  if (origin.operation < 0 && origin.start == 0.0) {
    return motion.angle(t);
  }
  return origin.angle + motion.angle(t - origin.start);
}

ToolStanding standing_in_effect(const Model& model, int tool, const ToolMotionOrigin& origin,
                                double t) {
  return {travel_in_effect(model, tool, origin, t), placement_in_effect(model, tool, origin, t),
          angle_in_effect(model, tool, origin, t)};
}

std::optional<double> stroke_end_time(const Model& model, const Operation& op,
                                      const ToolMotionOrigin& origin) {
  const RigidToolMotion& motion = motion_in_effect(model, op.tool, origin);
  const bool from_start = origin.operation < 0 && origin.start == 0.0;
  const std::optional<double> since =
      motion.time_at_travel(from_start ? op.stroke : op.stroke - origin.travel);
  if (!since) {
    return std::nullopt;
  }
  return from_start ? *since : origin.start + *since;
}

double checked_stroke_end(const Model& model, const Operation& op, const ToolMotionOrigin& origin,
                          double t0, double travel_now) {
  const std::optional<double> end = stroke_end_time(model, op, origin);
  if (op.stroke <= travel_now || !end || !(*end > t0)) {
    throw InputError(fmt::format(
        "{}: {}.stroke = {} mm: tool '{}' stands at a travel of {:.6g} mm when the operation "
        "starts (t = {:.6g} s) and its motion {} (the stroke counts from the case's start)",
        model.case_file.string(), op.entry, op.stroke,
        model.tools[static_cast<std::size_t>(op.tool)].name, travel_now, t0,
        end ? "has passed that travel already" : "never reaches it"));
  }
  return *end;
}

ToolMotionOrigin origin_at_start(const Model& model, int k, int tool,
                                 const ToolMotionOrigin& before, bool moved, double t0,
                                 const ToolStanding& here) {
  const Operation& op = model.operations[static_cast<std::size_t>(k)];
  if (!op.motions[static_cast<std::size_t>(tool)] && moved) {
    return before;
  }
  return {.operation = op.motions[static_cast<std::size_t>(tool)] ? k : -1,
          .start = t0,
          .travel = here.travel,
          .displacement = here.placement.translation,
          .rotation = here.placement.rotation,
          .angle = here.angle};
}

void build_operations(const CaseConfig& config, Model& model) {
  if (config.operations.empty()) {
    return;
  }
  const std::size_t n = model.tools.size();
  for (std::size_t k = 0; k < config.operations.size(); ++k) {
    model.operations.push_back(make_operation(config, model, k));
    Operation& op = model.operations.back();
    if (op.end == End::gap) {
      set_reference_clearance(config, model, op);
    }
  }
  // The plan: each operation starts where the one before ends as planned; the tools with a
  // prescribed motion follow the rule of operation_plan.hpp.
  std::vector<ToolMotionOrigin> origin(n);
  std::vector<unsigned char> moved(n, 0);
  std::vector<ToolStanding> standing(n);  // where each tool stands at an operation's start
  double t = 0.0;
  for (std::size_t k = 0; k < model.operations.size(); ++k) {
    Operation& op = model.operations[k];
    if (op.kind == Kind::springback) {
      op.planned_end = t;
      break;
    }
    if (op.kind == Kind::trim) {
      // No time passes and no tool moves: after it, each tool restarts its motion from where
      // it stands (as after an operation it stood still in).
      op.planned_end = t;
      for (std::size_t i = 0; i < n; ++i) {
        if (!model.tools[i].force_control && (moved[i] || k == 0)) {
          standing[i] = standing_in_effect(model, static_cast<int>(i), origin[i], t);
        }
        moved[i] = 0;
      }
      continue;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const int ti = static_cast<int>(i);
      if (model.tools[i].force_control) {
        continue;
      }
      if (moved[i] || k == 0) {
        standing[i] = standing_in_effect(model, ti, origin[i], t);
      }
      if (op.in_play[i] && (k > 0 || op.motions[i])) {
        origin[i] = origin_at_start(model, static_cast<int>(k), ti, origin[i], moved[i] != 0, t,
                                    standing[i]);
      }
    }
    const ToolMotionOrigin stroke_origin =
        op.tool >= 0 ? origin[static_cast<std::size_t>(op.tool)] : ToolMotionOrigin{};
    op.planned_end = planned_end(model, op, stroke_origin, t);
    for (std::size_t i = 0; i < n; ++i) {
      moved[i] = op.in_play[i];
    }
    t = op.planned_end;
  }
  model.time.end_time = t;
  if (!config.operations.empty() && config.operations.back().kind == Kind::springback &&
      !model.springback) {
    model.springback = SpringbackConfig{};  // the case's [springback] defaults
  }
}

}  // namespace sf
