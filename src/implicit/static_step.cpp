#include "implicit/static_step.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/errors.hpp"
#include "core/log.hpp"
#include "implicit/node_graph.hpp"
#include "implicit/rigid_body_modes.hpp"
#include "implicit/tangent_stiffness.hpp"

namespace sf {

namespace {

using Clock = std::chrono::steady_clock;

// The full Newton step is kept unless it multiplies the residual norm by more than this.
constexpr double kResidualGrowthLimit = 1e3;
// An increment diverges (and is cut) when an iteration leaves the residual norm more than this
// times its norm at the start of the increment (docs/static-analysis.md).
constexpr double kDivergenceFactor = 1e6;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A trial point of the Newton iteration: the increment, the forces there and the trial state.
struct TrialPoint {
  Matrix3X du, dtheta;    // mm, rad
  Matrix3X f_int, m_int;  // N, N mm
  Matrix3X f_ext, m_ext;  // N, N mm
  ShellState state;
  VectorX residual;  // per equation: external - internal
  ShellForceResult forces;
  double reference = 0.0;      // N
  double residual_norm = 0.0;  // N (moments / length)
};

class NewtonSolver {
 public:
  NewtonSolver(StaticShellBody& body, const DofMap& dofs, const StaticLoad& load,
               const StaticStepOptions& options, StaticStepReport& report)
      : body_(body),
        dofs_(dofs),
        load_(load),
        options_(options),
        report_(report),
        graph_(make_node_graph(body.part(), body.node_count())),
        tangent_(graph_, dofs, body.length_scale()),
        solver_(options.controls.linear_solver),
        length_(body.length_scale()) {
    const Eigen::Index n = body.node_count();
    for (TrialPoint* p : {&current_, &candidate_}) {
      p->du.setZero(3, n);
      p->dtheta.setZero(3, n);
      p->f_ext.setZero(3, n);
      p->m_ext.setZero(3, n);
      p->residual.setZero(dofs.equation_count());
    }
    delta_.setZero(dofs.equation_count());
    predictor_force_.setZero(dofs.equation_count());
    prescribed_du_.setZero(3, n);
    prescribed_dtheta_.setZero(3, n);
    rotation_.setZero(3, n);
    report_.colours = tangent_.colour_count();
    report_.equations = dofs.equation_count();
  }

