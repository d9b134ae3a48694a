#pragma once
// The drawbead line model (docs/drawbeads.md): a bead of the binder replaced by a line on the
// tool's surface. A blank node in the band of `width` across the line, with the tool closed on
// it, is held back across the line by a restraining force per unit length of bead and pushed away
// from the tool by an uplift force per unit length, both read from curves against the bead's
// closure (0: the tool a bead height or more away, 1: closed on the sheet). The restraint is a
// stick spring with a slip limit, as regularised Coulomb friction is, so a sheet drawn through
// the bead feels the limit and a sheet at rest does not creep; a locking bead has no limit.
#include <climits>
#include <span>
#include <string>
#include <vector>

#include "contact/penalty_contact.hpp"
#include "core/exact_sum.hpp"
#include "core/types.hpp"

namespace sf {

/// The bead's spring across the line as a share of the node's contact penalty stiffness. The
/// spring acts in the sheet's plane, where the friction's stick spring (ratio up to 1) may act
/// too: a quarter keeps their sum within 1.25 k, which the stiffness cap's margin for the
/// elements absorbs (contact/penalty_contact.hpp, build_model's cap factor).
inline constexpr double kDrawbeadStiffnessRatio = 0.25;

/// One bead line: what is fixed for the run (DrawbeadState holds what changes).
struct DrawbeadLine {
  std::string name;
  /// mm, the line's points on the tool's surface, in the tool's mesh frame (its point X stands
  /// at R X + displacement), in order; at least 2
  std::vector<Vec3> points;
  /// unit, the tool surface's normal at each point (mesh frame); either sign
  std::vector<Vec3> normals;
  double width = 0.0;   ///< mm, the band across the line in which the force acts
  double height = 0.0;  ///< mm, the closing travel over which the closure goes from 0 to 1
  /// The force curves: closures in [0, 1], increasing, and at each the restraining and the
  /// uplift force per unit length of bead (N/mm; uplift empty: none); linear between the
  /// points, the end values beyond them. Empty restraining: none (a locking bead).
  std::vector<double> closure;
  std::vector<double> restraining;
  std::vector<double> uplift;
  bool locking = false;  ///< no slip limit: the sheet does not pass
  /// N/mm per blank node: the stick spring across the line (kDrawbeadStiffnessRatio x the
  /// node's contact penalty stiffness with the bead's tool)
  VectorX stiffness;
  /// mm^2 per blank node: its tributary area at the start, and its half thickness then (mm);
  /// the area now is taken as area x start / now of the half thickness (plastic flow keeps the
  /// volume)
  VectorX area;
  VectorX start_half_thickness;
  Vec3 box_min = Vec3::Zero();  ///< mm, mesh frame: the points' box grown by the reach
  Vec3 box_max = Vec3::Zero();

  /// N/mm, the restraining (or uplift) force per length at closure `kappa`; 0 for an empty curve.
  double restraining_at(double kappa) const { return curve_at(restraining, kappa); }
  double uplift_at(double kappa) const { return curve_at(uplift, kappa); }
  double curve_at(const std::vector<double>& values, double kappa) const;
  /// Sets box_min and box_max from the points, grown by width / 2 + height + `thickness` (mm).
  void set_box(double thickness);
  /// mm, the line's length.
  double length() const;
};

/// Per-thread sums of one call, exact so that the totals do not depend on the share-out.
struct alignas(64) DrawbeadShare {
  ExactSum force_on_tool[3];   ///< N
  ExactSum moment_on_tool[3];  ///< N mm, about the origin
  ExactSum work;               ///< N mm, dissipated by slip across the line
  int nodes_in_bead = 0;       ///< nodes within the band with the tool closing on them
  int sliding_nodes = 0;       ///< of which at the slip limit
  void reset() { *this = DrawbeadShare(); }
};

/// What changes over a run: each node's stick force across the line (N; zero off the bead).
struct DrawbeadState {
  VectorX restraint;
  std::vector<DrawbeadShare> shares;        ///< one per thread (scratch)
  std::vector<DrawbeadShare> ghost_shares;  ///< the ghost nodes' (scratch, dropped)
};

/// What one call did (the sums over the counted nodes).
struct DrawbeadResult {
  Vec3 force_on_tool = Vec3::Zero();  ///< N, the reactions on the bead's tool
  Vec3 moment_on_tool =
      Vec3::Zero();   ///< N mm, about the origin (zero for a tool that does not turn)
  double work = 0.0;  ///< N mm, slip work of this call, >= 0
  int nodes_in_bead = 0;
  int sliding_nodes = 0;
};

/// Sizes the state for n blank nodes (zero restraint).
void size_drawbead_state(DrawbeadState& state, int n);

/// For every blank node i (or kinematics.owned_nodes and ghost_nodes as penalty contact takes
/// them): p = R^T (x_i - displacement) in the tool's mesh frame; q the nearest point of the line
/// (nodes beyond its ends are off the bead), t the line's direction and n the surface normal
/// there (interpolated between the points, made normal to t), c = n x t across the line. With
/// s = (p - q) . c, d = (p - q) . n and h_i the node's half thickness:
///   window   phi = (1 + cos(2 pi s / w)) / w   for |s| < w / 2 (1/mm; its integral over s is 1),
///   closure  kappa = clamp(1 - (|d| - h_i) / height, 0, 1),
///   limit    F_r(kappa) A_i phi (N), A_i the node's area now;
/// the stick force across the line is updated as the friction's is (trial = stored - k_i du,
/// du the node's step across the line relative to the tool's point at it; slid back to the limit
/// beyond it, the slip work summed; a locking bead never slides) and the uplift
/// F_u(kappa) A_i phi pushes the node away from the tool along n. Both are added to
/// f_contact.col(i) (N), their reactions to the tool's. A node off the bead has its restraint
/// reset. Over a sheet of uniform nodes spaced w / m across the line (m >= 2 whole), the limits
/// sum to F_r times the length of line the sheet covers: the window's sum is exact there, and
/// close to it for other spacings up to w / 2. Deterministic;
/// allocates only when the state is sized.
DrawbeadResult compute_drawbead_forces(const DrawbeadLine& line, DrawbeadState& state,
                                       const ContactKinematics& kinematics, Matrix3X& f_contact);

}  // namespace sf
