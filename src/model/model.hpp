#pragma once
// The model: everything the time loop needs, built once from the case and the meshes by
// build_model (the one place that sees both).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contact/penalty_contact.hpp"
#include "element/shell_bt.hpp"
#include "io/case_config.hpp"
#include "mesh/mesh_data.hpp"
#include "mesh/triangle_surface.hpp"
#include "model/boundary_conditions.hpp"
#include "model/force_controlled_tool.hpp"
#include "model/mass_scaling.hpp"
#include "model/rigid_tool_motion.hpp"

namespace sf {

/// The deformable blank: mesh, element description, mass and named node groups.
struct Blank {
  PartMesh mesh;
  ShellPart part;
  VectorX mass;                   ///< tonne per node (after any mass scaling; grows in the run)
  VectorX rotational_inertia;     ///< tonne mm^2 per node (likewise)
  double physical_mass = 0.0;     ///< tonne, before mass scaling
  MassScaling scaling;            ///< per-element density factors and the added mass
  VectorX inverse_element_count;  ///< per node, 1 / (elements sharing it), for nodal averages
  VectorX physical_nodal_mass;    ///< tonne per node before mass scaling (for gravity)
  std::vector<NodeGroup> groups;  ///< every node group the case names, each once

  /// The node group of this name (build_model reads every group the case names).
  const NodeGroup& group(const std::string& name) const;
};

/// A force or moment per node, scaled over time.
struct NodalLoad {
  std::vector<int> nodes;
  Vec3 value = Vec3::Zero();  ///< N (force) or N mm (moment) per node
  bool moment = false;
  LoadCurve scale;  ///< scale factor against time
};

/// A pressure on the top face of a set of elements, following the deforming surface.
struct PressureLoad {
  std::vector<int> elements;  ///< numbered as in ShellPart: quads, then triangles
  double pressure = 0.0;      ///< MPa
  LoadCurve scale;
};

/// One degree of freedom of a set of nodes driven along a curve ([[prescribed_motion]], or one
/// component of a [[prescribed_velocity]]): at node nodes[k] the component component[k] (0..5, in
/// the node's axes: NodalConstraints) equals sign[k] x target(t).
struct PrescribedMotion {
  enum class Kind { displacement, velocity };
  Kind kind = Kind::velocity;
  std::string entry;               ///< the case entry, e.g. "prescribed_motion[0]", for messages
  std::string group;               ///< its node group
  bool rotation = false;           ///< a rotation (rad, rad/s) rather than a translation (mm, mm/s)
  Vec3 direction = Vec3::UnitX();  ///< unit, global: the translation or the rotation axis driven
  double value = 1.0;              ///< mm, rad, mm/s or rad/s per unit of `scale`
  LoadCurve scale;                 ///< against time (s)
  std::vector<int> nodes;
  std::vector<unsigned char> component;  ///< per node: 0..5 in the node's axes
  std::vector<double> sign;              ///< per node: +1 or -1

  /// The prescribed displacement (mm, rad) or velocity (mm/s, rad/s) at time t (s).
  double target(double t) const { return value * scale.value(t); }
};

/// Everything that loads the blank besides the tools.
struct ExternalLoads {
  std::vector<NodalLoad> nodal;
  std::vector<PressureLoad> pressures;
  Vec3 gravity = Vec3::Zero();  ///< mm/s^2
  LoadCurve gravity_scale;      ///< scale factor against time; empty = 1 (explicit runs)
  double damping = 0.0;         ///< 1/s, mass-proportional
  bool empty() const { return nodal.empty() && pressures.empty() && gravity.isZero(); }
};

/// A rigid tool: its triangulated surface in the reference position and how it moves: a
/// prescribed motion, or (force_control set) driven by a force, its motion then fixed.
struct Tool {
  std::string name;
  PartMesh mesh;  ///< as read (for output)
  TriangleSurface surface;
  RigidToolMotion motion;
  std::optional<ForceControlledTool> force_control;

  /// The axis the tool moves along (the prescribed motion's or the force's; the case's default,
  /// -z, for a fixed tool).
  const Vec3& direction() const {
    return force_control ? force_control->direction() : motion.direction();
  }
};

/// A contact pair between all blank nodes and one tool's triangles.
struct ContactInterface {
  int tool = -1;       ///< index into Model::tools
  ContactPair pair;    ///< fixed for the run
  ContactState state;  ///< what changes during the run (sized by the first contact call)
};

struct Model {
  CaseConfig config;
  Blank blank;
  std::vector<Tool> tools;
  std::vector<ContactInterface> contacts;
  NodalConstraints constraints;  ///< held and prescribed degrees of freedom, node frames
  std::vector<PrescribedMotion> prescribed_motions;  ///< what drives the prescribed ones
  ExternalLoads loads;
  double end_time = 0.0;      ///< s, from control.end_time or the stroke
  int stroke_tool = -1;       ///< index of the tool whose travel is the stroke, or -1
  double time_step = 0.0;     ///< s, the initial stable step with the safety factor (after scaling)
  int limiting_element = -1;  ///< the element limiting time_step
};

}  // namespace sf