  // Tries the increment lambda_start -> lambda_end from the committed state; commits it and
  // returns true when it converges.
  bool run_increment(double lambda_start, double lambda_end, IncrementRecord& record) {
    record.lambda_start = lambda_start;
    record.lambda_end = lambda_end;
    record.stabilization = spring_;
    lambda_end_ = lambda_end;
    const ImplicitConfig& c = options_.controls;
    current_.du.setZero();
    current_.dtheta.setZero();
    set_prescribed_increment(lambda_start, lambda_end);
    try {
      evaluate(current_, lambda_end);
      if (pending_ > 0.0) {
        f_int_start_ = current_.f_int;
        m_int_start_ = current_.m_int;
        compute_predictor_force();
      }
    } catch (const InstabilityError& e) {
      record.failure = e.what();
      return false;
    }
    // External work of the increment by the trapezoidal rule needs the loads at its start.
    f_ext_start_.resize(3, body_.node_count());
    m_ext_start_.resize(3, body_.node_count());
    load_.at(lambda_start, body_.x(), f_ext_start_, m_ext_start_);
    record.initial_residual = current_.residual_norm / current_.reference;
    bool converged = !options_.linear && pending_ == 0.0 &&
                     current_.residual_norm <= c.force_tolerance * current_.reference;
    const int max_iterations = options_.linear ? 1 : c.max_iterations;
    // A divergence is measured against the larger of the initial residual and the force the
    // prescribed increment causes (a step driven by prescriptions alone starts in equilibrium).
    pending_start_ = pending_;
    const double initial_norm =
        std::max({current_.residual_norm, pending_ * predictor_norm_, 1e-300});
    for (int it = 0; it < max_iterations && !converged; ++it) {
      const auto tangent_start = Clock::now();
      tangent_.compute(body_, current_.du, current_.dtheta, stiffness_);
      add_stabilization_to_tangent();
      report_.tangent_seconds += seconds_since(tangent_start);
      report_.tangent_evaluations += tangent_.evaluations_per_tangent();
      factorize_or_throw();
      // K_ff delta = r - K_fp dp for the part dp of the prescribed increment not yet imposed: the
      // free degrees of freedom follow the prescribed ones in the same solve (a consistent
      // predictor), instead of one element taking the whole prescribed step alone.
      solved_for_ = current_.residual - pending_ * predictor_force_;
      solver_.solve(std::span<const double>(solved_for_.data(), solved_for_.size()),
                    std::span<double>(delta_.data(), delta_.size()));
      NewtonIteration iteration;
      double step = 1.0;
      try {
        if (options_.linear) {
          take_step(1.0);
        } else {
          step = search_line();
        }
      } catch (const InstabilityError& e) {
        record.failure = fmt::format("iteration {}: {}", it + 1, e.what());
        return false;
      }
      std::swap(current_, candidate_);
      pending_ = step >= 1.0 ? 0.0 : pending_ * (1.0 - step);  // the prescribed part taken
      iteration.step = step;
      iteration.residual = current_.residual_norm / current_.reference;
      const double increment_norm = displacement_norm(current_.du, current_.dtheta);
      iteration.correction = step * correction_norm() / std::max(increment_norm, 1e-300);
      record.iterations.push_back(iteration);
      log_verbose("    iteration {}: residual {:.3e}, correction {:.3e}, line search {:.3f}\n",
                  it + 1, iteration.residual, iteration.correction, step);
      if (!std::isfinite(current_.residual_norm)) {
        record.failure = fmt::format("iteration {}: the residual is not finite", it + 1);
        return false;
      }
      if (current_.residual_norm > kDivergenceFactor * initial_norm) {
        record.failure = fmt::format(
            "iteration {}: the residual diverged: {:.3e} times its norm at the start of the "
            "increment, beyond the limit {:.0e} (residual {:.3e} of the reference force, largest "
            "at {})",
            it + 1, current_.residual_norm / initial_norm, kDivergenceFactor, iteration.residual,
            worst_node());
        return false;
      }
      converged = options_.linear || (pending_ == 0.0 && iteration.residual <= c.force_tolerance &&
                                      iteration.correction <= c.displacement_tolerance);
    }
    if (!converged) {
      const double correction =
          record.iterations.empty() ? 0.0 : record.iterations.back().correction;
      record.failure = fmt::format(
          "no convergence in {} iterations: residual {:.3e} (tolerance {:.1e}), last correction "
          "{:.3e} (tolerance {:.1e}); the residual is largest at {}",
          max_iterations, current_.residual_norm / current_.reference, c.force_tolerance,
          correction, c.displacement_tolerance, worst_node());
      return false;
    }
    record.converged = true;
    record.unbalanced = spring_ * translation_norm(current_.du) / current_.reference;
    if (options_.linear) {
      // The nonlinear residual at the linear solution means little; report how well the linear
      // system was solved instead.
      report_.final_residual = linear_solve_residual();
    } else {
      report_.final_residual = current_.residual_norm / current_.reference;
    }
    report_.internal_work += current_.forces.internal_work;
    report_.hourglass_work += current_.forces.hourglass_work;
    double external = 0.0;
    for (Eigen::Index i = 0; i < current_.du.cols(); ++i) {
      external += 0.5 * ((f_ext_start_.col(i) + current_.f_ext.col(i)).dot(current_.du.col(i)) +
                         (m_ext_start_.col(i) + current_.m_ext.col(i)).dot(current_.dtheta.col(i)));
    }
    if (options_.linear) {
      compute_linear_reactions();
      // The linear problem's internal forces, whose difference from the loads on the undeformed
      // geometry is the linear reaction (for the history of node groups, converged()).
      linear_f_int_ = linear_force_ + candidate_.f_ext;
      linear_m_int_ = linear_moment_ + candidate_.m_ext;
    }
    const double prescribed = prescribed_increment_work();
    report_.external_work += external + prescribed;
    report_.prescribed_work += prescribed;
    report_.force_scale =
        std::max({report_.force_scale, current_.reference, pending_start_ * predictor_norm_});
    body_.commit(current_.du, current_.state);
    rotation_ += current_.dtheta;
    return true;
  }

