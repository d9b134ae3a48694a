#pragma once
// Every field of the run state, described once (shared/DESIGN.md R7): its name, where it lives,
// its unit, what it means, and its roles: kept by a checkpoint, handed on in the formed part,
// gathered to the output process before output, and how it follows a change of the mesh. The
// checkpoint's list (checkpoint_fields.hpp), the formed-part file (formed_part.hpp) and the
// gathers of a distributed run (state_gather.cpp) are filters of this one walk, in its order.
//
// visit_state_fields(v, s) calls v(field, key, value) for every field, with `field` its
// StateField, `key` its storage name (the field's name, prefixed "tools/T/" or "contacts/C/"
// for a tool's or a contact pair's, suffixed with the component for a tool's vectors), and
// `value` a reference into the state: double, long, int or bool; Matrix3X or VectorX per node;
// std::vector<double> per element or integration point (s.shell.n_elements elements). The
// SolutionState members it does not visit are named, with the reason, in kStateLeftOut.
#include <array>
#include <string>
#include <string_view>
#include <type_traits>

#include "solver/solution_state.hpp"

namespace sf {

/// Where a field's values live.
enum class FieldPlace {
  run,      ///< one value for the run
  node,     ///< per blank node (3 columns or 1)
  element,  ///< per blank element (a fixed number of values each)
  point,    ///< per integration point through the thickness (e * n_points + k, a width each)
  tool,     ///< per rigid tool
  contact,  ///< per contact pair, per blank node
};

/// What a field is used for (bits of StateField::roles).
namespace field_role {
inline constexpr unsigned checkpoint = 1u;   ///< a checkpoint keeps it (a restart needs it)
inline constexpr unsigned formed_part = 2u;  ///< the formed part hands it to the next operation
/// a distributed run gathers it to the output process before a frame, a history row, the
/// summary or a springback (the rest of the checkpoint's fields only before a checkpoint)
inline constexpr unsigned output = 4u;
}  // namespace field_role

/// How a field follows a change of the blank's mesh (a trim, a refinement).
enum class FieldMapping {
  none,         ///< not of the mesh (a run value, a tool's)
  interpolate,  ///< a node's value from the nodes it is made between
  inherit,      ///< an element's or point's value from the element it is cut from
  /// the same, its components (in the element's frame) turned into the new element's frame
  inherit_in_frame,
  recompute,  ///< made again from the new mesh (masses, time steps, offsets)
  reset,      ///< starts again at zero (a contact pair's history, the force sums)
};

struct StateField {
  std::string_view name;
  FieldPlace place;
  std::string_view unit;  ///< in the model's units (mm, tonne, s; N, MPa, N mm)
  unsigned roles;
  FieldMapping mapping;
  std::string_view meaning;
  /// The name of the frame field (results.h5, ParaView) that writes it as it is; empty: none
  /// (the results' other fields are computed from the state: docs/results-format.md).
  std::string_view result = {};
  [[nodiscard]] constexpr bool has(unsigned role) const { return (roles & role) != 0; }
};

namespace state_field {
using enum FieldPlace;
using enum FieldMapping;
inline constexpr unsigned kCheckpoint = field_role::checkpoint;
inline constexpr unsigned kHandedOn = field_role::checkpoint | field_role::formed_part;
inline constexpr unsigned kShown = kHandedOn | field_role::output;

// The run's numbers.
inline constexpr StateField time{"time", run, "s", kHandedOn, none, "time of the state"};
inline constexpr StateField cycle{"cycle", run, "-", kHandedOn, none, "steps taken"};
inline constexpr StateField dt{"dt", run, "s", kHandedOn, none, "the last step taken"};
inline constexpr StateField stable_dt{"stable_dt", run,  "s",
                                      kHandedOn,   none, "the last stable step (safety included)"};
inline constexpr StateField dt_element{"dt_element", run,  "-",
                                       kHandedOn,    none, "the element limiting stable_dt"};
inline constexpr StateField min_stable_dt{"min_stable_dt", run,  "s",
                                          kHandedOn,       none, "smallest stable step so far"};
inline constexpr StateField max_stable_dt{"max_stable_dt", run,  "s",
                                          kHandedOn,       none, "largest stable step so far"};
inline constexpr StateField min_dt_element{
    "min_dt_element", run, "-", kHandedOn, none, "the element limiting min_stable_dt"};
inline constexpr StateField element_dt_cycle{
    "element_dt_cycle", run, "-", kHandedOn, none, "the cycle of mass_scaling/element_dt"};
inline constexpr StateField contact_spring_energy{
    "contact_spring_energy", run, "N mm", kCheckpoint, none, "1/2 k g^2 over the penalty springs"};
// A diagnostic of each run's own window (after the first tenth of its end time): not handed on.
inline constexpr StateField peak_kinetic_ratio{
    "peak_kinetic_ratio", run, "-", kCheckpoint, none, "largest kinetic / internal energy so far"};

// The operation of the press line the run is in (a restart goes on inside it).
inline constexpr StateField operation_index{"operation/index", run,  "-",
                                            kCheckpoint,       none, "the operation (0, 1, ...)"};
inline constexpr StateField operation_start_time{
    "operation/start_time", run, "s", kCheckpoint, none, "when the operation started"};
inline constexpr StateField operation_start_cycle{
    "operation/start_cycle", run, "-", kCheckpoint, none, "the cycle it started at"};
inline constexpr StateField operation_end_time{
    "operation/end_time", run, "s", kCheckpoint, none, "its stroke or time end, or its latest"};
inline constexpr StateField operation_peak_kinetic{
    "operation/peak_kinetic", run, "N mm", kCheckpoint, none, "largest kinetic energy in it"};

// The blank's nodes.
inline constexpr StateField x{"x", node, "mm", kShown, interpolate, "coordinates"};
inline constexpr StateField v{
    "v", node, "mm/s", kShown, interpolate, "velocity at the half step", "velocity"};
inline constexpr StateField omega{"omega", node,        "rad/s",
                                  kShown,  interpolate, "angular velocity at the half step"};
inline constexpr StateField rotation{
    "rotation", node, "rad", kShown, interpolate, "rotation increments summed since time 0"};
inline constexpr StateField f_int{"f_int", node, "N", kShown, recompute, "internal forces"};
inline constexpr StateField m_int{"m_int", node, "N mm", kShown, recompute, "internal moments"};
inline constexpr StateField f_contact{
    "f_contact", node, "N", kShown, recompute, "contact forces on the blank", "contact_force"};
inline constexpr StateField f_ext{"f_ext", node, "N", kShown, recompute, "applied forces"};
inline constexpr StateField m_ext{"m_ext", node, "N mm", kShown, recompute, "applied moments"};
inline constexpr StateField f_ext_previous{
    "f_ext_previous", node,      "N",
    kHandedOn,        recompute, "applied forces a step ago (work increment)"};
inline constexpr StateField m_ext_previous{
    "m_ext_previous", node, "N mm", kHandedOn, recompute, "applied moments a step ago"};
inline constexpr StateField f_int_previous{
    "f_int_previous", node, "N", kHandedOn, recompute, "internal forces a step ago"};
inline constexpr StateField m_int_previous{
    "m_int_previous", node, "N mm", kHandedOn, recompute, "internal moments a step ago"};
inline constexpr StateField f_contact_previous{
    "f_contact_previous", node, "N", kHandedOn, recompute, "contact forces a step ago"};
inline constexpr StateField half_thickness{
    "half_thickness", node, "mm", kShown, recompute, "contact offset (half the nodal thickness)"};
inline constexpr StateField mass{"mass", node,      "tonne",
                                 kShown, recompute, "lumped mass (mass scaling included)"};
inline constexpr StateField rotational_inertia{
    "rotational_inertia", node, "tonne mm^2", kShown, recompute, "lumped rotational inertia"};
inline constexpr StateField inverse_mass{"inverse_mass", node,      "1/tonne",
                                         kHandedOn,      recompute, "1 / mass"};
inline constexpr StateField inverse_inertia{"inverse_inertia", node,      "1/(tonne mm^2)",
                                            kHandedOn,         recompute, "1 / rotational_inertia"};

// Mass scaling.
inline constexpr StateField added_mass{"mass_scaling/added_mass",     run, "tonne", kHandedOn, none,
                                       "mass added by scaling so far"};
inline constexpr StateField scaled_elements{
    "mass_scaling/scaled_elements", run, "-", kHandedOn, none, "elements with added mass"};
inline constexpr StateField density_factor{
    "mass_scaling/density_factor", element, "-", kShown, inherit, "scaled / physical density"};
inline constexpr StateField element_dt{
    "mass_scaling/element_dt", element, "s", kShown, recompute, "the element's critical step"};

// The blank's elements and integration points (element frame).
inline constexpr StateField sxx{"shell/sxx", point, "MPa", kShown, inherit_in_frame, "stress xx"};
inline constexpr StateField syy{"shell/syy", point, "MPa", kShown, inherit_in_frame, "stress yy"};
inline constexpr StateField sxy{"shell/sxy", point, "MPa", kShown, inherit_in_frame, "stress xy"};
inline constexpr StateField eps_p{"shell/eps_p", point,   "-",
                                  kShown,        inherit, "equivalent plastic strain"};
inline constexpr StateField flow_stress{
    "shell/flow_stress", point, "MPa", kShown, inherit, "flow stress at flow_stress_at"};
inline constexpr StateField flow_stress_at{
    "shell/flow_stress_at", point, "-", kShown, inherit, "the plastic strain of flow_stress"};
inline constexpr StateField sxz{"shell/sxz", element,          "MPa",
                                kShown,      inherit_in_frame, "transverse shear stress xz"};
inline constexpr StateField syz{"shell/syz", element,          "MPa",
                                kShown,      inherit_in_frame, "transverse shear stress yz"};
inline constexpr StateField thickness{"shell/thickness",   element,    "mm", kShown, inherit,
                                      "current thickness", "thickness"};
inline constexpr StateField hourglass{"shell/hourglass",
                                      element,
                                      "N, N mm",
                                      kShown,
                                      reset,
                                      "hourglass resultants (kHourglassModes per element)"};
inline constexpr StateField director{
    "shell/director", element,   "-",
    kShown,           recompute, "unit directors at the element's nodes (global)"};
inline constexpr StateField back_stress{"shell/back_stress",
                                        point,
                                        "MPa",
                                        kShown,
                                        inherit_in_frame,
                                        "back stresses (kinematic hardening)"};

// The energies.
inline constexpr StateField kinetic{"energies/kinetic", run, "N mm", kHandedOn, none, "kinetic"};
inline constexpr StateField internal{"energies/internal", run,  "N mm",
                                     kHandedOn,           none, "internal (elastic and plastic)"};
inline constexpr StateField hourglass_energy{"energies/hourglass", run, "N mm", kHandedOn, none,
                                             "hourglass"};
inline constexpr StateField contact_energy{
    "energies/contact", run, "N mm", kHandedOn, none, "work against the contact forces"};
inline constexpr StateField damping{"energies/damping", run,  "N mm",
                                    kHandedOn,          none, "dissipated by damping"};
inline constexpr StateField external_work{"energies/external_work",   run, "N mm", kHandedOn, none,
                                          "work of the applied loads"};
inline constexpr StateField initial_kinetic{
    "energies/initial_kinetic", run, "N mm", kHandedOn, none, "kinetic energy at the start"};
inline constexpr StateField mass_scaling_energy{
    "energies/mass_scaling", run, "N mm", kHandedOn, none, "kinetic energy of the added mass"};
inline constexpr StateField plastic_work{"energies/plastic_work", run, "N mm", kHandedOn, none,
                                         "plastic dissipation"};
inline constexpr StateField friction_work{"energies/friction_work", run, "N mm", kHandedOn, none,
                                          "friction dissipation"};
inline constexpr StateField half_kick{
    "energies/half_kick", run, "N mm", kHandedOn, none, "half-step kinetic energy correction"};
inline constexpr StateField half_kick_reference{
    "energies/half_kick_reference", run, "N mm", kHandedOn, none, "half_kick at the start"};

// The tools (rigid bodies of the case; the formed part records where they stand).
inline constexpr StateField tool_travel{"travel",  tool, "mm",
                                        kHandedOn, none, "travel along the motion direction"};
inline constexpr StateField tool_speed{
    "speed", tool, "mm/s", kHandedOn, none, "speed along the direction at the state's time"};
inline constexpr StateField tool_velocity{
    "velocity", tool, "mm/s", kHandedOn, none, "force-controlled: the half-step velocity"};
inline constexpr StateField tool_peak_force{
    "peak_force", tool, "N", kHandedOn, none, "largest push against the motion so far"};
inline constexpr StateField tool_nodes_in_contact{
    "nodes_in_contact", tool, "-", kHandedOn, none, "blank nodes touching it"};
inline constexpr StateField tool_held{"held",    tool, "-",
                                      kHandedOn, none, "held where it is for the rest of the run"};
inline constexpr StateField tool_displacement{"displacement", tool, "mm",
                                              kHandedOn,      none, "displacement (x, y, z)"};
inline constexpr StateField tool_force{"force",   tool, "N",
                                       kHandedOn, none, "force of the blank on the tool (x, y, z)"};
inline constexpr StateField tool_previous_displacement{
    "previous_displacement", tool, "mm", kHandedOn, none, "displacement a step ago"};
inline constexpr StateField tool_previous_force{"previous_force", tool, "N",
                                                kHandedOn,        none, "force a step ago"};
inline constexpr StateField tool_rotation{
    "rotation", tool, "-", kHandedOn, none, "rotation of its placement (row by row)"};
inline constexpr StateField tool_previous_rotation{"previous_rotation",  tool, "-", kHandedOn, none,
                                                   "rotation a step ago"};
inline constexpr StateField tool_angle{"angle",   tool, "rad",
                                       kHandedOn, none, "turn about its motion's axis"};
inline constexpr StateField tool_moment{
    "moment", tool, "N mm", kHandedOn, none, "moment of the blank's forces about the origin"};
inline constexpr StateField tool_previous_moment{"previous_moment", tool, "N mm",
                                                 kHandedOn,         none, "moment a step ago"};
// Where the tool's motion in effect starts; the next case's tools follow its own motions.
inline constexpr StateField tool_origin_operation{
    "origin_operation", tool, "-",
    kCheckpoint,        none, "the operation whose motion it follows (-1: the case's)"};
inline constexpr StateField tool_origin_start{
    "origin_start", tool, "s", kCheckpoint, none, "the time its motion counts from"};
inline constexpr StateField tool_origin_travel{
    "origin_travel", tool, "mm", kCheckpoint, none, "the travel its motion adds to"};
inline constexpr StateField tool_origin_displacement{
    "origin_displacement", tool, "mm", kCheckpoint, none, "the displacement it adds to"};
inline constexpr StateField tool_origin_rotation{
    "origin_rotation", tool, "-", kCheckpoint, none, "the rotation it turns from"};
inline constexpr StateField tool_origin_angle{"origin_angle", tool, "rad",
                                              kCheckpoint,    none, "the turn it adds to"};

// The contact pairs' history. The stick forces are handed on with their pair's tool (a pair of
// the next case with a tool of that name takes them); the distance bounds are only a shortcut
// of the search and start afresh.
inline constexpr StateField stick_force{
    "stick_force", contact, "N", kHandedOn, reset, "elastic stick force of the friction"};
// The contact's results: the normal force of the last call and the path slid over the tool,
// written per tool in every frame (as pressure and sliding distance) and handed on with their
// pair's tool, so that a chain's sliding distances add up.
inline constexpr StateField contact_normal_force{
    "normal_force", contact, "N", kShown, reset, "normal contact force (0 out of contact)"};
inline constexpr StateField sliding_distance{
    "sliding_distance", contact, "mm", kShown, reset, "path slid over the tool in contact"};
inline constexpr StateField bound_anchor{
    "bound_anchor", contact, "mm",
    kCheckpoint,    reset,   "distance bound: position at the last search"};
// A drawbead line's stick forces: a restart needs them; the next case's beads start afresh.
inline constexpr StateField bead_restraint{
    "restraint", contact, "N", kCheckpoint, reset, "a drawbead's stick force across its line"};
inline constexpr StateField drawbead_work{"energies/drawbead_work",
                                          run,
                                          "N mm",
                                          kCheckpoint,
                                          none,
                                          "slip work across the drawbead lines (part of contact)"};
inline constexpr StateField bound_slack{
    "bound_slack", contact, "mm",
    kCheckpoint,   reset,   "distance bound: distance left before a search"};
// The front bounds (issue 34): kept so that a restart skips the same nodes as the whole run.
inline constexpr StateField front_anchor{
    "front_anchor", contact, "mm", kCheckpoint, reset, "front bound: position where it was taken"};
inline constexpr StateField front_side{
    "front_side", contact, "mm",
    kCheckpoint,  reset,   "front bound: side slack (< 0: the last attempt failed)"};
inline constexpr StateField front_gap{"front_gap", contact, "mm",
                                      kCheckpoint, reset,   "front bound: gap slack (with h)"};
}  // namespace state_field

/// SolutionState members visit_state_fields does not visit, and why (tests/solver/
/// test_state_fields.cpp counts the members: one added must be described above or named here).
inline constexpr std::array<std::string_view, 17> kStateLeftOut = {
    "mass_before: scratch of one cycle's mass scaling",
    "inertia_before: scratch of one cycle's mass scaling",
    "scaling.scaled_dt, corner_mass: scratch of one cycle's mass scaling",
    "pressure_corners: scratch of one cycle's pressure loads",
    "scaling.target_dt, safety, element_mass, inertia_factor: the model's, set at the start",
    "element_pass: the corner buffer and per-thread sums, scratch",
    "domain: how the process shares the blank, not state",
    "contact_sums: scratch of one contact call",
    "drawbeads' shares: per-thread scratch",
    "contacts' search caches: rebuilt exactly (the cached search answers as the modified one)",
    "contacts' shares: per-thread scratch",
    "contacts' warned_beyond_table: the friction tables' warn-once flags, messages, not physics "
    "(a restarted run may warn again)",
    "contact_off: the springback's dynamic relaxation only, which writes no checkpoint",
    "released_loads: likewise",
    "times: wall-clock time per phase, not physics",
    "shell.n_elements, n_points: the model's sizes",
    "tools' and contacts' counts: the model's",
};

template <class Visitor, class State>
void visit_state_fields(Visitor& v, State& s) {
  static_assert(std::is_same_v<std::remove_const_t<State>, SolutionState>);
  namespace f = state_field;
  v(f::time, "time", s.time);
  v(f::cycle, "cycle", s.cycle);
  v(f::dt, "dt", s.dt);
  v(f::stable_dt, "stable_dt", s.stable_dt);
  v(f::dt_element, "dt_element", s.dt_element);
  v(f::min_stable_dt, "min_stable_dt", s.min_stable_dt);
  v(f::max_stable_dt, "max_stable_dt", s.max_stable_dt);
  v(f::min_dt_element, "min_dt_element", s.min_dt_element);
  v(f::element_dt_cycle, "element_dt_cycle", s.element_dt_cycle);
  v(f::contact_spring_energy, "contact_spring_energy", s.contact_spring_energy);
  v(f::peak_kinetic_ratio, "peak_kinetic_ratio", s.peak_kinetic_ratio);
  v(f::operation_index, std::string(f::operation_index.name), s.operation.index);
  v(f::operation_start_time, std::string(f::operation_start_time.name), s.operation.start_time);
  v(f::operation_start_cycle, std::string(f::operation_start_cycle.name), s.operation.start_cycle);
  v(f::operation_end_time, std::string(f::operation_end_time.name), s.operation.end_time);
  v(f::operation_peak_kinetic, std::string(f::operation_peak_kinetic.name),
    s.operation.peak_kinetic);
  for (const auto& [field, value] : {std::pair{&f::x, &s.x},
                                     {&f::v, &s.v},
                                     {&f::omega, &s.omega},
                                     {&f::rotation, &s.rotation},
                                     {&f::f_int, &s.f_int},
                                     {&f::m_int, &s.m_int},
                                     {&f::f_contact, &s.f_contact},
                                     {&f::f_ext, &s.f_ext},
                                     {&f::m_ext, &s.m_ext},
                                     {&f::f_ext_previous, &s.f_ext_previous},
                                     {&f::m_ext_previous, &s.m_ext_previous},
                                     {&f::f_int_previous, &s.f_int_previous},
                                     {&f::m_int_previous, &s.m_int_previous},
                                     {&f::f_contact_previous, &s.f_contact_previous}}) {
    v(*field, std::string(field->name), *value);
  }
  for (const auto& [field, value] : {std::pair{&f::half_thickness, &s.half_thickness},
                                     {&f::mass, &s.mass},
                                     {&f::rotational_inertia, &s.rotational_inertia},
                                     {&f::inverse_mass, &s.inverse_mass},
                                     {&f::inverse_inertia, &s.inverse_inertia}}) {
    v(*field, std::string(field->name), *value);
  }
  v(f::added_mass, std::string(f::added_mass.name), s.scaling.added_mass);
  v(f::scaled_elements, std::string(f::scaled_elements.name), s.scaling.scaled_elements);
  v(f::density_factor, std::string(f::density_factor.name), s.scaling.density_factor);
  v(f::element_dt, std::string(f::element_dt.name), s.scaling.element_dt);
  auto& shell = s.shell;
  for (const auto& [field, value] : {std::pair{&f::sxx, &shell.sxx},
                                     {&f::syy, &shell.syy},
                                     {&f::sxy, &shell.sxy},
                                     {&f::eps_p, &shell.eps_p},
                                     {&f::flow_stress, &shell.flow_stress},
                                     {&f::flow_stress_at, &shell.flow_stress_at},
                                     {&f::sxz, &shell.sxz},
                                     {&f::syz, &shell.syz},
                                     {&f::thickness, &shell.thickness},
                                     {&f::hourglass, &shell.hourglass},
                                     {&f::director, &shell.director},
                                     {&f::back_stress, &shell.back_stress}}) {
    v(*field, std::string(field->name), *value);
  }
  auto& e = s.energies;
  for (const auto& [field, value] : {std::pair{&f::kinetic, &e.kinetic},
                                     {&f::internal, &e.internal},
                                     {&f::hourglass_energy, &e.hourglass},
                                     {&f::contact_energy, &e.contact},
                                     {&f::damping, &e.damping},
                                     {&f::external_work, &e.external_work},
                                     {&f::initial_kinetic, &e.initial_kinetic},
                                     {&f::mass_scaling_energy, &e.mass_scaling},
                                     {&f::plastic_work, &e.plastic_work},
                                     {&f::friction_work, &e.friction_work},
                                     {&f::half_kick, &e.half_kick},
                                     {&f::half_kick_reference, &e.half_kick_reference}}) {
    v(*field, std::string(field->name), *value);
  }
  for (std::size_t t = 0; t < s.tools.size(); ++t) {
    auto& tool = s.tools[t];
    const std::string p = "tools/" + std::to_string(t) + "/";
    v(f::tool_travel, p + "travel", tool.travel);
    v(f::tool_speed, p + "speed", tool.speed);
    v(f::tool_velocity, p + "velocity", tool.velocity);
    v(f::tool_peak_force, p + "peak_force", tool.peak_force);
    v(f::tool_nodes_in_contact, p + "nodes_in_contact", tool.nodes_in_contact);
    v(f::tool_held, p + "held", tool.held);
    for (int c = 0; c < 3; ++c) {  // component by component, interleaved (checkpoint format 1)
      const std::string k = std::to_string(c);
      v(f::tool_displacement, p + "displacement" + k, tool.displacement[c]);
      v(f::tool_force, p + "force" + k, tool.force[c]);
      v(f::tool_previous_displacement, p + "previous_displacement" + k,
        tool.previous_displacement[c]);
      v(f::tool_previous_force, p + "previous_force" + k, tool.previous_force[c]);
    }
    // (format 3: a tool's turn)
    for (int c = 0; c < 9; ++c) {
      const std::string k = std::to_string(c);
      v(f::tool_rotation, p + "rotation" + k, tool.rotation(c / 3, c % 3));
      v(f::tool_previous_rotation, p + "previous_rotation" + k,
        tool.previous_rotation(c / 3, c % 3));
    }
    v(f::tool_angle, p + "angle", tool.angle);
    for (int c = 0; c < 3; ++c) {
      const std::string k = std::to_string(c);
      v(f::tool_moment, p + "moment" + k, tool.moment[c]);
      v(f::tool_previous_moment, p + "previous_moment" + k, tool.previous_moment[c]);
    }
    v(f::tool_origin_operation, p + "origin_operation", tool.origin.operation);
    v(f::tool_origin_start, p + "origin_start", tool.origin.start);
    v(f::tool_origin_travel, p + "origin_travel", tool.origin.travel);
    for (int c = 0; c < 3; ++c) {
      v(f::tool_origin_displacement, p + "origin_displacement" + std::to_string(c),
        tool.origin.displacement[c]);
    }
    for (int c = 0; c < 9; ++c) {
      v(f::tool_origin_rotation, p + "origin_rotation" + std::to_string(c),
        tool.origin.rotation(c / 3, c % 3));
    }
    v(f::tool_origin_angle, p + "origin_angle", tool.origin.angle);
  }
  for (std::size_t c = 0; c < s.contacts.size(); ++c) {
    auto& contact = s.contacts[c];
    const std::string p = "contacts/" + std::to_string(c) + "/";
    v(f::stick_force, p + "stick_force", contact.stick_force);
    // (format 4: the contact's results)
    v(f::contact_normal_force, p + "normal_force", contact.normal_force);
    v(f::sliding_distance, p + "sliding_distance", contact.sliding_distance);
    v(f::bound_anchor, p + "bound_anchor", contact.distance_bounds.anchors());
    v(f::bound_slack, p + "bound_slack", contact.distance_bounds.slacks());
    // (format 5: the front bounds)
    v(f::front_anchor, p + "front_anchor", contact.distance_bounds.front_anchors());
    v(f::front_side, p + "front_side", contact.distance_bounds.front_sides());
    v(f::front_gap, p + "front_gap", contact.distance_bounds.front_gaps());
  }
  // A case with drawbeads only (a case without keeps the layout of format 3).
  if (!s.drawbeads.empty()) {
    v(f::drawbead_work, std::string(f::drawbead_work.name), s.energies.drawbead_work);
  }
  for (std::size_t b = 0; b < s.drawbeads.size(); ++b) {
    v(f::bead_restraint, "drawbeads/" + std::to_string(b) + "/restraint", s.drawbeads[b].restraint);
  }
}

/// visit_state_fields restricted to the fields with `role`.
template <class Visitor, class State>
void visit_state_fields_with(unsigned role, Visitor& v, State& s) {
  auto filter = [&](const StateField& field, const std::string& key, auto& value) {
    if (field.has(role)) {
      v(field, key, value);
    }
  };
  visit_state_fields(filter, s);
}

}  // namespace sf
