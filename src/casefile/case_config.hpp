#pragma once
// The case, as plain data: what `read_case` produces from a case.toml. Every default is filled
// here, in one place, and nowhere else. Units follow the case (forming cases: mm, s, tonne, N,
// MPa); the solver itself is unit-agnostic.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "contact/contact_choices.hpp"
#include "core/choice.hpp"
#include "core/expression.hpp"
#include "element/shell_choices.hpp"
#include "meshing/geo_parameter.hpp"
#include "meshing/mesh_limits.hpp"

namespace sf {

/// A piecewise-linear curve value(time), given as points [[t0, v0], [t1, v1], ...] with strictly
/// increasing times. Held constant beyond its last point.
struct CurveConfig {
  std::vector<double> times;   ///< s
  std::vector<double> values;  ///< unit of the quantity it drives
};

/// Isotropic hardening: flow stress as a function of equivalent plastic strain.
struct HardeningConfig {
  enum class Law { swift, linear, voce, ludwik, tabulated, hockett_sherby, swift_voce };
  Law law = Law::swift;
  // swift: sigma_y = K * (eps0 + eps_p)^n
  double swift_k = 0.0;     ///< MPa
  double swift_eps0 = 0.0;  ///< -
  double swift_n = 0.0;     ///< -
  // linear: sigma_y = sigma_y0 + H * eps_p
  double yield_stress = 0.0;  ///< MPa
  double modulus = 0.0;       ///< MPa (plastic hardening modulus H)
  // voce: sigma_y = sigma0 + Q * (1 - exp(-b * eps_p))
  double voce_sigma0 = 0.0;  ///< MPa, initial yield stress
  double voce_q = 0.0;       ///< MPa, saturation increase
  double voce_b = 0.0;       ///< -, saturation rate
  // ludwik: sigma_y = A + B * eps_p^n
  double ludwik_a = 0.0;  ///< MPa, initial yield stress
  double ludwik_b = 0.0;  ///< MPa
  double ludwik_n = 0.0;  ///< -
  // hockett_sherby: sigma_y = sigma_s - (sigma_s - sigma_i) exp(-N eps_p^p)
  double hs_sigma_s = 0.0;  ///< MPa
  double hs_sigma_i = 0.0;  ///< MPa
  double hs_n = 0.0;        ///< -
  double hs_p = 1.0;        ///< -
  // swift_voce: sigma_y = weight Swift (K, eps0, n) + (1 - weight) Voce (sigma0, Q, b)
  double sv_weight = 0.5;  ///< -
  /// tabulated: a CSV file of (equivalent plastic strain -, true stress MPa) rows, absolute
  /// (resolved against the case file's folder); read by build_model (read_hardening_csv).
  std::filesystem::path table_file;
};

inline constexpr std::array<Choice<HardeningConfig::Law>, 7> kHardeningLawNames{{
    {HardeningConfig::Law::swift, "swift", "Swift"},
    {HardeningConfig::Law::linear, "linear", ""},
    {HardeningConfig::Law::voce, "voce", "Voce"},
    {HardeningConfig::Law::ludwik, "ludwik", "Ludwik"},
    {HardeningConfig::Law::tabulated, "tabulated", "a table, below"},
    {HardeningConfig::Law::hockett_sherby, "hockett_sherby", "Hockett-Sherby"},
    {HardeningConfig::Law::swift_voce, "swift_voce", "a weighted sum of Swift and Voce"},
}};

/// Nonlinear kinematic hardening (Armstrong-Frederick back stresses, Chaboche's sum): one C and
/// one gamma per back stress, 1 to 4 of them; empty = isotropic hardening only.
struct KinematicConfig {
  std::vector<double> C;      ///< MPa, each >= 0
  std::vector<double> gamma;  ///< -, each >= 0
};

/// Cowper-Symonds strain-rate dependence: sigma_y times 1 + (rate / D)^(1/q), rate the
/// equivalent plastic strain rate. D = 0: none (the default).
struct CowperSymondsConfig {
  double D = 0.0;  ///< 1/s, > 0 when given
  double q = 1.0;  ///< -, > 0
};

struct MaterialConfig {
  enum class Type { elastic, von_mises, hill48, yld2000, yld89 };
  std::string name;  ///< the table's key under [materials]
  Type type = Type::von_mises;
  double density = 0.0;       ///< tonne/mm^3
  double young = 0.0;         ///< MPa
  double poisson = 0.0;       ///< -
  HardeningConfig hardening;  ///< used when type is von_mises or hill48
  // hill48 (required there, not allowed otherwise): Lankford coefficients at 0, 45 and 90 deg to
  // the rolling direction; the hardening curve is the flow stress along the rolling direction.
  double r0 = 1.0;   ///< -
  double r45 = 1.0;  ///< -
  double r90 = 1.0;  ///< -
  // yld2000 and yld89 (Barlat): the exponent a (M for Yld89), >= 2; 8 for aluminium, 6 for steel.
  double exponent = 8.0;  ///< -
  /// yld2000: alpha_1..alpha_8 given directly, or empty: fitted to sigma0, sigma45, sigma90,
  /// sigma_b, r0, r45, r90, r_b (Barlat et al. 2003). yld89 uses r0, r45, r90.
  std::vector<double> alpha;
  double sigma0 = 1.0;        ///< MPa (or any unit: only ratios to sigma0 are used), yld2000 fit
  double sigma45 = 1.0;       ///< as sigma0
  double sigma90 = 1.0;       ///< as sigma0
  double sigma_b = 1.0;       ///< as sigma0, equibiaxial
  double r_b = 1.0;           ///< -, equibiaxial d_eps_yy / d_eps_xx, yld2000 fit
  KinematicConfig kinematic;  ///< any plastic type; empty = none
  CowperSymondsConfig cowper_symonds;  ///< any plastic type; D = 0 = none
  /// Optional forming limit curve: [minor, major] true (logarithmic) strain points, minor
  /// strictly increasing, major > 0, falling to its lowest point and rising after it; empty =
  /// the Keeler-Brazier curve from the Swift exponent n and the thickness, or none
  /// (model/forming_limit.hpp; the formability results, docs/formability.md).
  std::vector<std::array<double, 2>> forming_limit_curve;
};

inline constexpr std::array<Choice<MaterialConfig::Type>, 5> kMaterialTypeNames{{
    {MaterialConfig::Type::von_mises, "von_mises", "isotropic elastic-plastic"},
    {MaterialConfig::Type::elastic, "elastic", ""},
    {MaterialConfig::Type::hill48, "hill48", "Hill 1948 orthotropic elastic-plastic"},
    {MaterialConfig::Type::yld2000, "yld2000", "Barlat et al. 2003 Yld2000-2d"},
    {MaterialConfig::Type::yld89, "yld89", "Barlat & Lian 1989"},
}};

/// A mesh source: a .geo file meshed by gmsh, a ready .msh file, a CAD file (STEP, IGES, BREP)
/// meshed by gmsh, or an STL file's triangles (meshing/mesh_import.hpp).
struct MeshSourceConfig {
  std::filesystem::path file;  ///< absolute (resolved against the case file's folder)
  /// physical group name holding the part's surface; for a CAD or STL file (which has no groups)
  /// the name its surfaces are given
  std::string group;
  /// mm; 0 = leave the .geo file's own sizes (ignored for .msh and STL; required > 0 for CAD)
  double element_size = 0.0;
  /// .geo only: numbers set before gmsh parses the file, sorted by name; each must be declared by
  /// the file with DefineConstant[] (checked when the model is built: load_gmsh_model).
  std::vector<GeoParameter> parameters{};
  double scale = 1.0;           ///< -, lengths of a CAD, STL or .msh file multiplied by it
  int curvature_elements = 0;   ///< CAD only: elements per 2 pi of curvature; 0 = off
  double chord_error = 0.0;     ///< mm, CAD only: largest stand-off of a facet; 0 = off
  std::vector<int> surfaces{};  ///< CAD and STL: the surface tags of the part; empty = all
};

/// How a blank's .geo or CAD file is meshed.
enum class BlankMeshing {
  quad,       ///< every surface recombined into quadrilaterals wherever gmsh can make them
  as_meshed,  ///< the .geo's own Recombine commands decide (triangles where it has none)
};

inline constexpr std::array<Choice<BlankMeshing>, 2> kBlankMeshingNames{{
    {BlankMeshing::quad, "quad", "every surface recombined (quadrilaterals wherever gmsh can)"},
    {BlankMeshing::as_meshed, "as_meshed",
     "the file's own `Recombine` commands (triangles where it has none)"},
}};

/// One part of a blank of several ([[blank.parts]], a tailor-welded blank): the elements of a
/// 2-D physical group of the blank's mesh, with their own thickness and material. The parts share
/// the nodes along their weld lines.
struct BlankPartConfig {
  std::string name;        ///< unique among the parts; names the part in results and messages
  std::string group;       ///< a 2-D physical group of the blank's mesh: the part's elements
  double thickness = 0.0;  ///< mm, initial
  std::string material;    ///< name of a [materials.NAME] table
  int line = 0;            ///< of the part's [[blank.parts]] header in the case file (0: unknown)
};

struct BlankConfig {
  MeshSourceConfig mesh{.file = {}, .group = "blank"};  ///< group defaults to "blank"
  /// How a .geo or CAD blank is meshed. Triangles left in the mesh are C0 shell triangles either
  /// way; a .msh (or another code's mesh) is read as it is.
  BlankMeshing element = BlankMeshing::quad;
  /// mm, initial. With `parts`: not given; the reader sets the largest part's.
  double thickness = 0.0;
  int integration_points = 5;  ///< through the thickness: gauss 1..9, lobatto 2..9
  ThroughThicknessRule integration_rule = ThroughThicknessRule::gauss;
  std::string material;  ///< name of a [materials.NAME] table; empty with `parts`
  /// The blank's parts (a tailor-welded blank); empty: one part, of `thickness` and `material`.
  std::vector<BlankPartConfig> parts;
  /// The quadrilaterals' formulation: "assumed_strain" (the default: one point, directors, MITC4
  /// transverse shear, physical stabilisation: no hourglass keys) or "belytschko_tsay" (one point,
  /// Flanagan-Belytschko hourglass control, the two keys below). docs/element-and-material.md
  ShellFormulation formulation = ShellFormulation::assumed_strain;
  /// -, hourglass coefficient (Flanagan-Belytschko), (0, 0.5]; belytschko_tsay only
  double hourglass_coefficient = 0.1;
  HourglassForm hourglass_form = HourglassForm::viscous;  ///< belytschko_tsay only
  /// Rolling direction (unit vector, global axes; normalised on read), projected on each element
  /// at the start to fix its material axes. Used by the laws with material axes (hill48, ...),
  /// where it must not be (near) normal to an element (build_model checks), and by a contact's
  /// friction_across_ratio (projected on the tangent plane of the contact).
  std::array<double, 3> rolling_direction{1.0, 0.0, 0.0};
  /// A formed part (another run's <results>/formed_part.h5, absolute after reading) whose state
  /// the run starts from: its blank must be this case's (docs/process-chain.md). Empty: the
  /// blank starts flat and stress-free.
  std::filesystem::path formed_part;
};

/// How a tool moves: fixed, a prescribed velocity or displacement along `direction`, or driven by
/// a force along `direction` (a blank holder: the tool is then a rigid body of mass `mass` that
/// moves along that axis only, under the force and the blank's reaction).
struct MotionConfig {
  enum class Type { velocity, displacement, fixed, force };
  /// What a force curve's abscissa is: the time (s) or the tool's travel (mm: a gas spring)
  enum class ForceOf { time, travel };
  Type type = Type::fixed;
  ForceOf force_of = ForceOf::time;
  std::array<double, 3> direction{0.0, 0.0, -1.0};  ///< unit vector (normalised on read)
  /// velocity in mm/s, displacement in mm, or (force) the force in N pushing along `direction`,
  /// against time in s
  CurveConfig curve;
  /// force: the tool's moving mass, tonne (> 0); absent = the blank's mass at the start (mass
  /// scaling included), filled in by build_model. Not allowed for the other types.
  std::optional<double> mass;
  /// force: mass-proportional damping on the tool, 1/s (>= 0). Not allowed for the other types.
  double damping = 0.0;
  /// A turn of the tool about `axis` through `pivot`, in degrees against time in s (right-hand
  /// rule; empty: the tool does not turn). Not for a force-controlled tool.
  CurveConfig angle;
  std::array<double, 3> axis{0.0, 1.0, 0.0};   ///< unit vector (normalised on read), as meshed
  std::array<double, 3> pivot{0.0, 0.0, 0.0};  ///< mm, a point of the axis, as meshed
  bool turns() const { return !angle.times.empty(); }
};

struct ToolConfig {
  /// Where the tool starts: where its mesh puts it, or moved along its motion's direction until
  /// it touches the blank (auto-positioning)
  enum class Position { as_meshed, touch };
  std::string name;  ///< unique; referred to by [[contact]] and [control]
  MeshSourceConfig mesh;
  Position position = Position::as_meshed;
  MotionConfig motion;
};

/// A tool's motion redefined by an operation ([[operations.motion]]): its time counts from the
/// operation's start and its travel adds to where the tool stands then.
struct OperationMotionConfig {
  std::string tool;  ///< name of a [[tools]] entry with a prescribed motion or none
  MotionConfig motion;
};

/// One operation of the press line ([[operations]], docs/process-chain.md), run in the case's
/// order on one time loop; time runs on across them.
struct OperationConfig {
  enum class Kind { gravity, closing, forming, trim, springback };
  /// Which side of a trim line stays: what projects inside it, or outside.
  enum class Keep { inside, outside };
  /// How a trim takes the scrap off: whole elements by their centres, or cut along the line.
  enum class TrimMode { remove, cut };
  /// What ends it: the stroke tool's travel, a duration, the push on a tool, the clearance left
  /// between two tools, or the blank at rest (kinetic energy fallen below `rest` x its peak).
  enum class End { stroke, time, force, gap, rest, none };
  std::string name;  ///< unique; names its results group and summary entry
  Kind kind = Kind::forming;
  std::vector<std::string> tools;  ///< the tools in play (contact and motion); empty = all
  bool all_tools = true;           ///< `tools` absent: every tool is in play
  End end = End::stroke;
  std::string tool;     ///< the tool of a stroke, force or gap end
  double stroke = 0.0;  ///< mm, the tool's travel since the case's start
  double time = 0.0;    ///< s: the duration (end "time"), else the longest it may take
  double force = 0.0;   ///< N, the tool's push against its motion
  double gap = 0.0;     ///< mm, the clearance left between `tool` and `gap_to` along its motion
  std::string gap_to;   ///< the tool the gap is measured to
  double rest = 1e-3;   ///< -, kinetic energy / its peak in the operation
  std::optional<double> damping;  ///< 1/s, mass-proportional; absent = control.damping
  std::vector<OperationMotionConfig> motions;
  /// mm, a trim's line: a closed polyline (the last point joins the first), projected along
  /// `direction` onto the part as it stands
  std::vector<std::array<double, 3>> line;
  /// A trim's line from a file (absolute; empty: none): a .geo or .msh file's 1-D physical group
  /// `line_group`, or a CAD file's curves `line_curves` (all when empty), meshed by gmsh into
  /// points `line_element_size` apart and joined into one closed line
  std::filesystem::path line_file;
  std::string line_group = "trim";
  std::vector<int> line_curves;
  double line_element_size = 1.0;  ///< mm
  /// A trim's line as the outline of this tool (its surface projected along `direction`, where
  /// the tool stands at the trim) grown by line_offset; empty: none
  std::string line_tool;
  double line_offset = 0.0;                         ///< mm, >= 0
  std::array<double, 3> direction{0.0, 0.0, -1.0};  ///< -, a trim's projection (normalised)
  Keep keep = Keep::inside;
  TrimMode mode = TrimMode::remove;
  double sliver_fraction = 0.1;  ///< -, a cut's smallest piece over its parent element's area
};

struct ContactConfig {
  std::string tool;  ///< name of a [[tools]] entry
  /// The search (contact/contact_choices.hpp; docs/contact.md).
  ContactSearchKind search = ContactSearchKind::modified;
  /// After the search: project along the interpolated averaged nodal normal (the paper's
  /// "interpolated projection") or keep the orthogonal projection.
  ContactProjection projection = ContactProjection::interpolated;
  double penalty_scale = 0.1;      ///< -, scales the blank's bulk stiffness per node (see docs)
  double penalty_stiffness = 0.0;  ///< N/mm per blank node, given; 0 = from penalty_scale
  double friction_static = 0.0;    ///< -, Coulomb coefficient at rest
  double friction_dynamic = 0.0;   ///< -, Coulomb coefficient when sliding (<= static)
  double friction_decay = 0.0;     ///< s/mm, mu = mu_d + (mu_s - mu_d) exp(-decay |v_slip|)
  /// -, n of the pressure power law mu = mu_c(v) (p / p0)^(n - 1) (docs/contact.md); 1: none
  double friction_pressure_exponent = 1.0;
  double friction_reference_pressure = 0.0;  ///< MPa, p0 of the power law (> 0 when n != 1)
  /// [[pressure (MPa), mu], ...]: mu against the contact pressure, instead of the Coulomb keys;
  /// empty: none
  std::vector<std::array<double, 2>> friction_pressure_table;
  /// [[slip speed (mm/s), factor], ...]: a factor on mu against the slip speed; empty: none
  std::vector<std::array<double, 2>> friction_speed_table;
  /// -, mu across the blank's rolling_direction over mu along it (an elliptic limit); 1: isotropic
  double friction_across_ratio = 1.0;
  bool audit = false;          ///< count, per frame, the nodes where this search is not exact
  double search_margin = 0.0;  ///< mm, the cached search's candidate margin; 0 = its default
};

/// A drawbead line ([[drawbeads]], docs/drawbeads.md): the force of a bead of a tool on the sheet
/// drawn across it, per unit length of bead, instead of the bead meshed.
struct DrawbeadConfig {
  /// Where the force per unit length comes from: curves against the closure, or a round bead's
  /// geometry (contact/round_drawbead.hpp).
  enum class Force { curve, round_bead };
  std::string name;  ///< unique among the beads; names it in the banner and the summary
  std::string tool;  ///< the [[tools]] entry it belongs to (with a [[contact]]): it moves with it
  /// mm, an open polyline of at least 2 points on the tool's surface, where the tool is meshed
  std::vector<std::array<double, 3>> line;
  /// The line from a file instead (absolute; empty: none): a .geo or .msh file's 1-D physical
  /// group `line_group` (default: the bead's name), or a CAD file's curves `line_curves` (all
  /// when empty), meshed by gmsh into points `line_element_size` apart, joined into one open line
  std::filesystem::path line_file;
  std::string line_group;
  std::vector<int> line_curves;
  double line_element_size = 1.0;  ///< mm
  double width = 0.0;              ///< mm, the band across the line the force acts in
  double height = 0.0;  ///< mm, the closing travel from first touch to closed; 0: the bead's depth
  Force force = Force::curve;
  bool locking = false;                   ///< the sheet does not pass (no restraint limit)
  std::vector<double> closure;            ///< -, in [0, 1], increasing: the curves' abscissae
  std::vector<double> restraining_force;  ///< N/mm at each closure
  std::vector<double> uplift_force;       ///< N/mm at each closure; empty: none
  double bead_radius = 0.0;               ///< mm, round bead
  double shoulder_radius = 0.0;           ///< mm, round bead
  double depth = 0.0;                     ///< mm, round bead: its crest's depth into the groove
  double clearance = 0.0;                 ///< mm, round bead: side clearance
  double friction = -1.0;                 ///< -, round bead; < 0: the tool's [[contact]] friction
  double flow_stress = 0.0;  ///< MPa, round bead; 0: the blank material's (docs/drawbeads.md)
  double thickness = 0.0;    ///< mm, round bead; 0: the blank's
};

/// A local frame of axes given by two vectors (global components, unit length: normalised on
/// reading): x as given; y the part of the second vector perpendicular to x (made so on reading);
/// z = x cross y.
struct AxesConfig {
  std::array<double, 3> x{1.0, 0.0, 0.0};
  std::array<double, 3> y{0.0, 1.0, 0.0};
};

/// Degrees of freedom of a group of blank nodes held at zero ([[boundary]]), in the global axes
/// or in a local frame. Degrees of freedom are numbered 0..5: ux, uy, uz, rx, ry, rz
/// (core/dof_names.hpp).
struct BoundaryConfig {
  /// fixed: all six held. symmetry: the translation along the plane's normal and the rotations
  /// about the two in-plane axes. diaphragm: the two translations in the plane (rotations free).
  /// hold: the degrees of freedom listed in `hold`.
  enum class Type { symmetry, fixed, diaphragm, hold };
  std::string group;  ///< physical group name (curve or point set) of blank nodes
  Type type = Type::fixed;
  /// symmetry, diaphragm: the plane's normal axis, 0 = x, 1 = y, 2 = z (of `axes` when given);
  /// unused when `normal` is given.
  int axis = 0;
  /// symmetry, diaphragm: the plane's unit normal (global components), instead of `axis`.
  std::optional<std::array<double, 3>> normal;
  /// hold: which of ux, uy, uz, rx, ry, rz are held (components along `axes` when given).
  std::array<bool, 6> hold{};
  /// symmetry or diaphragm with `axis`, and hold: the local frame their components refer to;
  /// none = the global axes.
  std::optional<AxesConfig> axes;
  /// The line of the [[boundary]] table in the case file (0 = not read from a file), for the
  /// messages of build_model, which sees the mesh.
  int line = 0;
};

/// One degree of freedom of a group of blank nodes driven along a curve ([[prescribed_motion]]).
struct PrescribedMotionConfig {
  enum class Type { displacement, velocity };
  std::string group;  ///< physical group name of blank nodes
  /// displacement: mm (translations) or rad (rotations) from the initial state against time;
  /// velocity: mm/s or rad/s.
  Type type = Type::displacement;
  int dof = 0;  ///< 0..5: ux, uy, uz, rx, ry, rz (components along `axes` when given)
  /// mm, rad, mm/s or rad/s, used when `curve` is empty: a velocity is held at it; a
  /// displacement (static analyses only) ramps linearly from 0 at time 0 to it at end_time.
  double value = 0.0;
  /// [time (s), value] points; a displacement curve starts at 0. Empty = `value`.
  CurveConfig curve;
  std::optional<AxesConfig> axes;  ///< the local frame `dof` refers to; none = the global axes
  int line = 0;                    ///< of the [[prescribed_motion]] table; 0 = not from a file
};

/// A load on blank nodes or elements, scaled over time by an optional curve (default 1).
struct LoadConfig {
  enum class Type { force, moment, pressure };
  std::string group;  ///< physical group of blank nodes (force, moment) or elements (pressure)
  Type type = Type::force;
  std::array<double, 3> value{0.0, 0.0, 0.0};  ///< force: N per node; moment: N mm per node
  double pressure = 0.0;  ///< MPa on the top face (the +normal side): pushes along -normal
  CurveConfig curve;      ///< scale factor against time; empty = 1
};

/// Initial velocities of a group's nodes (every node without a group). Each component is a
/// number or an expression of the node's initial coordinates x, y, z (mm): a velocity field.
struct InitialVelocityConfig {
  std::string group;
  std::array<Expression, 3> velocity;          ///< mm/s, global axes
  std::array<Expression, 3> angular_velocity;  ///< rad/s of the nodes' rotations
};

/// Velocity components held at prescribed values (mm/s) on blank nodes, scaled by a curve.
struct PrescribedVelocityConfig {
  std::string group;
  std::array<double, 3> velocity{0.0, 0.0, 0.0};     ///< mm/s
  std::array<bool, 3> components{true, true, true};  ///< which of x, y, z are prescribed
  CurveConfig curve;                                 ///< scale factor against time; empty = 1
  int line = 0;  ///< of the [[prescribed_velocity]] table; 0 = not from a file
};

struct ControlConfig {
  double end_time = 0.0;    ///< s; 0 = run until the stroke is reached
  double stroke = 0.0;      ///< mm of travel of `stroke_tool`; 0 = use end_time
  std::string stroke_tool;  ///< tool of prescribed motion giving the stroke (default: the first)
  int output_frames = 20;   ///< frames at evenly spaced times (plus the initial one), each at the
                            ///< first step end at or past it
  int history_interval = 100;  ///< cycles between history rows
  int progress_interval = 0;   ///< cycles between progress lines; 0 = about every 2 s of wall time
  double time_step_safety = 0.9;  ///< factor on the elements' critical time step
  double mass_scaling_dt = 0.0;   ///< s; target time step for mass scaling; 0 = off
  /// -, largest added mass as a fraction of the physical mass; the run stops beyond it; 0 = none
  double mass_scaling_max_added = 1.0;
  double energy_blowup_ratio = 10.0;  ///< stop when total energy exceeds this x external work (+1)
  /// The last step is cut short to end exactly at the end time (false: the run ends at the first
  /// whole step at or past it)
  bool land_on_end = true;
  int checkpoint_cycles = 0;  ///< cycles between checkpoints; 0 = none by cycle count
  /// minutes of wall time between checkpoints; 0 = none by wall time
  double checkpoint_minutes = 30.0;
  std::array<double, 3> gravity{0.0, 0.0, 0.0};  ///< mm/s^2 (forming cases: 0, or -9810 in z)
  double damping = 0.0;  ///< 1/s, mass-proportional: force -damping * m * v on every node
};

/// A draw-in measurement: the in-plane displacement of a blank node along a direction at the end of
/// the run (mm), reported beside a measured value when one is given.
struct DrawInConfig {
  std::string name;                                 ///< e.g. "DX"
  std::string group;                                ///< physical group holding one blank node
  std::array<double, 3> direction{-1.0, 0.0, 0.0};  ///< unit vector (normalised on read)
  double measured = -1.0;                           ///< mm; < 0 = no measured value
  /// mm of the stroke tool's travel at which `measured` was taken; 0 = at the end of the run. A
  /// run that ends elsewhere reports the measured value without comparing it.
  double measured_stroke = 0.0;
  std::string source;  ///< where the measured value comes from
};

/// A node group whose motion and reaction the history records each row ([[history]]): the mean
/// over its nodes of the displacement, velocity and rotation, and the sum of the reactions.
struct HistoryGroupConfig {
  std::string group;         ///< physical group of blank nodes (points, curves or surfaces)
  bool displacement = true;  ///< mean displacement (mm)
  bool velocity = true;      ///< mean velocity (mm/s); explicit runs only
  bool rotation = true;      ///< mean rotation (rad), the summed rotation increments
  bool reaction = true;      ///< summed reaction force (N) and moment (N mm) of the constraints
};

/// Blank nodes chosen by position ([[node_group]]): a node group for a blank from a file without
/// physical groups (CAD, STL, another code's mesh), named like a physical group wherever the case
/// names a group. A node is chosen when it meets every criterion given (at least one).
struct NodeGroupConfig {
  std::string name;            ///< plain name (result_name.hpp), not a physical group's
  std::vector<double> point;   ///< mm, 3 numbers or empty: the plane's point, or the nearest node
  std::vector<double> normal;  ///< 3 numbers (unit after reading) or empty: a plane
  std::vector<double> box;     ///< mm, 6 numbers (x, y, z min then max) or empty: inside a box
  bool outline = false;        ///< only nodes on the blank's outline (its free edges)
  double tolerance = 0.0;      ///< mm; 0 = 1 % of the blank's shortest element edge
  int line = 0;                ///< of the [[node_group]] table; 0 = not from a file