  const StiffnessSolver& solver() const { return solver_; }

  /// The last converged state's f_int - f_ext and m_int - m_ext into the report (a linear
  /// analysis's, linear, from run_increment).
  void store_reactions(StaticStepReport& report) const {
    if (options_.linear) {
      report.reaction_force = linear_force_;
      report.reaction_moment = linear_moment_;
      return;
    }
    report.reaction_force = current_.f_int - current_.f_ext;
    report.reaction_moment = current_.m_int - current_.m_ext;
  }

  /// The last converged increment (after run_increment returned true); a linear analysis's forces
  /// are those of the linear problem, the loads on the undeformed geometry.
  ConvergedIncrement converged() const {
    if (options_.linear) {
      return {current_.du,      current_.dtheta,  linear_f_int_, linear_m_int_,
              candidate_.f_ext, candidate_.m_ext, rotation_};
    }
    return {current_.du,    current_.dtheta, current_.f_int, current_.m_int,
            current_.f_ext, current_.m_ext,  rotation_};
  }

  /// N/mm, the stabilising springs on every free translation, anchored at the increment's start.
  void set_stabilization(double k) { spring_ = k; }

 private:
  void evaluate(TrialPoint& p, double lambda) {
    p.forces = body_.compute_forces(p.du, p.dtheta, p.f_int, p.m_int, p.state, options_.linear);
    x_trial_ = body_.x() + p.du;
    load_.at(lambda, x_trial_, p.f_ext, p.m_ext);
    double external = 0.0;
    double internal = 0.0;
    for (Eigen::Index i = 0; i < p.du.cols(); ++i) {
      external += p.f_ext.col(i).squaredNorm() + p.m_ext.col(i).squaredNorm() / (length_ * length_);
      internal += p.f_int.col(i).squaredNorm() + p.m_int.col(i).squaredNorm() / (length_ * length_);
    }
    // The largest load seen in the step is a floor: a load that returns to zero would otherwise
    // measure the residual against nothing.
    largest_load_ = std::max(largest_load_, std::sqrt(external));
    p.reference = std::max({load_.reference_force, largest_load_, std::sqrt(internal), 1e-300});
    double norm = 0.0;
    for (int eq = 0; eq < dofs_.equation_count(); ++eq) {
      const int node = dofs_.node_of(eq);
      const int dof = dofs_.dof_of(eq);
      // Components along the node's axes (its own where it has a frame).
      const double r = dofs_.component(node, dof, p.f_ext, p.m_ext) -
                       dofs_.component(node, dof, p.f_int, p.m_int);
      p.residual[eq] = dof < 3 ? r - spring_ * dofs_.component(node, dof, p.du, p.dtheta) : r;
      norm += dof < 3 ? p.residual[eq] * p.residual[eq] : r * r / (length_ * length_);
    }
    p.residual_norm = std::sqrt(norm);
  }

  // candidate_ = current_ + s (delta + the prescribed increment not yet imposed), evaluated at the
  // increment's end load.
  void take_step(double s) {
    candidate_.du = current_.du;
    candidate_.dtheta = current_.dtheta;
    for (int eq = 0; eq < dofs_.equation_count(); ++eq) {
      dofs_.add(dofs_.node_of(eq), dofs_.dof_of(eq), s * delta_[eq], candidate_.du,
                candidate_.dtheta);
    }
    if (pending_ > 0.0) {
      candidate_.du += (s * pending_) * prescribed_du_;
      candidate_.dtheta += (s * pending_) * prescribed_dtheta_;
    }
    evaluate(candidate_, lambda_end_);
  }

