#pragma once
// The model: everything the run needs, built once from the case and the meshes by build_model (the
// one place that sees both), in typed parts; const during the run (what changes lives in the run
// state, SolutionState). It keeps no copy of the case.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "casefile/case_config.hpp"
#include "contact/drawbead_line.hpp"
#include "contact/penalty_contact.hpp"
#include "element/shell_bt.hpp"
#include "mesh/mesh_data.hpp"
#include "mesh/triangle_surface.hpp"
#include "model/boundary_conditions.hpp"
#include "model/force_controlled_tool.hpp"
#include "model/formability.hpp"
#include "model/mass_scaling.hpp"
#include "model/operation.hpp"
#include "model/rigid_tool_motion.hpp"

namespace sf {

/// The deformable blank: mesh, element description, mass and named node groups.
/// One part of the blank (a tailor-welded blank has several; element e belongs to part
/// material_index(part, e)).
struct BlankPartInfo {
  std::string name;
  double thickness = 0.0;  ///< mm, initial
};

struct Blank {
  PartMesh mesh;
  ShellPart part;
  /// The blank's parts, in the case's order: part i has material part.materials[i]. One part
  /// named "blank" for a blank without [[blank.parts]].
  std::vector<BlankPartInfo> parts;
  /// tonne per node at time 0, after the initial mass scaling (the run's masses, which grow under
  /// mass scaling, are SolutionState::mass)
  VectorX mass;
  VectorX rotational_inertia;     ///< tonne mm^2 per node at time 0 (likewise)
  double physical_mass = 0.0;     ///< tonne, before mass scaling
  MassScaling scaling;            ///< at time 0: per-element density factors and the added mass
  VectorX inverse_element_count;  ///< per node, 1 / (elements sharing it), for nodal averages
  NodeCorners node_corners;       ///< each node's element corners, in the order they are summed
  VectorX physical_nodal_mass;    ///< tonne per node before mass scaling (for gravity)
  std::vector<NodeGroup> groups;  ///< every node group the case names, each once
  /// The formed part the run starts from (blank.formed_part; solver/formed_part.hpp reads it
  /// when the run starts). Empty: none.
  std::filesystem::path formed_part;

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
  SurfaceOrientation orientation;  ///< what orient_surface did to the mesh as read
  RigidToolMotion motion;
  std::optional<ForceControlledTool> force_control;
  /// mm, how far the tool was moved along its direction to touch the blank (position =
  /// "touch"; its mesh and surface are where it was moved to); 0 otherwise
  double touch_shift = 0.0;

  /// The axis the tool moves along (the prescribed motion's or the force's; the case's default,
  /// -z, for a fixed tool).
  const Vec3& direction() const {
    return force_control ? force_control->direction() : motion.direction();
  }
};

/// A contact pair between all blank nodes and one tool's triangles.
struct ContactInterface {
  int tool = -1;  ///< index into Model::tools
  ContactSearchKind search = ContactSearchKind::modified;
  bool audit = false;  ///< the output counts, per frame, the nodes where the search is not exact
  ContactPair pair;    ///< fixed for the run (its changing state: SolutionState::contacts)
};

/// A drawbead line of a tool ([[drawbeads]], docs/drawbeads.md).
struct DrawbeadInterface {
  int tool = -1;      ///< index into Model::tools
  DrawbeadLine line;  ///< fixed for the run (its changing state: SolutionState::drawbeads)
  /// How its force per length was found, for the banner ("curve", "round bead: ...").
  std::string source;
};

/// How the run steps and when it ends.
struct TimeControl {
  double end_time = 0.0;      ///< s, from control.end_time or the stroke
  int stroke_tool = -1;       ///< index of the tool whose travel is the stroke, or -1
  double time_step = 0.0;     ///< s, the initial stable step with the safety factor (after scaling)
  int limiting_element = -1;  ///< the element limiting time_step
  int progress_interval = 0;  ///< cycles between progress lines; 0 = about every 2 s of wall time
  double energy_blowup_ratio = 10.0;  ///< stop when total energy exceeds this x external work (+1)
  /// The last step is cut short to end exactly at end_time (false: the run ends at the first
  /// whole step at or past it, control.land_on_end)
  bool land_on_end = true;
  /// -, largest added mass as a fraction of the physical mass; the run stops beyond it; 0 = none
  double mass_scaling_max_added = 0.0;
};

/// A constraint entry of the case ([[boundary]], [[prescribed_velocity]], [[prescribed_motion]])
/// whose total reaction the summary reports.
struct ReactionEntry {
  std::string entry;         ///< e.g. "boundary[0]", "prescribed_motion[1]"
  std::string group;         ///< its node group
  std::optional<Mat3> axes;  ///< the entry's own axes (columns), when it has them
  int dof = -1;              ///< a [[prescribed_motion]]'s degree of freedom (0..5), else -1
};

/// What the run writes, and when.
struct OutputPlan {
  int frames = 20;             ///< frames at evenly spaced times after the initial one
  int history_interval = 100;  ///< cycles between history rows (explicit)
  bool stress_layers = true;   ///< mid, top and bottom stress per element
  std::string units;           ///< the case's unit system ("mm-s-tonne-N-MPa")
  std::vector<DrawInConfig> draw_ins;
  std::vector<HistoryGroupConfig> history_groups;
  std::vector<ReactionEntry> reactions;  ///< in the case's order: boundaries, velocities, motions
  std::string resolved_case;  ///< the resolved case as TOML (kept in results.h5 and beside it)
  int checkpoint_cycles = 0;  ///< cycles between checkpoints (0: none by count)
  double checkpoint_minutes = 30.0;  ///< min of wall time between checkpoints (0: none by time)
};

/// The blank's state at time 0 besides its mesh.
struct InitialConditions {
  int integration_points = 5;  ///< through the thickness
  double thickness = 0.0;      ///< mm, the largest part's
  /// mm per element, initial (each element's part's); empty: `thickness` everywhere
  std::vector<double> element_thickness;
  std::vector<InitialVelocityConfig> velocities;  ///< in the case's order
};

/// What the case runs, and how the implicit steps solve.
struct AnalysisPlan {
  AnalysisConfig::Type type = AnalysisConfig::Type::explicit_dynamic;
  bool linear = false;  ///< static: one linear solve
  ImplicitConfig implicit;
  bool is_static() const { return type == AnalysisConfig::Type::static_equilibrium; }
};

struct Model {
  std::filesystem::path case_file;  ///< absolute; names the case in messages
  Blank blank;
  std::vector<Tool> tools;
  std::vector<ContactInterface> contacts;
  std::vector<DrawbeadInterface> drawbeads;
  NodalConstraints constraints;  ///< held and prescribed degrees of freedom, node frames
  std::vector<PrescribedMotion> prescribed_motions;  ///< what drives the prescribed ones
  ExternalLoads loads;
  InitialConditions initial;
  TimeControl time;
  OutputPlan output;
  FormabilityPlan formability;  ///< how the formability results judge the blank
  AnalysisPlan analysis;
  std::optional<SpringbackConfig> springback;  ///< the springback plan, when the case asks
  /// The press line's operations in order ([[operations]]); empty: the case runs as one forming
  /// operation to time.end_time (and its [springback], if any)
  std::vector<Operation> operations;
};

}  // namespace sf