  /// `point` alone: the one node nearest to it.
  bool nearest() const { return !point.empty() && normal.empty() && box.empty() && !outline; }
};

/// What a case may ask for before it is refused (exit 2) rather than run until killed: the
/// estimates `check` prints (docs/case-file.md, [limits]). A user raises a limit in the case or
/// with --set limits.KEY=VALUE.
struct LimitsConfig {
  double max_cycles = 1e8;       ///< explicit cycles (end time / time step)
  double max_elements = 5e6;     ///< elements of one part (estimated before gmsh meshes a .geo)
  int max_frames = 10000;        ///< control.output_frames
  double max_output_gb = 100.0;  ///< GB, estimated size of results.h5
  double max_memory_gb = 0.0;    ///< GB, estimated memory; 0 = this machine's memory
  double mesh_seconds = 0.0;     ///< s of wall time gmsh may take for one part; 0 = scaled
  double mesh_memory_gb = 0.0;   ///< GB gmsh may allocate for one part; 0 = this machine's memory
  /// deepest initial penetration of a tool into the blank, as a fraction of the blank thickness
  double max_initial_penetration = 0.5;
};

/// What gmsh may spend on one part of a case with these limits.
inline MeshLimits mesh_limits(const LimitsConfig& limits) {
  return {limits.mesh_seconds, limits.max_elements, limits.mesh_memory_gb};
}

struct OutputConfig {
  std::string directory = "results";  ///< relative to the case folder unless given with -o
  bool stress_layers = true;          ///< write mid, top and bottom stress per element
};

/// [formability] (docs/formability.md): how the formability results of every frame (strains,
/// thinning, the margin to the forming limit curve, the zone) are judged. True strains, -.
struct FormabilityConfig {
  /// Which surface's strains decide the margin and the zone.
  enum class Surface { mid, top, bottom, worst };
  Surface surface = Surface::mid;
  double safety_margin = 0.10;         ///< -, true major strain below the FLC: "risk of cracks"
  double insufficient_stretch = 0.02;  ///< -, major true strain below which a part is loose
  double wrinkle_thickening = 0.01;    ///< -, -(major + minor) above which: wrinkling tendency
  double severe_thinning = 30.0;       ///< per cent of the initial thickness
};

inline constexpr std::array<Choice<FormabilityConfig::Surface>, 4> kFormabilitySurfaceNames{{
    {FormabilityConfig::Surface::mid, "mid", "the mid-surface (membrane) strains"},
    {FormabilityConfig::Surface::top, "top", ""},
    {FormabilityConfig::Surface::bottom, "bottom", ""},
    {FormabilityConfig::Surface::worst, "worst", "the surface with the least margin"},
}};

/// What the case runs: an explicit forming run (optionally followed by springback), or a static
/// analysis of the blank under its loads and boundary conditions (docs/static-analysis.md).
struct AnalysisConfig {
  enum class Type { explicit_dynamic, static_equilibrium };
  Type type = Type::explicit_dynamic;  ///< "explicit" or "static"
  /// static: true = one linear solve on the initial geometry (small displacements, the elastic
  /// tangent at the initial state); false = Newton-Raphson with large rotations and plasticity.
  bool linear = false;
};

/// Newton-Raphson controls of an implicit static step: a static analysis, or springback.
struct ImplicitConfig {
  enum class LinearSolver { automatic, cholmod, umfpack };
  enum class RigidBodyModes { automatic, error };
  /// Equal increments the load (static: the load curves over 0..control.end_time; springback:
  /// the release of the tool forces) is applied in; an increment that fails is halved.
  int increments = 1;
  int max_iterations = 25;  ///< Newton iterations per increment before it is cut
  int max_cuts = 8;         ///< successive halvings of one increment before the step stops
  /// -, converged when the residual force norm <= this x the reference force norm ...
  double force_tolerance = 1e-6;
  /// -, ... and the last correction's norm <= this x the increment's displacement norm
  double displacement_tolerance = 1e-6;
  bool line_search = true;  ///< scale the Newton correction so that it lowers the residual
  /// "auto": CHOLMOD when the tangent is symmetric (to its finite-difference accuracy) and
  /// positive definite, else UMFPACK; or force one of them.
  LinearSolver linear_solver = LinearSolver::automatic;
  /// "auto": hold a minimal set of degrees of freedom that removes the rigid-body modes the
  /// case's constraints leave free (logged); "error": stop and name them.
  RigidBodyModes rigid_body_modes = RigidBodyModes::automatic;
};

/// The NUMISHEET'93 U-channel springback measures, computed on a line of blank nodes along the
/// channel (x along the length from the symmetry plane, z the punch axis). The three regions are
/// picked on the formed shape (at the end of forming) and measured on the current one.
struct UChannelMeasureConfig {
  std::string section;                     ///< node group: a line of blank nodes along x
  std::array<double, 2> bottom{0.0, 0.0};  ///< mm, x range of the bottom (formed shape)
  std::array<double, 2> wall{0.0, 0.0};    ///< mm, z range of the side wall (formed shape)
  std::array<double, 2> flange{0.0, 0.0};  ///< mm, x range of the flange (formed shape)
};

/// Springback after the forming run: the tools are removed, the blank keeps its stresses and
/// plastic history and finds its unloaded shape.
struct SpringbackConfig {
  enum class Method { implicit, dynamic_relaxation };
  /// implicit: a static Newton step (the [implicit] controls) that releases the tool forces;
  /// dynamic_relaxation: the explicit route, the tool forces ramped to zero over release_time,
  /// then kinetic damping until the blank is at rest.
  Method method = Method::implicit;
  double release_time = 0.0;  ///< s, dynamic_relaxation: required (> 0)
  /// s, dynamic_relaxation: the longest the relaxation may run after the release; 0 = 10 x
  /// release_time
  double max_time = 0.0;
  /// -, dynamic_relaxation: at rest when the kinetic energy is below this x the internal energy
  double kinetic_tolerance = 1e-6;
  /// -, implicit: stabilising springs on every node's translations, this x E x the mean thickness
  /// (N/mm), anchored at the start of each increment and removed at the end (0 = none): the
  /// formed part, its tools replaced by their forces, can be unstable (a flange compressed under
  /// the holder buckles once released). docs/static-analysis.md
  double stabilization = 1e-6;
  std::optional<UChannelMeasureConfig> u_channel;  ///< [springback.u_channel]
};

struct CaseConfig {
  std::filesystem::path file;  ///< the case file, absolute
  std::string title;
  /// "LENGTH-TIME-MASS-FORCE-STRESS", checked for consistency (parse_unit_system); it names the
  /// units in messages and output, the solver itself is unit-agnostic.
  std::string units = "mm-s-tonne-N-MPa";
  BlankConfig blank;
  std::vector<MaterialConfig> materials;
  std::vector<ToolConfig> tools;
  std::vector<ContactConfig> contacts;
  std::vector<BoundaryConfig> boundaries;
  ControlConfig control;
  OutputConfig output;
  FormabilityConfig formability;  ///< [formability]
  LimitsConfig limits;
  std::vector<DrawInConfig> draw_ins;                           ///< [[draw_in]] tables
  std::vector<HistoryGroupConfig> history_groups;               ///< [[history]] tables
  std::vector<NodeGroupConfig> node_groups;                     ///< [[node_group]] tables
  std::vector<LoadConfig> loads;                                ///< [[load]] tables
  std::vector<InitialVelocityConfig> initial_velocities;        ///< [[initial_velocity]]
  std::vector<PrescribedVelocityConfig> prescribed_velocities;  ///< [[prescribed_velocity]]
  std::vector<PrescribedMotionConfig> prescribed_motions;       ///< [[prescribed_motion]]
  AnalysisConfig analysis;                                      ///< [analysis]
  ImplicitConfig implicit;                                      ///< [implicit]
  std::optional<SpringbackConfig> springback;                   ///< [springback]
  std::vector<OperationConfig> operations;                      ///< [[operations]]
  std::vector<DrawbeadConfig> drawbeads;                        ///< [[drawbeads]]