  // The prescribed displacements' change over the increment (prescribed_du_, prescribed_dtheta_);
  // pending_ = 1 when there is one (it is imposed with the first Newton step), else 0.
  void set_prescribed_increment(double lambda_start, double lambda_end) {
    pending_ = 0.0;
    if (!load_.prescribed) {
      return;
    }
    prescribed_du_.setZero();
    prescribed_dtheta_.setZero();
    load_.prescribed(lambda_end, prescribed_du_, prescribed_dtheta_);
    start_du_.setZero(3, body_.node_count());
    start_dtheta_.setZero(3, body_.node_count());
    load_.prescribed(lambda_start, start_du_, start_dtheta_);
    prescribed_du_ -= start_du_;
    prescribed_dtheta_ -= start_dtheta_;
    if (prescribed_du_.cwiseAbs().maxCoeff() > 0.0 ||
        prescribed_dtheta_.cwiseAbs().maxCoeff() > 0.0) {
      pending_ = 1.0;
    }
  }

  // K_fp dp over the free equations: the derivative of the internal forces along the prescribed
  // increment dp, by a central difference at the increment's start (a step of 1e-6 x the length
  // scale for the largest translation, 1e-6 rad for the largest rotation), into predictor_force_.
  void compute_predictor_force() {
    const double largest_translation = prescribed_du_.cwiseAbs().maxCoeff();
    const double largest_rotation = prescribed_dtheta_.cwiseAbs().maxCoeff();
    double eps = std::numeric_limits<double>::infinity();
    if (largest_translation > 0.0) {
      eps = std::min(eps, 1e-6 * length_ / largest_translation);
    }
    if (largest_rotation > 0.0) {
      eps = std::min(eps, 1e-6 / largest_rotation);
    }
    const bool small_strain = options_.linear;
    candidate_.du = current_.du + eps * prescribed_du_;
    candidate_.dtheta = current_.dtheta + eps * prescribed_dtheta_;
    body_.compute_forces(candidate_.du, candidate_.dtheta, candidate_.f_int, candidate_.m_int,
                         candidate_.state, small_strain);
    f_plus_ = candidate_.f_int;
    m_plus_ = candidate_.m_int;
    candidate_.du = current_.du - eps * prescribed_du_;
    candidate_.dtheta = current_.dtheta - eps * prescribed_dtheta_;
    body_.compute_forces(candidate_.du, candidate_.dtheta, candidate_.f_int, candidate_.m_int,
                         candidate_.state, small_strain);
    double norm = 0.0;
    for (int eq = 0; eq < dofs_.equation_count(); ++eq) {
      const int node = dofs_.node_of(eq);
      const int dof = dofs_.dof_of(eq);
      const double k = (dofs_.component(node, dof, f_plus_, m_plus_) -
                        dofs_.component(node, dof, candidate_.f_int, candidate_.m_int)) /
                       (2.0 * eps);
      predictor_force_[eq] = k;
      norm += dof < 3 ? k * k : k * k / (length_ * length_);
    }
    predictor_norm_ = std::sqrt(norm);
  }

  // A linear analysis's reactions, linear in the increment: f_int(0) + K du - f_ext(x), K du
  // by a central difference along du (the forces of a linear analysis lie on x + du / 2, which
  // adds terms of second order: stress times rotation), the loads on the initial geometry. Before
  // the increment is committed.
  void compute_linear_reactions() {
    const double largest_translation = current_.du.cwiseAbs().maxCoeff();
    const double largest_rotation = current_.dtheta.cwiseAbs().maxCoeff();
    double eps = 1.0;
    if (largest_translation > 0.0) {
      eps = std::min(eps, 1e-6 * length_ / largest_translation);
    }
    if (largest_rotation > 0.0) {
      eps = std::min(eps, 1e-6 / largest_rotation);
    }
    const Eigen::Index n = body_.node_count();
    candidate_.du = eps * current_.du;
    candidate_.dtheta = eps * current_.dtheta;
    body_.compute_forces(candidate_.du, candidate_.dtheta, f_plus_, m_plus_, candidate_.state,
                         true);
    candidate_.du = -eps * current_.du;
    candidate_.dtheta = -eps * current_.dtheta;
    body_.compute_forces(candidate_.du, candidate_.dtheta, linear_force_, linear_moment_,
                         candidate_.state, true);
    linear_force_ = (0.5 / eps) * (f_plus_ - linear_force_);
    linear_moment_ = (0.5 / eps) * (m_plus_ - linear_moment_);
    candidate_.du.setZero(3, n);
    candidate_.dtheta.setZero(3, n);
    body_.compute_forces(candidate_.du, candidate_.dtheta, f_plus_, m_plus_, candidate_.state,
                         true);
    load_.at(lambda_end_, body_.x(), candidate_.f_ext, candidate_.m_ext);
    linear_force_ += f_plus_ - candidate_.f_ext;
    linear_moment_ += m_plus_ - candidate_.m_ext;
  }

