#pragma once
// The run state: everything that changes during a run (nodal kinematics and forces, masses under
// mass scaling, the blank's integration point state, the tools' positions, the energies, timers).
// The Model stays const; a run is its model plus this state.
#include <memory>
#include <vector>

#include "contact/contact_state.hpp"
#include "contact/drawbead_line.hpp"
#include "contact/penalty_contact.hpp"
#include "element/shell_bt.hpp"
#include "model/mass_scaling.hpp"
#include "model/model.hpp"
#include "solver/domain.hpp"
#include "solver/energies.hpp"
#include "solver/phase_times.hpp"

namespace sf {

struct ToolState {
  double travel = 0.0;               ///< mm along the motion direction
  Vec3 displacement = Vec3::Zero();  ///< mm
  Vec3 force = Vec3::Zero();         ///< N, force of the blank on the tool
  int nodes_in_contact = 0;
  /// N, the largest push against the motion so far (a fixed tool: along -z, either sign)
  double peak_force = 0.0;
  Vec3 previous_displacement = Vec3::Zero();  ///< mm, a step ago (for the work increment)
  Vec3 previous_force = Vec3::Zero();         ///< N, a step ago
  /// Its placement's rotation: the mesh's point X stands at rotation X + displacement
  /// (contact/tool_placement.hpp); identity for a tool that never turned.
  Mat3 rotation = Mat3::Identity();
  Mat3 previous_rotation = Mat3::Identity();  ///< a step ago
  double angle = 0.0;                         ///< rad, its turn about its motion's axis
  /// N mm, the moment of the blank's forces on the tool about the origin (a turning tool's;
  /// zero for one that only translates)
  Vec3 moment = Vec3::Zero();
  Vec3 previous_moment = Vec3::Zero();  ///< N mm, a step ago
  /// mm/s along the direction at the state's time: a prescribed motion's speed; for a
  /// force-controlled tool the whole-step velocity v(n+1) = v(n+1/2) + dt/2 u(n+1)
  double speed = 0.0;
  /// mm/s, force-controlled tools: the half-step velocity v(n+1/2) the step integrates (v(0)
  /// before the first step)
  double velocity = 0.0;
  /// Held where it is for the rest of the run (springback by dynamic relaxation): its travel and
  /// displacement stay, its speed is 0, a force-controlled tool no longer follows its force.
  bool held = false;
  /// Where its motion in effect starts (model/operation_plan.hpp); the case's own from time 0
  /// unless an operation gave it another or restarted it.
  ToolMotionOrigin origin;
};

/// Which operation of the press line the run is in (a case without [[operations]]: 0 always).
struct OperationState {
  int index = 0;
  double start_time = 0.0;  ///< s
  long start_cycle = 0;
  /// s, when a stroke or time end is reached (found at the operation's start); otherwise the
  /// latest it may end, past which the run stops with an error
  double end_time = 0.0;
  double peak_kinetic = 0.0;  ///< N mm, the largest kinetic energy in the operation so far
};

struct SolutionState {
  double time = 0.0;  ///< s
  long cycle = 0;
  double dt = 0.0;         ///< s, the last step taken (may be cut short to land on the end time)
  double stable_dt = 0.0;  ///< s, the last stable step (safety included, after mass scaling)
  int dt_element = -1;     ///< the element limiting stable_dt
  double min_stable_dt = 0.0;  ///< s, smallest stable_dt of the run so far (0 before any step)
  double max_stable_dt = 0.0;  ///< s, largest stable_dt of the run so far
  int min_dt_element = -1;     ///< the element limiting min_stable_dt
  Matrix3X x;                  ///< mm, current coordinates
  Matrix3X v;                  ///< mm/s, at the half step (v(0) before the first step)
  Matrix3X omega;              ///< rad/s, at the half step (likewise)
  /// rad, per node, the rotation increments summed since time 0 (explicit: omega dt per step;
  /// static: the converged increments' dtheta): the rotation vector for a rotation about a fixed
  /// axis, a first-order measure of a general one
  Matrix3X rotation;
  Matrix3X f_int;              ///< N, internal forces (resisting)
  Matrix3X m_int;              ///< N mm, internal moments (resisting)
  Matrix3X f_contact;          ///< N, contact forces on the blank nodes
  Matrix3X f_ext;              ///< N, applied forces (loads, pressure, gravity)
  Matrix3X m_ext;              ///< N mm, applied moments
  Matrix3X f_ext_previous;     ///< N, a step ago (for the work increment)
  Matrix3X m_ext_previous;     ///< N mm
  Matrix3X f_int_previous;     ///< N, for the trapezoidal work increment
  Matrix3X m_int_previous;     ///< N mm
  VectorX half_thickness;      ///< mm per node, the contact offset
  VectorX mass;                ///< tonne per node (grows under mass scaling)
  VectorX rotational_inertia;  ///< tonne mm^2 per node (likewise)
  MassScaling scaling;         ///< the elements' density factors and the added mass so far
  /// The cycle at which the element force pass last filled scaling.element_dt (the elements'
  /// critical steps at x); -1: never. compute_time_step uses them when they are of this cycle.
  long element_dt_cycle = -1;
  VectorX inverse_mass;     ///< 1/tonne per node, 1 / mass (update_inverse_masses)
  VectorX inverse_inertia;  ///< 1/(tonne mm^2) per node, 1 / rotational_inertia
  VectorX mass_before;      ///< tonne per node, scratch: the masses before this cycle's scaling
  VectorX inertia_before;   ///< tonne mm^2 per node, likewise
  /// N, the contact forces on the blank nodes a step ago (for the contact work increment).
  Matrix3X f_contact_previous;
  /// N mm, sum of 1/2 k g^2 over the penalty springs at the current state: a diagnostic only
  /// (energies.contact is the work done against the contact forces, docs/time-integration.md).
  double contact_spring_energy = 0.0;
  ShellState shell;
  ElementPass element_pass;  ///< the element passes' corner buffer and per-thread sums (scratch)
  /// What this process computes of the blank and how its partial sums become whole (serial: the
  /// identity; an MPI rank: its share, solver/domain.hpp).
  std::shared_ptr<Domain> domain = std::make_shared<SerialDomain>();
  std::vector<ToolState> tools;
  /// One per Model::contacts: the search caches, distance bounds and stick forces (sized by the
  /// first contact call).
  std::vector<ContactState> contacts;
  std::vector<ExactSum> contact_sums;  ///< scratch: every pair's exact sums of a contact call
  /// One per Model::drawbeads: each node's stick force across the bead (sized by the first call).
  std::vector<DrawbeadState> drawbeads;
  /// Scratch of the pressure loads: kLoadCornerWidth per corner slot (sized by the first call).
  std::vector<double> pressure_corners;
  /// Springback by dynamic relaxation: the contact is off, and the forces the tools held the
  /// blank with act as these nodal loads (released over time) besides the model's own.
  bool contact_off = false;
  std::vector<NodalLoad> released_loads;
  Energies energies;
  double peak_kinetic_ratio = 0.0;  ///< after the first tenth of the run
  OperationState operation;         ///< the operation of the press line the run is in
  PhaseTimes times;                 ///< wall time per phase of the steps
};

/// Sets state.inverse_mass and inverse_inertia from the masses (after they change).
inline void update_inverse_masses(SolutionState& s) {
  s.inverse_mass = s.mass.cwiseInverse();  // same size after the first call: no allocation
  s.inverse_inertia = s.rotational_inertia.cwiseInverse();
}

}  // namespace sf