  /// The material named by blank.material (the reader guarantees it exists). InputError for a
  /// blank of several parts (blank_parts names each one's).
  const MaterialConfig& blank_material() const;
  /// The blank's parts: blank.parts, or the one part a blank without them is (named "blank", the
  /// whole mesh, blank.thickness, blank.material).
  std::vector<BlankPartConfig> blank_parts() const;
  /// mm: the blank's thickness, or its thickest part's for a blank of several parts.
  double largest_blank_thickness() const;
  /// The material of this name (InputError naming the case file if there is none).
  const MaterialConfig& material_named(const std::string& name) const;
  /// The tool with this name, or nullptr.
  const ToolConfig* find_tool(const std::string& name) const;
};

/// The command-line options that change a case: `--set KEY=VALUE` overrides, then run's end
/// condition and contact search. They are applied to the case file's keys before the case is
/// read, so that they are checked like the file's own keys (a stroke without a moving tool, a
/// search without a contact) and land in the resolved case.
struct CaseOptions {
  std::vector<std::string> set;             ///< "KEY=VALUE", in order (apply_case_overrides)
  std::optional<double> stroke;             ///< mm: control.stroke; control.end_time removed
  std::optional<double> end_time;           ///< s: control.end_time; control.stroke removed
  std::optional<ContactSearchKind> search;  ///< every [[contact]]'s search (a search_margin is
                                            ///< dropped unless the search is "cached")
};

/// Reads and validates a case file. Throws InputError naming the file, line and key for an unknown
/// key, a wrong type, an out-of-range value, a missing file or a dangling name. `overrides`
/// ("KEY=VALUE", e.g. "blank.parameters.n=32") replace or add keys before the case is read
/// (apply_case_overrides); errors in their values name the override.
CaseConfig read_case(const std::filesystem::path& case_file,
                     const std::vector<std::string>& overrides = {});
/// The same with the command-line options of `run` as well.
CaseConfig read_case(const std::filesystem::path& case_file, const CaseOptions& options);

/// The fully resolved case (every default filled) as TOML text, written beside the results.
std::string format_resolved_case(const CaseConfig& config);

}  // namespace sf