  // N mm, the work of the reactions on the prescribed increment, by the trapezoidal rule: the
  // reaction is f_int - f_ext (what the support adds to the loads), at the start and the end (a
  // linear analysis's end reactions from compute_linear_reactions).
  double prescribed_increment_work() const {
    if (!load_.prescribed || (prescribed_du_.isZero(0.0) && prescribed_dtheta_.isZero(0.0))) {
      return 0.0;
    }
    double work = 0.0;
    for (Eigen::Index i = 0; i < prescribed_du_.cols(); ++i) {
      const Vec3 end_force = options_.linear ? Vec3(linear_force_.col(i))
                                             : Vec3(current_.f_int.col(i) - current_.f_ext.col(i));
      const Vec3 end_moment = options_.linear ? Vec3(linear_moment_.col(i))
                                              : Vec3(current_.m_int.col(i) - current_.m_ext.col(i));
      const Vec3 r_force = (f_int_start_.col(i) - f_ext_start_.col(i)) + end_force;
      const Vec3 r_moment = (m_int_start_.col(i) - m_ext_start_.col(i)) + end_moment;
      work += 0.5 * (r_force.dot(prescribed_du_.col(i)) + r_moment.dot(prescribed_dtheta_.col(i)));
    }
    return work;
  }

  // The line search is a safeguard, not an energy minimisation: thin shells store bending
  // energy quadratically but membrane energy quartically in a large-rotation step, so the energy
  // minimum along a Newton correction sits far short of the step that the next iteration
  // completes (the membrane part is fixed by one more linear solve). The full step is therefore
  // kept unless it inverts an element (then halved, up to four times) or raises the residual
  // norm more than a thousandfold (a thin strip's first step in a 22-degree increment raises it
  // 420-fold and converges in 7 iterations without a search); only then g(s) = delta . r(u + s
  // delta) is driven towards zero by regula falsi (Crisfield 1991, vol. 1, sec. 9.5), at most five
  // evaluations, s in [0.1, 1].
  double search_line() {
    const double g0 = delta_.dot(current_.residual);
    double s = 1.0;
    for (int attempt = 0;; ++attempt) {
      try {
        take_step(s);
        break;
      } catch (const InstabilityError&) {
        if (attempt >= 4) {
          throw;
        }
        s *= 0.5;
      }
    }
    log_verbose("      full step: residual x {:.3e}\n",
                candidate_.residual_norm / current_.residual_norm);
    if (!options_.controls.line_search ||
        candidate_.residual_norm <= kResidualGrowthLimit * current_.residual_norm) {
      return s;
    }
    double g = delta_.dot(candidate_.residual);
    if (g * g0 > 0.0) {
      return s;  // still descending at the full step: no root of g to find in (0, s)
    }
    double s_low = 0.0, g_low = g0, s_high = s, g_high = g;
    double best_s = s, best_g = g;
    for (int k = 0; k < 5; ++k) {
      double trial = s_high - g_high * (s_high - s_low) / (g_high - g_low);
      trial = std::clamp(trial, 0.1, 1.0);
      take_step(trial);
      const double gt = delta_.dot(candidate_.residual);
      if (std::abs(gt) < std::abs(best_g)) {
        best_s = trial;
        best_g = gt;
      }
      if (std::abs(gt) <= 0.5 * std::abs(g0)) {
        return trial;
      }
      if (gt * g0 > 0.0) {
        s_low = trial;
        g_low = gt;
      } else {
        s_high = trial;
        g_high = gt;
      }
    }
    take_step(best_s);
    return best_s;
  }

