#include "model/build_model.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>

#include "contact/contact_search.hpp"
#include "core/errors.hpp"
#include "core/log.hpp"
#include "element/element_block.hpp"
#include "material/anisotropy_fit.hpp"
#include "mesh/nodal_area.hpp"
#include "meshing/gmsh_reader.hpp"
#include "model/blank_parts.hpp"
#include "model/constraint_assembly.hpp"
#include "model/drawbead_setup.hpp"
#include "model/node_selection.hpp"
#include "model/operation_plan.hpp"
#include "model/physical_ranges.hpp"
#include "model/time_step_check.hpp"
#include "model/tool_clearance.hpp"

namespace sf {
namespace {

// The hardening law of a material; a tabulated one is read from its CSV file here, and its
// errors (naming the CSV file and line) are prefixed with the case file and the key.
Hardening make_hardening(const CaseConfig& config, const MaterialConfig& m) {
  const HardeningConfig& h = m.hardening;
  switch (h.law) {
    case HardeningConfig::Law::swift:
      return SwiftHardening{h.swift_k, h.swift_eps0, h.swift_n};
    case HardeningConfig::Law::linear:
      return LinearHardening{h.yield_stress, h.modulus};
    case HardeningConfig::Law::voce:
      return VoceHardening{h.voce_sigma0, h.voce_q, h.voce_b};
    case HardeningConfig::Law::ludwik:
      return LudwikHardening{h.ludwik_a, h.ludwik_b, h.ludwik_n};
    case HardeningConfig::Law::hockett_sherby:
      return HockettSherbyHardening{h.hs_sigma_s, h.hs_sigma_i, h.hs_n, h.hs_p};
    case HardeningConfig::Law::swift_voce:
      return SwiftVoceHardening{h.sv_weight, SwiftHardening{h.swift_k, h.swift_eps0, h.swift_n},
                                VoceHardening{h.voce_sigma0, h.voce_q, h.voce_b}};
    case HardeningConfig::Law::tabulated:
      try {
        return read_hardening_csv(h.table_file);
      } catch (const InputError& error) {
        throw InputError(fmt::format("{}: materials.{}.hardening.file: {}", config.file.string(),
                                     m.name, error.what()));
      }
  }
  return LinearHardening{h.yield_stress, h.modulus};
}

// The yield criterion of a plastic material; Barlat's are fitted here, errors naming the case
// file and the material.
YieldCriterion make_criterion(const CaseConfig& config, const MaterialConfig& m) {
  const std::string what = fmt::format("{}: materials.{}", config.file.string(), m.name);
  switch (m.type) {
    case MaterialConfig::Type::hill48:
      return Hill48Criterion{hill48_coefficients(m.r0, m.r45, m.r90)};
    case MaterialConfig::Type::yld2000:
      if (m.alpha.size() == 8) {
        Yld2000Criterion c;
        std::copy(m.alpha.begin(), m.alpha.end(), c.alpha.begin());
        c.a = m.exponent;
        return c;
      }
      return fit_yld2000(
          Yld2000Data{m.sigma0, m.sigma45, m.sigma90, m.sigma_b, m.r0, m.r45, m.r90, m.r_b},
          m.exponent, what.c_str());
    case MaterialConfig::Type::yld89:
      return fit_yld89(m.r0, m.r45, m.r90, m.exponent, what.c_str());
    case MaterialConfig::Type::elastic:
    case MaterialConfig::Type::von_mises:
      break;
  }
  return VonMisesCriterion{};
}

Material make_material(const CaseConfig& config, const MaterialConfig& m) {
  // Kinematic hardening or a rate dependence takes the general return.
  const bool closed_form = m.kinematic.C.empty() && !(m.cowper_symonds.D > 0.0);
  switch (m.type) {
    case MaterialConfig::Type::elastic:
      return ElasticPlaneStress{m.young, m.poisson};
    case MaterialConfig::Type::von_mises:
      if (closed_form) {
        return J2PlaneStress{m.young, m.poisson, make_hardening(config, m)};
      }
      break;
    case MaterialConfig::Type::hill48:
      if (closed_form) {
        return Hill48PlaneStress{m.young, m.poisson, m.r0, m.r45, m.r90, make_hardening(config, m)};
      }
      break;
    case MaterialConfig::Type::yld2000:
    case MaterialConfig::Type::yld89:
      break;
  }
  GeneralPlasticity law;
  law.E = m.young;
  law.nu = m.poisson;
  law.criterion = make_criterion(config, m);
  law.hardening = make_hardening(config, m);
  law.kinematic.count = static_cast<int>(m.kinematic.C.size());
  for (int i = 0; i < law.kinematic.count; ++i) {
    law.kinematic.terms[i] = {m.kinematic.C[i], m.kinematic.gamma[i]};
  }
  law.rate = {m.cowper_symonds.D, m.cowper_symonds.q};
  check_general_plasticity(law,
                           fmt::format("{}: materials.{}", config.file.string(), m.name).c_str());
  return law;
}

// Material axes of every blank element (laws with material axes only): the angle from each
// element's e1 to the rolling direction on the initial mesh. Errors name the case file, the key
// and the element.
std::vector<double> make_material_angles(const CaseConfig& config, const PartMesh& mesh) {
  const auto& d = config.blank.rolling_direction;
  try {
    return compute_material_angles(mesh.nodes, mesh.quads, mesh.triangles, Vec3(d[0], d[1], d[2]));
  } catch (const InputError& error) {
    throw InputError(
        fmt::format("{}: blank.rolling_direction: {}", config.file.string(), error.what()));
  }
}

// Meshes a part's source; a .geo parameter the file cannot take is reported at the case key
// that set it (`key` is "blank" or "tools[1]").
GmshModel load_mesh_source(const CaseConfig& config, const MeshSourceConfig& mesh,
                           const std::string& key, bool recombine) {
  try {
    const MeshImportOptions import{.scale = mesh.scale,
                                   .curvature_elements = mesh.curvature_elements,
                                   .chord_error = mesh.chord_error,
                                   .surfaces = mesh.surfaces,
                                   .group = mesh.group,
                                   .curves_only = false,
                                   .curves = {}};
    return load_gmsh_model(mesh.file, mesh.element_size, recombine, mesh.parameters, import,
                           mesh_limits(config.limits));
  } catch (const GeoParameterError& error) {
    const GeoParameter& p = mesh.parameters.at(error.index());
    throw InputError(fmt::format("{}: {}.parameters.{}: {}",
                                 p.location.empty() ? config.file.string() : p.location, key,
                                 p.name, error.what()));
  }
}

// A node group of the blank: a physical group of its mesh file, or of the given mesh.
NodeGroup blank_group(const GmshModel* gmsh_model, const BlankMesh* given, const PartMesh& mesh,
                      const std::string& name) {
  if (!given) {
    return extract_node_group(*gmsh_model, mesh, name);
  }
  for (const NodeGroup& g : given->groups) {
    if (g.name == name) {
      return g;
    }
  }
  throw InputError(fmt::format("no node group '{}' in {}", name, given->source));
}

// The blank's parts' names, thicknesses and materials; element_part (empty: one part) gives each
// element's part.
void set_blank_materials(const CaseConfig& config, std::vector<int> element_part, Blank& blank) {
  std::vector<ShellMaterial> materials;
  blank.parts.clear();
  for (const BlankPartConfig& p : config.blank_parts()) {
    const MaterialConfig& material = config.material_named(p.material);
    materials.push_back({make_material(config, material), material.density});
    blank.parts.push_back({p.name, p.thickness});
  }
  if (element_part.empty()) {
    blank.part.materials = std::move(materials);
    blank.part.element_material.clear();
    return;
  }
  const int back_stresses = back_stress_count(materials.front().law);
  if (std::any_of(materials.begin(), materials.end(), [&](const ShellMaterial& m) {
        return back_stress_count(m.law) != back_stresses;
      })) {
    throw InputError(
        fmt::format("{}: blank.parts: the parts' materials keep different numbers of back stresses "
                    "(kinematic hardening); expected the same number in every part's material",
                    config.file.string()));
  }
  set_element_materials(blank.part, std::move(materials), std::move(element_part));
}

void read_blank(const CaseConfig& config, Model& model, const BlankMesh* given) {
  const BlankConfig& bc = config.blank;
  // "quad": a .geo is meshed with every surface recombined (quads wherever gmsh can make them);
  // "as_meshed": the .geo's own Recombine commands decide. Either way the blank takes quads,
  // triangles or both (a .msh is read as it is).
  std::optional<GmshModel> gmsh_model;
  Blank& blank = model.blank;
  if (given) {
    blank.mesh = given->mesh;
  } else if (bc.mesh.file.empty()) {
    throw InputError(config.file.string() +
                     ": [blank] has no mesh: its mesh is blank.formed_part's, which "
                     "build_case_model (solver/case_model.hpp) reads");
  } else {
    gmsh_model = load_mesh_source(config, bc.mesh, "blank", bc.element == BlankMeshing::quad);
    blank.mesh = extract_part_mesh(*gmsh_model, bc.mesh.group, "blank");
  }
  if (blank.mesh.quads.cols() + blank.mesh.triangles.cols() == 0) {
    throw InputError(fmt::format("{}: group '{}' holds no quadrilaterals or triangles",
                                 bc.mesh.file.string(), bc.mesh.group));
  }
  std::vector<int> element_part;
  if (given) {  // a formed part's mesh: its elements' parts by name
    element_part = parts_by_name(given->part_names, given->element_part, bc.parts,
                                 config.file.string(), given->source);
  } else if (!bc.parts.empty()) {
    element_part = sort_blank_by_part(*gmsh_model, bc.parts, config.file.string(), blank.mesh);
  }
  // Every node group the case names, read once, with the entry that first names it (a missing
  // group's message names the case file, the entry's line where known, and its key).
  std::vector<std::pair<std::string, std::string>> names;  // group, "file[:line]: key"
  const std::string file = config.file.string();
  const auto at_line = [&file](int line) {
    return line > 0 ? fmt::format("{}:{}", file, line) : file;
  };
  // The case's own groups ([[node_group]], chosen by position) first: a group the case names is
  // one of them or a physical group of the blank's mesh, never both.
  for (std::size_t i = 0; i < config.node_groups.size(); ++i) {
    const NodeGroupConfig& g = config.node_groups[i];
    const std::string where = fmt::format("{}: node_group[{}]", at_line(g.line), i);
    const bool also_in_mesh =
        given ? std::any_of(given->groups.begin(), given->groups.end(),
                            [&](const NodeGroup& h) { return h.name == g.name; })
              : gmsh_model->find_group(g.name) != nullptr;
    if (also_in_mesh) {
      throw InputError(fmt::format(
          "{}.name: '{}' is also a physical group of '{}'; give the node group another name", where,
          g.name, bc.mesh.file.string()));
    }
    blank.groups.push_back(select_nodes(g, blank.mesh, where));
  }
  for (std::size_t i = 0; i < config.boundaries.size(); ++i) {
    names.emplace_back(
        config.boundaries[i].group,
        fmt::format("{}: boundary[{}].group", at_line(config.boundaries[i].line), i));
  }
  for (std::size_t i = 0; i < config.draw_ins.size(); ++i) {
    names.emplace_back(config.draw_ins[i].group, fmt::format("{}: draw_in[{}].group", file, i));
  }
  for (std::size_t i = 0; i < config.loads.size(); ++i) {
    names.emplace_back(config.loads[i].group, fmt::format("{}: load[{}].group", file, i));
  }
  for (std::size_t i = 0; i < config.initial_velocities.size(); ++i) {
    if (!config.initial_velocities[i].group.empty()) {
      names.emplace_back(config.initial_velocities[i].group,
                         fmt::format("{}: initial_velocity[{}].group", file, i));
    }
  }
  for (std::size_t i = 0; i < config.prescribed_velocities.size(); ++i) {
    const PrescribedVelocityConfig& v = config.prescribed_velocities[i];
    names.emplace_back(v.group,
                       fmt::format("{}: prescribed_velocity[{}].group", at_line(v.line), i));
  }
  for (std::size_t i = 0; i < config.prescribed_motions.size(); ++i) {
    const PrescribedMotionConfig& m = config.prescribed_motions[i];
    names.emplace_back(m.group, fmt::format("{}: prescribed_motion[{}].group", at_line(m.line), i));
  }
  for (std::size_t i = 0; i < config.history_groups.size(); ++i) {
    names.emplace_back(config.history_groups[i].group,
                       fmt::format("{}: history[{}].group", file, i));
  }
  if (config.springback && config.springback->u_channel) {
    names.emplace_back(config.springback->u_channel->section,
                       fmt::format("{}: springback.u_channel.section", file));
  }
  for (const auto& [name, key] : names) {
    // (A named reference: lambdas capture structured bindings only from clang 16, and the
    // ThreadSanitizer build, scripts/tsan.sh, uses clang 14.)
    const std::string& wanted = name;
    const bool seen = std::any_of(blank.groups.begin(), blank.groups.end(),
                                  [&](const NodeGroup& g) { return g.name == wanted; });
    if (!seen) {
      try {
        blank.groups.push_back(
            blank_group(gmsh_model ? &*gmsh_model : nullptr, given, blank.mesh, name));
      } catch (const InputError& error) {
        std::string own;  // the case's [[node_group]] names, which a typo may have meant
        for (const NodeGroupConfig& g : config.node_groups) {
          own += (own.empty() ? "" : ", ") + g.name;
        }
        throw InputError(fmt::format("{}: {}{}", key, error.what(),
                                     own.empty() ? "" : "; node groups of the case: " + own));
      }
      blank.groups.back().name = name;
    }
  }

  blank.inverse_element_count = VectorX::Zero(blank.mesh.nodes.cols());
  for (Eigen::Index e = 0; e < blank.mesh.quads.cols(); ++e) {
    for (int a = 0; a < 4; ++a) {
      blank.inverse_element_count[blank.mesh.quads(a, e)] += 1.0;
    }
  }
  for (Eigen::Index e = 0; e < blank.mesh.triangles.cols(); ++e) {
    for (int a = 0; a < 3; ++a) {
      blank.inverse_element_count[blank.mesh.triangles(a, e)] += 1.0;
    }
  }
  for (Eigen::Index i = 0; i < blank.inverse_element_count.size(); ++i) {
    if (blank.inverse_element_count[i] == 0.0) {
      throw InputError(fmt::format("{}: blank node {} (gmsh node {}) belongs to no element",
                                   bc.mesh.file.string(), i,
                                   blank.mesh.gmsh_node_tags[static_cast<std::size_t>(i)]));
    }
  }
  blank.inverse_element_count = blank.inverse_element_count.cwiseInverse();

  blank.part.quads = blank.mesh.quads;
  blank.part.triangles = blank.mesh.triangles;
  blank.node_corners = build_node_corners(blank.part, static_cast<int>(blank.mesh.nodes.cols()));
  blank.part.section = make_section(bc.integration_points, bc.integration_rule);
  set_blank_materials(config, element_part, blank);
  blank.part.hourglass_coefficient = bc.hourglass_coefficient;
  blank.part.hourglass_form = bc.hourglass_form;
  blank.part.formulation = bc.formulation;
  blank.formed_part = bc.formed_part;
  const bool material_axes = std::any_of(
      blank.part.materials.begin(), blank.part.materials.end(), [](const ShellMaterial& m) {
        return std::visit(
            [](const auto& law) { return kUsesMaterialAxes<std::decay_t<decltype(law)>>; }, m.law);
      });
  if (material_axes) {
    blank.part.material_angle = make_material_angles(config, blank.mesh);
  }
}

// position = "touch": moves the tool's mesh along its motion's direction d until it touches the
// blank: its surface each node's half thickness from the blank's mid-surface (quads split in two
// triangles) along d. Returns the distance moved (mm; negative: moved back along -d).
double move_to_touch(const CaseConfig& config, std::size_t index, const Model& model,
                     PartMesh& mesh) {
  const ToolConfig& tc = config.tools[index];
  const Blank& blank = model.blank;
  const Vec3 d =
      Vec3(tc.motion.direction[0], tc.motion.direction[1], tc.motion.direction[2]).normalized();
  TriConn blank_triangles(3, 2 * blank.mesh.quads.cols() + blank.mesh.triangles.cols());
  Eigen::Index k = 0;
  for (Eigen::Index q = 0; q < blank.mesh.quads.cols(); ++q) {
    const auto& n = blank.mesh.quads.col(q);
    blank_triangles.col(k++) << n(0), n(1), n(2);
    blank_triangles.col(k++) << n(0), n(2), n(3);
  }
  for (Eigen::Index e = 0; e < blank.mesh.triangles.cols(); ++e) {
    blank_triangles.col(k++) = blank.mesh.triangles.col(e);
  }
  // The sheet's surface facing the tool less the thinnest half thickness: the mid-surface moved
  // toward the tool by what each node's half thickness exceeds the least (nothing for a blank of
  // one thickness).
  const VectorX half = initial_half_thickness(blank, model.initial);
  const double least_half = half.minCoeff();
  Matrix3X surface = blank.mesh.nodes;
  for (Eigen::Index i = 0; i < surface.cols(); ++i) {
    surface.col(i) -= (half[i] - least_half) * d;
  }
  const TriangleSurface moving(tc.name, mesh.nodes, mesh.triangles);
  const TriangleSurface sheet("blank", surface, blank_triangles);
  const std::optional<double> clearance = clearance_along(moving, sheet, d);
  if (!clearance) {
    throw InputError(fmt::format(
        "{}: tools[{}].position = \"touch\": tool '{}' moving along ({:g}, {:g}, {:g}) never "
        "meets the blank; check the motion's direction, or give position = \"as_meshed\"",
        config.file.string(), index, tc.name, d.x(), d.y(), d.z()));
  }
  const double shift = *clearance - least_half;
  mesh.nodes.colwise() += shift * d;
  return shift;
}

void read_tools(const CaseConfig& config, Model& model) {
  for (std::size_t t = 0; t < config.tools.size(); ++t) {
    const ToolConfig& tc = config.tools[t];
    const GmshModel gmsh_model =
        load_mesh_source(config, tc.mesh, fmt::format("tools[{}]", t), false);
    Tool tool;
    tool.name = tc.name;
    tool.mesh = extract_part_mesh(gmsh_model, tc.mesh.group, tc.name);
    if (tool.mesh.quads.cols() > 0) {
      throw InputError(
          fmt::format("{}: tool '{}' group '{}' holds quadrilaterals; tools must be "
                      "meshed as triangles",
                      tc.mesh.file.string(), tc.name, tc.mesh.group));
    }
    if (tc.position == ToolConfig::Position::touch) {
      tool.touch_shift = move_to_touch(config, t, model, tool.mesh);
    }
    tool.surface = TriangleSurface(tc.name, tool.mesh.nodes, tool.mesh.triangles);
    tool.orientation = orient_surface(tool.surface, model.blank.mesh.nodes);
    // A force-controlled tool keeps a fixed RigidToolMotion; its ForceControlledTool is set up
    // once the blank's mass and the contact springs are known (set_up_force_controlled_tools).
    if (tc.motion.type != MotionConfig::Type::force) {
      tool.motion = RigidToolMotion(tc.motion);
      tool.motion.move_pivot(tool.touch_shift * tool.motion.direction());
    }
    model.tools.push_back(std::move(tool));
  }
}

LoadCurve make_scale_curve(const CurveConfig& curve) {
  return curve.times.empty() ? LoadCurve({0.0}, {1.0}) : LoadCurve(curve.times, curve.values);
}

// A static analysis: a load without a curve ramps from zero at time 0 to its value at end_time (in
// an explicit run it would be constant), and so does gravity: the static step follows the load
// from the unloaded state.
void ramp_loads_without_curves(const CaseConfig& config, double end_time, ExternalLoads& loads) {
  const LoadCurve ramp({0.0, end_time}, {0.0, 1.0});
  std::size_t nodal = 0;
  std::size_t pressure = 0;
  for (const LoadConfig& lc : config.loads) {  // the loads are in the case's order
    LoadCurve& scale = lc.type == LoadConfig::Type::pressure ? loads.pressures.at(pressure++).scale
                                                             : loads.nodal.at(nodal++).scale;
    if (lc.curve.times.empty()) {
      scale = ramp;
    }
  }
  loads.gravity_scale = ramp;
}

void set_up_loads(const CaseConfig& config, Model& model) {
  ExternalLoads& loads = model.loads;
  const Blank& blank = model.blank;
  for (const LoadConfig& lc : config.loads) {
    const NodeGroup& group = blank.group(lc.group);
    if (lc.type == LoadConfig::Type::pressure) {
      // The elements (quads, then triangles, numbered as in ShellPart) whose nodes all lie in
      // the group.
      std::vector<char> in_group(static_cast<std::size_t>(blank.mesh.nodes.cols()), 0);
      for (int node : group.nodes) {
        in_group[static_cast<std::size_t>(node)] = 1;
      }
      PressureLoad pressure{{}, lc.pressure, make_scale_curve(lc.curve)};
      for (const ElementBlock& block : element_blocks(blank.mesh.quads, blank.mesh.triangles)) {
        for (int e = block.first; e < block.end(); ++e) {
          const int* nodes = block.element_nodes(e);
          bool all = true;
          for (int a = 0; a < block.nodes_per_element(); ++a) {
            all = all && in_group[static_cast<std::size_t>(nodes[a])];
          }
          if (all) {
            pressure.elements.push_back(e);
          }
        }
      }
      if (pressure.elements.empty()) {
        throw InputError(
            fmt::format("{}: pressure load on group '{}': the group holds no whole "
                        "element of the blank (give a surface group)",
                        config.file.string(), lc.group));
      }
      loads.pressures.push_back(std::move(pressure));
    } else {
      loads.nodal.push_back({group.nodes, Vec3(lc.value[0], lc.value[1], lc.value[2]),
                             lc.type == LoadConfig::Type::moment, make_scale_curve(lc.curve)});
    }
  }
  loads.gravity =
      Vec3(config.control.gravity[0], config.control.gravity[1], config.control.gravity[2]);
  loads.damping = config.control.damping;
  if (config.analysis.type == AnalysisConfig::Type::static_equilibrium) {
    ramp_loads_without_curves(config, model.time.end_time, loads);
  }
}

// Selective mass scaling (docs/time-integration.md): every element whose stable step is below
// control.mass_scaling_dt gets the density that brings it to that step; the others keep theirs.
void set_mass_and_time_step(const CaseConfig& config, Model& model, const ShellState& state) {
  Blank& blank = model.blank;
  const ControlConfig& control = config.control;
  compute_lumped_mass(blank.part, blank.mesh.nodes, state, blank.mass, blank.rotational_inertia);
  blank.physical_mass = blank.mass.sum();
  blank.physical_nodal_mass = blank.mass;
  const bool explicit_run = !model.analysis.is_static();
  if (explicit_run) {  // before mass scaling, which would divide by a step of 0
    check_critical_time_step(config, blank,
                             compute_stable_time_step(blank.part, blank.mesh.nodes, state));
  }
  set_up_mass_scaling(blank.part, blank.mesh.nodes, state, control.mass_scaling_dt,
                      control.time_step_safety, blank.scaling);
  const TimeStepCheck step =
      scale_mass_to_time_step(blank.part, blank.node_corners, blank.mesh.nodes, blank.scaling,
                              blank.mass, blank.rotational_inertia);
  const double limit = control.mass_scaling_max_added;
  if (limit > 0.0 && blank.scaling.added_mass > limit * blank.physical_mass) {
    throw InputError(fmt::format(
        "{}: control.mass_scaling_dt = {:.4e} s adds {:.2f} % of the blank's mass at the start, "
        "more than control.mass_scaling_max_added = {:.2f} %; lower the target step or raise "
        "the limit",
        config.file.string(), control.mass_scaling_dt,
        100.0 * blank.scaling.added_mass / blank.physical_mass, 100.0 * limit));
  }
  model.time.time_step = step.dt;
  model.time.limiting_element = step.element;
  if (explicit_run) {
    check_scaled_time_step(config, model);
  }
}

// The blank's material with the largest bulk modulus (the stiffest penalty; the stability cap
// bounds it per node).
const MaterialConfig& stiffest_blank_material(const CaseConfig& config) {
  const MaterialConfig* best = nullptr;
  double best_bulk = 0.0;
  for (const BlankPartConfig& p : config.blank_parts()) {
    const MaterialConfig& m = config.material_named(p.material);
    const double bulk = m.young / (3.0 * (1.0 - 2.0 * m.poisson));
    if (best == nullptr || bulk > best_bulk) {
      best = &m;
      best_bulk = bulk;
    }
  }
  return *best;
}

// A table of the case as the friction law's.
FrictionTable friction_table(const std::vector<std::array<double, 2>>& points) {
  FrictionTable table;
  for (const auto& [x, y] : points) {
    table.x.push_back(x);
    table.y.push_back(y);
  }
  return table;
}

// The friction beyond Coulomb of a [[contact]] (docs/contact.md, "Friction laws"): the pressure
// law or table, the slip-speed table, the orthotropic ratio along the blank's rolling direction,
// and the nodes' start areas for the contact pressure when the law depends on it.
void set_friction_law(const CaseConfig& config, const ContactConfig& cc, const Model& model,
                      ContactPair& pair) {
  FrictionParameters& law = pair.friction;
  law.pressure_exponent = cc.friction_pressure_exponent;
  if (cc.friction_pressure_exponent != 1.0) {
    law.reference_pressure = cc.friction_reference_pressure;
  }
  law.pressure_table = friction_table(cc.friction_pressure_table);
  law.speed_table = friction_table(cc.friction_speed_table);
  law.across_ratio = cc.friction_across_ratio;
  const auto& d = config.blank.rolling_direction;  // unit: normalised on reading
  law.rolling_direction = Vec3(d[0], d[1], d[2]);
  if (law.active()) {
    try {
      law.validate(cc.tool);
    } catch (const InputError& error) {
      throw InputError(fmt::format("{}: {}", config.file.string(), error.what()));
    }
  }
  if (law.needs_pressure()) {
    const Blank& blank = model.blank;
    pair.start_area =
        nodal_tributary_area(blank.mesh.nodes, blank.mesh.quads, blank.mesh.triangles);
    pair.start_half_thickness = initial_half_thickness(blank, model.initial);
  }
}

void set_up_contacts(const CaseConfig& config, Model& model, const ShellState& state) {
  const MaterialConfig& material = stiffest_blank_material(config);
  for (const ContactConfig& cc : config.contacts) {
    ContactInterface contact;
    contact.search = cc.search;
    contact.audit = cc.audit;
    const auto found = std::find_if(model.tools.begin(), model.tools.end(),
                                    [&](const Tool& t) { return t.name == cc.tool; });
    contact.tool = static_cast<int>(found - model.tools.begin());
    const Tool& tool = model.tools[static_cast<std::size_t>(contact.tool)];
    contact.pair.surface = &tool.surface;
    contact.pair.search = make_contact_search(contact.search, tool.surface,
                                              SearchOptions{.cached_margin = cc.search_margin});
    // Nodes far from the tool are skipped until their motion could bring them within reach.
    contact.pair.distance_bound = std::make_unique<ToolDistanceBound>(tool.surface);
    // The contact spring adds to the element stiffness at a node: with the element part at
    // w_e dt <= 2 x safety (1.8), the total stays below the stability limit w dt = 2 when the
    // contact part keeps w_c dt <= sqrt(4 - 1.8^2) = 0.87, i.e. a cap factor of 0.87 / 2.
    const double safety = config.control.time_step_safety;
    const double contact_cap_factor = 0.5 * std::sqrt(std::max(4.0 - 4.0 * safety * safety, 0.0));
    if (contact_cap_factor < 0.2) {
      throw InputError(fmt::format(
          "{}: control.time_step_safety = {} leaves no room for the contact stiffness in the "
          "stable time step; use 0.95 or less with contact",
          config.file.string(), safety));
    }
    if (cc.penalty_stiffness > 0.0) {
      contact.pair.stiffness =
          VectorX::Constant(model.blank.mesh.nodes.cols(), cc.penalty_stiffness);
      const int capped = cap_penalty_stiffness(contact.pair.stiffness, model.blank.mass,
                                               model.time.time_step, contact_cap_factor);
      if (capped > 0) {
        log_info(
            "contact with tool '{}': penalty_stiffness = {} N/mm lowered at {} of {} blank nodes "
            "to keep the stable time step (cap k <= m (2 f / dt)^2, docs/contact.md)",
            cc.tool, cc.penalty_stiffness, capped, contact.pair.stiffness.size());
      }
    } else {
      contact.pair.stiffness = compute_penalty_stiffness(
          model.blank.mesh.nodes, model.blank.mesh.quads, model.blank.mesh.triangles,
          model.blank.mass, material.young, material.poisson, cc.penalty_scale,
          model.time.time_step, contact_cap_factor);
    }
    contact.pair.projection = cc.projection;
    if (contact.pair.projection == ContactProjection::interpolated) {
      contact.pair.projector = std::make_unique<InterpolatedProjector>(tool.surface);
    }
    contact.pair.friction.static_coefficient = cc.friction_static;
    contact.pair.friction.dynamic_coefficient = cc.friction_dynamic;
    contact.pair.friction.decay = cc.friction_decay;
    set_friction_law(config, cc, model, contact.pair);
    // Nodes farther than this from the tool cannot touch it within one step.
    contact.pair.cutoff = 2.0 * config.largest_blank_thickness();
    model.contacts.push_back(std::move(contact));
  }
}

// Force-controlled tools (docs/time-integration.md, "Force-controlled tools"): the mass (default:
// the blank's mass at the start, mass scaling included) and its stability check. The tool is
// coupled to the blank through the contact springs k_i, each capped at k_i <= m_i (w_c / dt)^2
// (w_c = sqrt(4 - 4 safety^2) = 0.87 at safety 0.9: the share of the stability limit the element
// leaves to the contact). The tool on those springs has the frequency sqrt(sum k / M), held to the
// same bound: M >= sum k (dt / w_c)^2 over the blank nodes of its contact pair (every node: which
// ones will touch is not known at the start). The default mass always passes, as sum k <=
// (w_c / dt)^2 sum m. The damping must keep c dt < 1 at the initial step (the explicit update is
// stable for c dt < 2: a factor 2 of margin for the step to grow in the run).
void set_up_force_controlled_tools(const CaseConfig& config, Model& model) {
  const double dt = model.time.time_step;
  const double safety = config.control.time_step_safety;
  const double w_c = std::sqrt(std::max(4.0 - 4.0 * safety * safety, 0.0));
  const double default_mass = model.blank.mass.sum();
  for (std::size_t t = 0; t < config.tools.size(); ++t) {
    const ToolConfig& tc = config.tools[t];
    if (tc.motion.type != MotionConfig::Type::force) {
      continue;
    }
    const double mass = tc.motion.mass.value_or(default_mass);
    double k_sum = 0.0;
    for (const ContactInterface& c : model.contacts) {
      if (c.tool == static_cast<int>(t)) {
        k_sum += c.pair.stiffness.sum();
      }
    }
    const auto& d = tc.motion.direction;
    const bool of_travel = tc.motion.force_of == MotionConfig::ForceOf::travel;
    ForceControlledTool tool(Vec3(d[0], d[1], d[2]),
                             LoadCurve(tc.motion.curve.times, tc.motion.curve.values), mass,
                             tc.motion.damping, of_travel);
    k_sum += tool.stiffness();  // a force of the travel is a spring on the tool too
    const double minimum_mass = k_sum * (dt / w_c) * (dt / w_c);
    if (mass < minimum_mass * (1.0 - 1e-12)) {
      throw InputError(fmt::format(
          "{}: tools[{}].motion.mass: tool '{}': a mass of {:.4e} tonne is too small for a stable "
          "run: on the blank's contact springs (and its force's slope against its travel; sum k "
          "= {:.4e} N/mm) the tool's frequency "
          "sqrt(sum k / mass) times the step {:.4e} s is {:.3f}, above {:.3f}, the bound on every "
          "contact spring at time_step_safety = {}; give mass >= {:.4e} tonne, or leave it out "
          "(the default, the blank's mass, {:.4e} tonne, is always enough)",
          config.file.string(), t, tc.name, mass, k_sum, dt, std::sqrt(k_sum / mass) * dt, w_c,
          safety, minimum_mass, default_mass));
    }
    if (!(tc.motion.damping * dt < 1.0)) {
      throw InputError(fmt::format(
          "{}: tools[{}].motion.damping: tool '{}': damping = {} 1/s times the step {:.4e} s is "
          "{:.3g}; it must stay below 1 (the explicit damping is unstable at 2): give damping < "
          "{:.4e} 1/s",
          config.file.string(), t, tc.name, tc.motion.damping, dt, tc.motion.damping * dt,
          1.0 / dt));
    }
    model.tools[t].force_control = std::move(tool);
  }
}

// The stroke tool's motion never travels control.stroke: the message names the case file, the
// stroke and the tool's curve, and how far the curve goes.
[[noreturn]] void throw_stroke_not_reached(const CaseConfig& config, std::size_t index,
                                           const Tool& tool) {
  const MotionConfig& motion = config.tools[index].motion;
  if (!tool.motion.moves()) {
    throw InputError(fmt::format(
        "{}: control.stroke_tool: tool '{}' (tools[{}]) does not move, so it cannot define the "
        "stroke",
        config.file.string(), tool.name, index));
  }
  const bool velocity = motion.type == MotionConfig::Type::velocity;
  const char* curve = velocity ? "velocity" : "displacement";
  const double end = RigidToolMotion::kTravelSearchEnd;
  throw InputError(fmt::format(
      "{}: control.stroke = {} mm: tool '{}' never travels that far: its tools[{}].motion.curve "
      "(type = \"{}\", {}) reaches {:.6g} mm by t = {:g} s (after its last point the {} holds its "
      "last value); give a curve that reaches the stroke, or a smaller control.stroke (or "
      "--stroke)",
      config.file.string(), config.control.stroke, tool.name, index, curve,
      velocity ? "[s, mm/s]" : "[s, mm]", tool.motion.travel(end), end, curve));
}

void set_end_time(const CaseConfig& config, Model& model) {
  const ControlConfig& control = config.control;
  if (!control.stroke_tool.empty()) {
    for (std::size_t i = 0; i < model.tools.size(); ++i) {
      if (model.tools[i].name == control.stroke_tool) {
        model.time.stroke_tool = static_cast<int>(i);
      }
    }
  }
  if (control.stroke > 0.0) {
    const Tool& tool = model.tools[static_cast<std::size_t>(model.time.stroke_tool)];
    if (tool.force_control) {
      // read_case refuses it too; a configuration made in code may not have been read.
      throw InputError(fmt::format(
          "{}: control.stroke_tool: tool '{}' is force-controlled (its travel follows from the "
          "force), so it cannot define the stroke",
          config.file.string(), tool.name));
    }
    const std::optional<double> end = tool.motion.time_at_travel(control.stroke);
    if (!end) {
      throw_stroke_not_reached(config, static_cast<std::size_t>(model.time.stroke_tool), tool);
    }
    model.time.end_time = *end;
  } else {
    model.time.end_time = control.end_time;
  }
}

std::vector<ReactionEntry> make_reaction_entries(const CaseConfig& config) {
  std::vector<ReactionEntry> out;
  for (std::size_t i = 0; i < config.boundaries.size(); ++i) {
    const BoundaryConfig& b = config.boundaries[i];
    ReactionEntry r{fmt::format("boundary[{}]", i), b.group, std::nullopt, -1};
    if (b.normal) {
      r.axes = make_plane_frame(Vec3((*b.normal)[0], (*b.normal)[1], (*b.normal)[2]));
    } else if (b.axes) {
      r.axes = make_frame(*b.axes);
    }
    out.push_back(std::move(r));
  }
  for (std::size_t i = 0; i < config.prescribed_velocities.size(); ++i) {
    out.push_back({fmt::format("prescribed_velocity[{}]", i), config.prescribed_velocities[i].group,
                   std::nullopt, -1});
  }
  for (std::size_t i = 0; i < config.prescribed_motions.size(); ++i) {
    const PrescribedMotionConfig& pm = config.prescribed_motions[i];
    ReactionEntry r{fmt::format("prescribed_motion[{}]", i), pm.group, std::nullopt, pm.dof};
    if (pm.axes) {
      r.axes = make_frame(*pm.axes);
    }
    out.push_back(std::move(r));
  }
  return out;
}

// The parts of the model that are the case's settings as they are.
void copy_plans(const CaseConfig& config, Model& model) {
  model.case_file = config.file;
  model.initial.integration_points = config.blank.integration_points;
  model.initial.thickness = config.largest_blank_thickness();
  model.initial.velocities = config.initial_velocities;
  TimeControl& time = model.time;
  time.progress_interval = config.control.progress_interval;
  time.energy_blowup_ratio = config.control.energy_blowup_ratio;
  time.land_on_end = config.control.land_on_end;
  time.mass_scaling_max_added = config.control.mass_scaling_max_added;
  OutputPlan& output = model.output;
  output.frames = config.control.output_frames;
  output.history_interval = config.control.history_interval;
  output.checkpoint_cycles = config.control.checkpoint_cycles;
  output.checkpoint_minutes = config.control.checkpoint_minutes;
  output.stress_layers = config.output.stress_layers;
  output.units = config.units;
  output.draw_ins = config.draw_ins;
  output.history_groups = config.history_groups;
  output.reactions = make_reaction_entries(config);
  model.formability = make_formability_plan(config);
  model.analysis.type = config.analysis.type;
  model.analysis.linear = config.analysis.linear;
  model.analysis.implicit = config.implicit;
  model.springback = config.springback;
}

}  // namespace

const NodeGroup& Blank::group(const std::string& name) const {
  for (const NodeGroup& g : groups) {
    if (g.name == name) {
      return g;
    }
  }
  throw std::logic_error("node group '" + name + "' was not read by build_model");
}

CaseConfig resolve_case(const CaseConfig& config, const Model& model) {
  CaseConfig resolved = config;
  for (std::size_t t = 0; t < model.tools.size() && t < resolved.tools.size(); ++t) {
    if (model.tools[t].force_control) {
      resolved.tools[t].motion.mass = model.tools[t].force_control->mass();  // tonne
    }
  }
  // A material judged by the Keeler-Brazier curve: that curve, when every part of it has the same
  // (one thickness), so that the resolved case says what the run used.
  const std::vector<BlankPartConfig> parts = config.blank_parts();
  for (MaterialConfig& material : resolved.materials) {
    const FormingLimitCurve* used = nullptr;
    bool one_curve = material.forming_limit_curve.empty();
    for (std::size_t i = 0; i < parts.size() && i < model.formability.part_curves.size(); ++i) {
      const FormingLimitCurve& curve = model.formability.part_curves[i];
      if (parts[i].material == material.name) {
        one_curve = one_curve && !curve.empty() && (!used || used->points == curve.points);
        used = &curve;
      }
    }
    if (one_curve && used) {
      material.forming_limit_curve = used->points;
    }
  }
  return resolved;
}

Model build_model(const CaseConfig& config, const BlankMesh* blank) {
  Model model;
  copy_plans(config, model);
  read_blank(config, model, blank);
  if (!config.blank.parts.empty()) {
    model.initial.element_thickness = element_thicknesses(model.blank);
  }
  read_tools(config, model);
  const ShellState state = make_blank_shell_state(model.blank, model.initial);
  set_mass_and_time_step(config, model, state);
  check_physical_ranges(config, model);
  set_up_contacts(config, model, state);
  set_up_drawbeads(config, model);
  set_up_force_controlled_tools(config, model);
  set_end_time(config, model);
  build_operations(config, model);
  assemble_constraints(config, model.blank, model.time.end_time, model);
  set_up_loads(config, model);
  // The contact pairs point at the tools' surfaces: the tools vector must not move again.
  for (ContactInterface& c : model.contacts) {
    c.pair.surface = &model.tools[static_cast<std::size_t>(c.tool)].surface;
  }
  model.output.resolved_case = format_resolved_case(resolve_case(config, model));
  return model;
}

}  // namespace sf
