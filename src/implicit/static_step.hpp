#pragma once
// An implicit static step: the load applied in increments, each solved by Newton-Raphson on the
// finite-difference tangent with a line search, convergence on the force and displacement
// norms, and an increment that fails halved and tried again (docs/static-analysis.md).
#include <functional>
#include <string>
#include <vector>

#include "casefile/case_config.hpp"
#include "implicit/dof_map.hpp"
#include "implicit/static_shell_body.hpp"
#include "implicit/stiffness_solver.hpp"

namespace sf {

/// What loads the body over the step, as a function of the load factor lambda in [0, 1].
struct StaticLoad {
  /// External forces f (N) and moments m (N mm) at lambda on the coordinates x (f, m sized by
  /// the caller; the function sets every entry).
  std::function<void(double lambda, const Matrix3X& x, Matrix3X& f, Matrix3X& m)> at;
  /// N, the force level the residual is measured against (moments count divided by the body's
  /// length scale); 0 = the larger of the internal force norm at each iteration and the largest
  /// external load norm met so far in the step.
  double reference_force = 0.0;
  /// Prescribed displacements (mm) and rotations (rad) of held degrees of freedom at lambda, from
  /// the state the step starts from: adds them to du, dtheta (sized and zeroed by the caller),
  /// along the nodes' axes. Empty = none: held degrees of freedom stay where they are. Each
  /// increment imposes the change over it (docs/static-analysis.md, "Prescribed displacements").
  std::function<void(double lambda, Matrix3X& du, Matrix3X& dtheta)> prescribed;
};

/// One Newton iteration's record.
struct NewtonIteration {
  double residual = 0.0;    ///< -, residual norm / reference force after the iteration
  double correction = 0.0;  ///< -, correction norm / increment norm
  double step = 1.0;        ///< -, the line search's factor on the Newton correction
};

struct IncrementRecord {
  double lambda_start = 0.0;
  double lambda_end = 0.0;
  bool converged = false;
  double initial_residual = 0.0;  ///< -, before the first iteration
  std::vector<NewtonIteration> iterations;
  std::string failure;         ///< why it was cut (empty when converged)
  double stabilization = 0.0;  ///< N/mm, the stabilising springs it was solved with
  /// -, the springs' force at the converged state / the reference force: the force by which the
  /// state misses equilibrium without them (0 without springs)
  double unbalanced = 0.0;
};

struct StaticStepOptions {
  ImplicitConfig controls;
  /// One solve on the tangent at the start, no iterations (a linear analysis).
  bool linear = false;
  /// Names a node in messages (e.g. "node 12 (gmsh 13)"); default "node i".
  std::function<std::string(int node)> node_name;
  /// N/mm, stabilising springs on every free translation, anchored at the start of each
  /// increment (0 = none). They resist only the motion within an increment, so the step can pass
  /// states where the unsupported body is unstable; once the load factor reaches 1 the step
  /// settles at it, the springs softened as the motion dies out and finally removed, so the last
  /// state is in equilibrium without them (pseudo-transient continuation, docs/static-analysis.md).
  double stabilization = 0.0;
};

struct StaticStepReport {
  std::vector<IncrementRecord> increments;  ///< every attempt, in order, cut ones included
  int converged_increments = 0;
  int cuts = 0;
  int newton_iterations = 0;  ///< over the converged increments
  double tangent_seconds = 0.0;
  int tangent_evaluations = 0;
  int colours = 0;  ///< of the distance-2 node colouring
  int equations = 0;
  FactorizationStats last_factorization;
  StiffnessSolverTotals solver;
  /// N mm, work of the internal forces over the step (the drilling springs' included; the
  /// hourglass forces' apart)
  double internal_work = 0.0;
  /// N mm, work of the hourglass forces: Belytschko-Tsay's stiffness form, or the assumed-strain
  /// element's stabilisation (as in explicit runs)
  double hourglass_work = 0.0;
  /// N mm, work of the loads over the step, and of the reactions on the prescribed displacements
  double external_work = 0.0;
  double prescribed_work = 0.0;  ///< N mm, the part of external_work done by those reactions
  double final_residual = 0.0;   ///< -, relative, of the last converged increment
  /// Stabilisation (StaticStepOptions::stabilization > 0): the settling increments at load
  /// factor 1 (the last one is taken without springs: increments.back().stabilization == 0).
  int settling_increments = 0;
  /// Per node, f_int - f_ext (N) and m_int - m_ext (N mm) at the last converged state: the
  /// reactions where a degree of freedom is held or prescribed, the residual elsewhere. A linear
  /// analysis gives them linear: f_int(0) + K du - f_ext with the loads on the initial geometry.
  Matrix3X reaction_force, reaction_moment;
  /// N, the largest force the step measured against: the reference forces of its increments and
  /// the forces its prescribed increments cause (K_fp dp).
  double force_scale = 0.0;
};

/// A static step as the run summary reports it.
struct ImplicitStepSummary {
  StaticStepReport report;
  std::vector<std::string> free_modes;  ///< rigid-body modes the case's constraints left free
  std::vector<std::string> added_constraints;  ///< the holds added for them
  double wall_seconds = 0.0;                   ///< s, the whole step
};

/// A converged increment as IncrementCallback sees it: its motion from the previous committed
/// state and the forces at the new committed state (valid during the call only).
struct ConvergedIncrement {
  const Matrix3X& du;      ///< mm, the translation increment of every node
  const Matrix3X& dtheta;  ///< rad, the rotation increment of every node
  const Matrix3X& f_int;   ///< N, internal forces (the drilling springs' included)
  const Matrix3X& m_int;   ///< N mm, internal moments (the drilling springs' included)
  const Matrix3X& f_ext;   ///< N, external forces at the increment's load factor
  const Matrix3X& m_ext;   ///< N mm, external moments likewise
  /// rad, every node's rotation increments summed over the step's converged increments so far
  /// (settling increments included)
  const Matrix3X& rotation;
};

/// Called after each converged increment with its load factor, the body (committed), the report
/// so far and the increment.
using IncrementCallback =
    std::function<void(double lambda, const StaticShellBody& body, const StaticStepReport& report,
                       const ConvergedIncrement& increment)>;

/// Solves the step, committing each converged increment into `body` and calling on_converged
/// after it. Throws ConvergenceError naming the load factor, the
/// residual and the worst node when an increment fails after controls.max_cuts halvings or the
/// stiffness is singular.
StaticStepReport solve_static_step(StaticShellBody& body, const DofMap& dofs,
                                   const StaticLoad& load, const StaticStepOptions& options,
                                   const IncrementCallback& on_converged = {});

}  // namespace sf