  void factorize_or_throw() {
    try {
      solver_.factorize(stiffness_);
      report_.last_factorization = solver_.last_stats();
    } catch (const SingularSystemError& e) {
      std::string where = "an equation the solver does not name";
      if (e.equation() >= 0 && e.equation() < dofs_.equation_count()) {
        const int node = dofs_.node_of(e.equation());
        where = fmt::format("{} {}", name(node), dofs_.dof_name(node, dofs_.dof_of(e.equation())));
      }
      throw ConvergenceError(fmt::format(
          "the tangent stiffness is singular at {} ({}): the constraints leave a mechanism or a "
          "rigid-body mode free there; hold it with [[boundary]] entries (or leave "
          "implicit.rigid_body_modes = \"auto\" for the rigid-body modes)",
          where, e.what()));
    }
  }

  // ||K delta - r|| / ||r|| of the last solve (r the residual it was solved for).
  double linear_solve_residual() {
    product_.resize(delta_.size());
    stiffness_.multiply(std::span<const double>(delta_.data(), delta_.size()),
                        std::span<double>(product_.data(), product_.size()));
    return (product_ - solved_for_).norm() / std::max(solved_for_.norm(), 1e-300);
  }

  void add_stabilization_to_tangent() {
    if (spring_ == 0.0) {
      return;
    }
    if (diagonal_.empty()) {  // the pattern is fixed: find the translations' diagonal once
      for (int eq = 0; eq < dofs_.equation_count(); ++eq) {
        if (dofs_.dof_of(eq) < 3) {
          diagonal_.push_back(stiffness_.find(eq, eq));
        }
      }
    }
    for (const int at : diagonal_) {
      stiffness_.values[static_cast<std::size_t>(at)] += spring_;
    }
  }

  // mm, the norm of the free translations of an increment.
  double translation_norm(const Matrix3X& du) const {
    double norm = 0.0;
    for (int eq = 0; eq < dofs_.equation_count(); ++eq) {
      const int dof = dofs_.dof_of(eq);
      if (dof < 3) {
        const double d = dofs_.component(dofs_.node_of(eq), dof, du, du);
        norm += d * d;
      }
    }
    return std::sqrt(norm);
  }

  double displacement_norm(const Matrix3X& du, const Matrix3X& dtheta) const {
    return std::sqrt(du.squaredNorm() + length_ * length_ * dtheta.squaredNorm());
  }

  double correction_norm() const {
    double norm = 0.0;
    for (int eq = 0; eq < dofs_.equation_count(); ++eq) {
      const double d = delta_[eq];
      norm += dofs_.dof_of(eq) < 3 ? d * d : d * d * length_ * length_;
    }
    return std::sqrt(norm);
  }

  std::string name(int node) const {
    return options_.node_name ? options_.node_name(node) : fmt::format("node {}", node);
  }

  std::string worst_node() const {
    int worst = -1;
    double largest = -1.0;
    std::vector<double> per_node(static_cast<std::size_t>(body_.node_count()), 0.0);
    for (int eq = 0; eq < dofs_.equation_count(); ++eq) {
      const double r = current_.residual[eq];
      per_node[static_cast<std::size_t>(dofs_.node_of(eq))] +=
          dofs_.dof_of(eq) < 3 ? r * r : r * r / (length_ * length_);
    }
    for (std::size_t i = 0; i < per_node.size(); ++i) {
      if (per_node[i] > largest) {
        largest = per_node[i];
        worst = static_cast<int>(i);
      }
    }
    return worst < 0 ? std::string("no node")
                     : fmt::format("{} ({:.3e} N)", name(worst), std::sqrt(largest));
  }

  StaticShellBody& body_;
  const DofMap& dofs_;
  const StaticLoad& load_;
  const StaticStepOptions& options_;
  StaticStepReport& report_;
  NodeGraph graph_;
  TangentStiffness tangent_;
  StiffnessSolver solver_;
  double length_;
  CscMatrix stiffness_;
  TrialPoint current_, candidate_;
  VectorX delta_;
  VectorX solved_for_, product_;  // the right-hand side of the last solve, and K delta
  Matrix3X x_trial_, f_ext_start_, m_ext_start_;
  // Prescribed displacements: the increment's change (along the nodes' axes), the share of it not
  // yet imposed, K_fp dp over the free equations and its norm, the internal forces at the start.
  Matrix3X prescribed_du_, prescribed_dtheta_, start_du_, start_dtheta_;
  Matrix3X f_plus_, m_plus_, f_int_start_, m_int_start_;
  VectorX predictor_force_;
  double predictor_norm_ = 0.0;
  double pending_ = 0.0;
  double pending_start_ = 0.0;  // pending_ at the increment's start (1 with a prescription)
  Matrix3X linear_force_, linear_moment_;  // a linear analysis's reactions (N, N mm)
  Matrix3X linear_f_int_, linear_m_int_;   // and its internal forces (N, N mm)
  Matrix3X rotation_;          // rad, the converged rotation increments summed over the step
  std::vector<int> diagonal_;  // positions of the translations' diagonal entries in stiffness_
  double spring_ = 0.0;        // N/mm, stabilising springs (StaticStepOptions::stabilization)
  double lambda_end_ = 0.0;    // the load factor the increment being solved ends at
  double largest_load_ = 0.0;  // N, the largest external load norm evaluated in the step
};

// Settling at load factor 1 (pseudo-transient continuation with switched evolution
// relaxation: Mulder & van Leer 1985, Kelley & Keyes 1998). Each settling increment is solved with
// springs k anchored at its start, so the converged state misses equilibrium by the springs'
// force k |du|, the unbalanced force. The springs are scaled by the ratio of the last two
// unbalanced forces (softer as the motion dies out, within [1/20, 2] per increment) and, after an
// increment that took at most a third of max_iterations, softened fourfold more; once the
// unbalanced force is within the force tolerance, or the springs are a millionth of their start,
// an increment without springs finishes the step (a plain Newton solve from a state that is
// nearly in equilibrium). An increment that fails is retried with ten times stiffer springs.
constexpr int kMaxSettlingIncrements = 60;

void settle(NewtonSolver& newton, const StaticStepOptions& options, StaticStepReport& report) {
  const double k_start = options.stabilization;
  const double tolerance = options.controls.force_tolerance;
  double k = k_start;
  double previous = report.increments.back().unbalanced;
  for (int n = 0; n < kMaxSettlingIncrements; ++n) {
    const bool last_try = previous <= tolerance || k <= 1e-6 * k_start;
    newton.set_stabilization(last_try ? 0.0 : k);
    IncrementRecord record;
    const bool ok = newton.run_increment(1.0, 1.0, record);
    report.increments.push_back(record);
    if (!ok) {
      report.cuts += 1;
      log_info("  settling increment with {:.3e} N/mm springs failed ({}); stiffer springs\n",
               record.stabilization, record.failure);
      k = std::min(10.0 * std::max(k, 1e-6 * k_start), 10.0 * k_start);
      previous = std::numeric_limits<double>::infinity();  // not done: springs again next
      continue;
    }
    report.settling_increments += 1;
    report.newton_iterations += static_cast<int>(record.iterations.size());
    log_info(
        "  settling {} at load factor 1: springs {:.3e} N/mm, {} iterations, unbalanced "
        "{:.2e}\n",
        report.settling_increments, record.stabilization, record.iterations.size(),
        record.unbalanced);
    if (record.stabilization == 0.0) {
      return;
    }
    const double ratio =
        std::isfinite(previous) && previous > 0.0 ? record.unbalanced / previous : 1.0;
    const bool easy =
        static_cast<int>(record.iterations.size()) * 3 <= options.controls.max_iterations;
    k *= std::clamp(ratio, 0.05, 2.0) * (easy ? 0.25 : 1.0);
    k = std::min(k, 10.0 * k_start);
    previous = record.unbalanced;
  }
  throw ConvergenceError(fmt::format(
      "the static step reached load factor 1 but did not settle in {} increments: the state "
      "still misses equilibrium by {:.3e} x the reference force without its stabilising springs; "
      "raise implicit.increments, or lower the stabilisation",
      kMaxSettlingIncrements, previous));
}

}  // namespace

StaticStepReport solve_static_step(StaticShellBody& body, const DofMap& dofs,
                                   const StaticLoad& load, const StaticStepOptions& options,
                                   const IncrementCallback& on_converged) {
  StaticStepReport report;
  // Free rigid-body modes make the tangent singular; finite differences would only make it
  // nearly so, and the factorisation could return a huge rigid motion instead of failing.
  const RigidBodyModes free = find_free_rigid_body_modes(body.x(), dofs.held());
  if (free.free_count > 0) {
    std::string listed;
    for (const std::string& m : free.free_modes) {
      listed += (listed.empty() ? "" : "; ") + m;
    }
    throw ConvergenceError(
        fmt::format("the stiffness is singular: the holds leave {} rigid-body mode{} free ({})",
                    free.free_count, free.free_count == 1 ? "" : "s", listed));
  }
  NewtonSolver newton(body, dofs, load, options, report);
  const ImplicitConfig& c = options.controls;
  const bool stabilized = options.stabilization > 0.0 && !options.linear;
  newton.set_stabilization(stabilized ? options.stabilization : 0.0);
  const double nominal = options.linear ? 1.0 : 1.0 / c.increments;
  double lambda = 0.0;
  double step = nominal;
  int cut_level = 0;
  int successes_since_cut = 0;
  while (lambda < 1.0 - 1e-12) {
    const double target = std::min(1.0, lambda + step);
    IncrementRecord record;
    const bool ok = newton.run_increment(lambda, target, record);
    report.increments.push_back(record);
    if (ok) {
      lambda = target;
      report.converged_increments += 1;
      report.newton_iterations += static_cast<int>(record.iterations.size());
      log_info("  increment {}: load factor {:.4f}, {} iterations, residual {:.2e}{}\n",
               report.converged_increments, lambda, record.iterations.size(), report.final_residual,
               stabilized ? fmt::format(", unbalanced {:.2e} (held by the stabilising springs)",
                                        record.unbalanced)
                          : std::string());
      // A stabilised step reports load factor 1 once it has settled there.
      if (on_converged && !(stabilized && lambda >= 1.0 - 1e-12)) {
        on_converged(lambda, body, report, newton.converged());
      }
      // After two good increments at a cut size, try twice the size again (up to the nominal).
      if (cut_level > 0 && ++successes_since_cut >= 2) {
        step = std::min(2.0 * step, nominal);
        cut_level -= 1;
        successes_since_cut = 0;
      }
      continue;
    }
    report.cuts += 1;
    cut_level += 1;
    successes_since_cut = 0;
    if (options.linear || cut_level > c.max_cuts) {
      report.solver = newton.solver().totals();
      throw ConvergenceError(fmt::format(
          "the static step stopped at load factor {:.6f} of 1: the increment to {:.6f} failed "
          "after {} halvings ({}); raise implicit.max_iterations or implicit.max_cuts, or give "
          "more implicit.increments{}",
          lambda, target, cut_level - 1, record.failure,
          stabilized ? ", or stronger stabilising springs" : ""));
    }
    step *= 0.5;
    log_info(
        "  increment to load factor {:.4f} failed ({}); halved ({} of {}): tried again from load "
        "factor {:.4f} to {:.4f}\n",
        target, record.failure, cut_level, c.max_cuts, lambda, std::min(1.0, lambda + step));
  }
  if (stabilized) {
    settle(newton, options, report);
  }
  newton.store_reactions(report);
  if (stabilized && on_converged) {
    on_converged(1.0, body, report, newton.converged());
  }
  report.solver = newton.solver().totals();
  return report;
}

}  // namespace sf
