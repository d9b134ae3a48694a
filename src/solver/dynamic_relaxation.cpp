#include "solver/dynamic_relaxation.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "core/log.hpp"
#include "solver/explicit_driver.hpp"
#include "solver/frame_observer.hpp"
#include "solver/output_schedule.hpp"
#include "solver/time_loop.hpp"
#include "solver/time_step_control.hpp"

// The explicit springback route (docs/static-analysis.md, "Springback by dynamic relaxation").
//
// Release. The contact forces of the last forming cycle become nodal loads, each scaled by a curve
// that is 1 at the end of forming t0 and falls linearly to 0 at t0 + release_time; the contact is
// switched off and the tools are held where they are (a force-controlled tool is stopped). At t0
// the applied force on every node is exactly what it was: the contact force is moved into
// state.f_ext, so the first step's trapezoidal work is counted with the loads (not half with the
// contact), and nothing jumps.
//
// Kinetic damping (Cundall's scheme), from the start of the release. After every step the
// whole-step kinetic energy K(n+1) is compared with K(n); when it has fallen, a peak has just
// passed, and the whole-step velocity v(n+1) is set to zero (translations and rotations; the
// components a prescribed velocity holds keep theirs). The run then goes on as from rest: the next
// step takes a run's first half kick, v(n+3/2) = dt/2 a(n+1). (Zeroing only the half-step velocity
// and going on with the full kick, v(n+3/2) = dt a(n+1), makes every step after a reset a gradient
// step twice too long, unstable for the modes with omega dt > sqrt(2): resets every other step
// near the stability limit then pumped energy in until the run blew up.)
// Why this finds the static state whatever the masses are (mass scaling included): for elastic
// forces the total energy E = K + Pi (Pi the potential of the internal forces and the loads) is
// constant in the undamped motion up to the integrator's small error; each reset lowers it by the
// kinetic energy taken out, largest at a peak of K, where the configuration is nearest a minimum
// of Pi along the path. E only decreases and K >= 0, so the motion settles where Pi is stationary
// with zero velocity: M a = f_ext - f_int = 0. M is diagonal and positive, so a = 0 means f_ext =
// f_int for any M: the masses (scaled or not) change the path, the time to converge and when the
// resets come, never the equilibrium. With plasticity the internal forces are path dependent:
// the route then finds an equilibrium reached along a damped dynamic path, not the quasi-static
// one (reverse yielding in an oscillation would stay); the slow release and the resets keep that
// path close to the quasi-static one.
//
// Energies. The released loads do work (energies.external_work, by the driver's trapezoidal rule,
// as for any nodal load). A reset takes out the whole-step kinetic energy K(n+1), counted in
// energies.damping. The reported total is then unchanged, and so is the central-difference
// invariant total - supplied - D (D = dt^2/8 F.M^-1.F, the half-kick energy, which the reset does
// not change; docs/time-integration.md), so the balance column keeps the accuracy of an undamped
// run.
//
// Stop rule. Right after a reset K is 0, and the peaks of K between resets are no measure either:
// a stiff shell has modes far apart, and a little energy in a high mode makes K turn down within
// a few steps of a reset, again and again, while the lowest mode, restarted from rest each time,
// creeps towards equilibrium with a tiny K (measured: three such peaks in a row below 1e-8 of the
// internal energy with the tip of a cantilever still 8e-4 of its deflection away). So a small
// peak only starts a check of rest: a free run without resets as long as the longest interval
// between resets seen so far (the lowest mode's quarter period: the time it takes to turn its
// remaining energy into kinetic energy). At rest when K stays below kinetic_tolerance x the
// reference energy all through it; otherwise the resets resume. Every mode with energy E_j left
// reaches K >= E_j within its first quarter period, so a passed check bounds the energy left in
// each mode (the lowest included) by the tolerance. The velocities are zeroed at the end.
// The reference is the larger of the internal energy (hourglass included) at the start of
// springback and now: for a part that springs back almost fully (an elastic one) the internal
// energy itself goes to zero with the kinetic energy and their ratio does not fall, while the
// energy the part held when formed keeps the scale.

namespace sf {
namespace {

/// Kinetic damping's reset at the end of a step, time t(n+1): the whole-step velocity v(n+1)
/// (translations and rotations; the components a prescribed velocity holds keep their value) is
/// set to zero and the run goes on as from rest: state.v = 0 and the next step takes the first
/// step's half kick, v(n+3/2) = dt/2 a(n+1) (the caller passes dt_previous = 0). Returns the
/// kinetic energy taken out (N mm), added to energies.damping; energies.kinetic becomes that of the
/// prescribed components (0 without prescribed velocities).
double reset_velocities(const Model& model, SolutionState& s) {
  const double before = s.energies.kinetic;
  const NodalConstraints& constraints = model.constraints;
  double after = 0.0;
  for (Eigen::Index i = 0; i < s.v.cols(); ++i) {
    const unsigned prescribed =
        constraints.prescribed.empty() ? 0u : constraints.prescribed[static_cast<std::size_t>(i)];
    if (prescribed == 0) {
      s.v.col(i).setZero();
      s.omega.col(i).setZero();
      continue;
    }
    Vec3 v = s.v.col(i);
    Vec3 omega = s.omega.col(i);
    constraints.zero_components(static_cast<int>(i), ~prescribed & 0x3fu, v, omega);
    s.v.col(i) = v;
    s.omega.col(i) = omega;
    after += 0.5 * (s.mass[i] * v.squaredNorm() + s.rotational_inertia[i] * omega.squaredNorm());
  }
  const double removed = before - after;
  s.energies.kinetic = after;
  s.energies.damping += removed;
  return removed;
}

/// What freezing the tool forces did.
struct FrozenLoads {
  int nodes = 0;                    // nodes that got a released load
  Vec3 contact_sum = Vec3::Zero();  // N, the contact forces' sum at the end of forming
  Vec3 sum = Vec3::Zero();          // N, the released loads' sum
};

/// Turns what the tools held the blank with into nodal loads released linearly over
/// [t0, t0 + T]: per node, the static internal force and moment of the formed state (velocities
/// zero, no strain increment) less the case's own loads, as the implicit route releases them
/// (run_implicit_springback). With them the blank starts in equilibrium at rest. The contact
/// forces themselves are not used: at the end of a dynamic run they differ from those by the
/// blank's inertia, which on a U-channel is a vibrating flange tapping the holder (about 70 of its
/// 280 nodes touch at any one time): frozen, that snapshot is a set of unbalanced point loads of
/// a few N on a flange whose tip stiffness is 0.03 N/mm, and the flange swung up by 36 degrees.
/// Call with the contact off and the velocities zeroed; moves the loads into state.f_ext, m_ext.
FrozenLoads freeze_tool_forces(const Model& model, SolutionState& s, double release_time,
                               const Matrix3X& contact_force) {
  FrozenLoads frozen;
  for (Eigen::Index i = 0; i < contact_force.cols(); ++i) {
    frozen.contact_sum += contact_force.col(i);
  }
  compute_forces(model, s, 0.0);  // dt = 0: the stresses as they are, no viscous terms at rest
  const double t0 = s.time;
  const LoadCurve release({t0, t0 + release_time}, {1.0, 0.0});
  for (Eigen::Index i = 0; i < s.f_int.cols(); ++i) {
    const Vec3 f = s.f_int.col(i) - s.f_ext.col(i);
    const Vec3 m = s.m_int.col(i) - s.m_ext.col(i);
    for (const auto& [value, moment] : {std::pair{f, false}, std::pair{m, true}}) {
      if (value.isZero(0.0)) {
        continue;
      }
      NodalLoad load;
      load.nodes = {static_cast<int>(i)};
      load.value = value;
      load.moment = moment;
      load.scale = release;
      s.released_loads.push_back(std::move(load));
    }
    if (!f.isZero(0.0) || !m.isZero(0.0)) {
      ++frozen.nodes;
    }
    s.f_ext.col(i) += f;
    s.m_ext.col(i) += m;
    frozen.sum += f;
  }
  s.f_contact.setZero();
  s.f_contact_previous.setZero();
  s.contact_spring_energy = 0.0;
  return frozen;
}

/// Switches the contact off for the rest of the run (no contact forces, no searches; the search
/// audits, if any, stop with it).
void switch_contact_off(SolutionState& s) {
  s.contact_off = true;
}

/// Holds every tool where it is for the rest of the run (a displacement curve held at its present
/// travel): a force-controlled tool becomes a fixed one and its kinetic energy, taken out with its
/// velocity, is counted in energies.damping. Returns that energy (N mm).
double hold_tools(const Model& model, SolutionState& s) {
  double removed = 0.0;
  for (std::size_t t = 0; t < model.tools.size(); ++t) {
    const Tool& tool = model.tools[t];
    ToolState& state = s.tools[t];
    if (tool.force_control && !state.held) {
      removed += 0.5 * tool.force_control->mass() * state.speed * state.speed;
    }
    state.held = true;
    if (tool.force_control) {
      state.displacement = state.travel * tool.direction();
    }
    state.previous_displacement = state.displacement;
    state.previous_rotation = state.rotation;
    state.moment.setZero();
    state.previous_moment.setZero();
    state.speed = 0.0;
    state.velocity = 0.0;
    state.force.setZero();
    state.previous_force.setZero();
    state.nodes_in_contact = 0;
  }
  s.energies.kinetic -= removed;
  s.energies.damping += removed;
  return removed;
}

/// Kinetic damping and the stop rule, applied after every step.
class KineticDamping {
 public:
  enum class Outcome { moving, reset, at_rest };

  /// tolerance: kinetic_tolerance; entry_internal: the internal + hourglass energy at the start
  /// (N mm); t0: the start time (s); kinetic: the kinetic energy at the start (N mm).
  KineticDamping(double tolerance, double entry_internal, double t0, double kinetic)
      : tolerance_(tolerance),
        entry_internal_(entry_internal),
        reference_(entry_internal),
        previous_kinetic_(kinetic),
        interval_peak_(kinetic),
        last_reset_time_(t0) {}

  /// After a step: resets the velocities at a peak of the kinetic energy, runs the rest probe
  /// (only once `after_release`), and says which happened.
  Outcome after_step(const Model& model, SolutionState& s, bool after_release) {
    const Energies& e = s.energies;
    reference_ = std::max(entry_internal_, e.internal + e.hourglass);
    const double threshold = tolerance_ * reference_;
    const double k = e.kinetic;
    if (probing_) {
      probe_peak_ = std::max(probe_peak_, k);
      if (probe_peak_ >= threshold) {
        probing_ = false;  // not at rest after all: the resets resume at the next peak
        interval_peak_ = probe_peak_;
        probe_peak_ = 0.0;
      } else if (s.time - probe_start_ >= longest_interval_) {
        last_peak_ = probe_peak_;
        removed_ += reset_velocities(model, s);  // leave the blank at rest
        ++resets_;
        return Outcome::at_rest;
      } else {
        previous_kinetic_ = k;
        return Outcome::moving;
      }
    }
    if (k < previous_kinetic_) {
      last_peak_ = std::max(interval_peak_, k);
      removed_ += reset_velocities(model, s);
      ++resets_;
      if (!interval_probed_) {
        longest_interval_ = std::max(longest_interval_, s.time - last_reset_time_);
      }
      last_reset_time_ = s.time;
      interval_probed_ = false;
      interval_peak_ = e.kinetic;
      previous_kinetic_ = e.kinetic;
      if (after_release && last_peak_ < threshold) {
        probing_ = true;
        interval_probed_ = true;
        probe_start_ = s.time;
        probe_peak_ = e.kinetic;
        ++probes_;
      }
      return Outcome::reset;
    }
    interval_peak_ = std::max(interval_peak_, k);
    previous_kinetic_ = k;
    return Outcome::moving;
  }

  /// N mm, what the tolerance multiplies.
  double reference() const { return reference_; }
  /// The stop rule's kinetic energy (N mm): the peak of the probe that ended at rest, or else the
  /// larger of the last closed interval's and the open interval's (or probe's) peaks.
  double peak(bool at_rest) const {
    return at_rest ? last_peak_ : std::max({last_peak_, interval_peak_, probe_peak_});
  }
  /// The peak of the open interval (or probe) over the reference: the progress line's ratio.
  double running_ratio() const {
    const double k = probing_ ? probe_peak_ : interval_peak_;
    return reference_ > 0.0 ? k / reference_ : 0.0;
  }
  long resets() const { return resets_; }
  int probes() const { return probes_; }
  double removed() const { return removed_; }
  double window() const { return longest_interval_; }

 private:
  double tolerance_;
  double entry_internal_;
  double reference_;
  double previous_kinetic_;        // N mm, after the last step (or reset)
  double interval_peak_;           // N mm, the largest kinetic energy since the last reset
  double last_peak_ = 0.0;         // N mm, the peak of the last interval closed by a reset
  double last_reset_time_;         // s
  double longest_interval_ = 0.0;  // s, the longest interval between resets without a probe
  bool interval_probed_ = false;   // a probe ran in the open interval
  bool probing_ = false;
  double probe_start_ = 0.0;  // s
  double probe_peak_ = 0.0;   // N mm
  long resets_ = 0;
  int probes_ = 0;
  double removed_ = 0.0;  // N mm
};

/// The progress line of the springback, in the driver's columns (src/solver/progress.hpp) with
/// the phase in place of the stroke: the share of the release, then of max_time; KE/IE is the
/// stop rule's ratio (the kinetic-energy peak since the last reset over the reference energy).
class RelaxationProgress {
 public:
  explicit RelaxationProgress(int interval_cycles)
      : interval_cycles_(interval_cycles), last_(std::chrono::steady_clock::now()) {
    log_info("{:>9} {:>12} {:>8} {:>11} {:>9} {:>9} {:>8} {:>7}\n", "cycle", "time [s]", "phase",
             "dt [s]", "KEpk/IE", "energy", "mass+", "resets");
  }

  void report(const Model& model, const SolutionState& s, double release_fraction,
              double relax_fraction, double kinetic_ratio, long resets, bool final) {
    const auto now = std::chrono::steady_clock::now();
    const bool due = interval_cycles_ > 0
                         ? s.cycle % interval_cycles_ == 0
                         : std::chrono::duration<double>(now - last_).count() >= 2.0;
    if (!due && !final) {
      return;
    }
    last_ = now;
    const std::string phase = release_fraction < 1.0
                                  ? fmt::format("R{:>6.1f}%", 100.0 * release_fraction)
                                  : fmt::format("D{:>6.1f}%", 100.0 * relax_fraction);
    log_info("{:>9} {:>12.5e} {:>8} {:>11.3e} {:>9.2e} {:>9.1e} {:>7.2f}% {:>7}\n", s.cycle, s.time,
             phase, s.stable_dt, kinetic_ratio, s.energies.balance_error(),
             100.0 * s.scaling.added_mass / model.blank.physical_mass, resets);
  }

 private:
  int interval_cycles_;
  std::chrono::steady_clock::time_point last_;
};

// What the dynamic relaxation's observers tell each other.
struct RelaxationFlags {
  bool restart = false;       ///< the last step ended with a reset: the next starts from rest
  bool at_rest = false;       ///< the stop rule found the blank at rest
  bool reached_stop = false;  ///< max_time after the release has passed
};

// Kinetic damping after every step: a reset at a peak of the kinetic energy, the rest probe once
// the release is over.
class KineticDampingObserver final : public LoopObserver {
 public:
  KineticDampingObserver(const Model& model, KineticDamping& damping, double release_end,
                         RelaxationFlags& flags)
      : model_(model), damping_(damping), release_end_(release_end), flags_(flags) {}

  bool after_step(SolutionState& s) override {
    const bool after_release = s.time >= release_end_ * (1.0 - 1e-12);
    const KineticDamping::Outcome outcome = damping_.after_step(model_, s, after_release);
    flags_.restart = outcome != KineticDamping::Outcome::moving;
    flags_.at_rest = outcome == KineticDamping::Outcome::at_rest;
    return false;
  }

 private:
  const Model& model_;
  KineticDamping& damping_;
  double release_end_;
  RelaxationFlags& flags_;
};

// The relaxation's end: at rest, or max_time after the release; a start from rest after a reset;
// the progress line.
class RelaxationEndObserver final : public LoopObserver {
 public:
  RelaxationEndObserver(const Model& model, RelaxationProgress& progress,
                        const KineticDamping& damping, double t0, double release_time,
                        double max_time, double& dt_previous, RelaxationFlags& flags)
      : model_(model),
        progress_(progress),
        damping_(damping),
        t0_(t0),
        release_time_(release_time),
        max_time_(max_time),
        dt_previous_(dt_previous),
        flags_(flags) {}

  bool before_step(SolutionState& s) override {
    if (s.time >= t_stop() * (1.0 - 1e-12)) {
      flags_.reached_stop = true;
      return true;
    }
    if (flags_.restart) {
      // After a reset the state is a start from rest, as before a run's first step (dt 0 for
      // the whole-step velocity in compute_time_step's momentum update, a half kick next).
      s.dt = 0.0;
      dt_previous_ = 0.0;
      flags_.restart = false;
    }
    return false;
  }
  double bound_step(const SolutionState& s, double dt) override {
    return std::min(dt, t_stop() - s.time);
  }
  bool after_step(SolutionState& s) override {
    const double release_end = t0_ + release_time_;
    progress_.report(model_, s, std::min(1.0, (s.time - t0_) / release_time_),
                     std::max(0.0, (s.time - release_end) / max_time_), damping_.running_ratio(),
                     damping_.resets(), false);
    return flags_.at_rest;
  }

 private:
  double t_stop() const { return t0_ + release_time_ + max_time_; }

  const Model& model_;
  RelaxationProgress& progress_;
  const KineticDamping& damping_;
  double t0_;
  double release_time_;
  double max_time_;
  double& dt_previous_;
  RelaxationFlags& flags_;
};

}  // namespace

DynamicRelaxationResult run_dynamic_relaxation(const Model& model, SolutionState& state,
                                               FrameOutput* output,
                                               const SpringbackConfig& config) {
  SolutionState& s = state;
  if (!(config.release_time > 0.0)) {
    throw InputError(
        fmt::format("springback by dynamic relaxation: release_time must be > 0 s (got {})",
                    config.release_time));
  }
  if (!(config.kinetic_tolerance > 0.0)) {
    throw InputError(
        fmt::format("springback by dynamic relaxation: kinetic_tolerance must be > 0 (got {})",
                    config.kinetic_tolerance));
  }
  const double t0 = s.time;
  const double release_time = config.release_time;
  const double max_time = config.max_time > 0.0 ? config.max_time : 10.0 * release_time;
  const double release_end = t0 + release_time;

  DynamicRelaxationResult result;
  result.release_time = release_time;

  if (output) {
    output->set_springback_reference(s.x);
  }
  // After forming, the punch stops at the end of its stroke: the release starts from rest, as the
  // implicit route's does (the forming's velocities would carry the free blank on).
  // Without contact at the end (a relaxation under the case's own loads) nothing is released and
  // the run goes on from its present motion.
  const Matrix3X contact_force = s.f_contact;
  const bool formed = !contact_force.isZero(0.0);
  switch_contact_off(s);
  result.damping_energy += hold_tools(model, s);
  FrozenLoads frozen;
  if (formed) {
    result.damping_energy += reset_velocities(model, s);
    frozen = freeze_tool_forces(model, s, release_time, contact_force);
  }
  result.frozen_load_nodes = frozen.nodes;
  result.frozen_force = frozen.sum;
  result.contact_force = frozen.contact_sum;

  const Energies& e = s.energies;
  const double entry_internal = e.internal + e.hourglass;
  const double energy_scale = std::max(0.0, e.total());

  log_info(
      "springback by dynamic relaxation from t = {:.6e} s: the formed state's static internal "
      "forces at {} nodes (sum {:.4g} N; the contact forces' sum {:.4g} N) released over {:.4e} "
      "s, then kinetic damping until the kinetic energy peak < {:.1e} x the internal energy "
      "(max_time {:.4e} s after the release)\n",
      t0, frozen.nodes, frozen.sum.norm(), frozen.contact_sum.norm(), release_time,
      config.kinetic_tolerance, max_time);

  // Frames: release_frames evenly over the release (steps land on them), one at the end.
  const int release_frames = std::max(2, model.output.frames / 4);
  OutputSchedule schedule(t0, release_time, release_frames, model.output.history_interval);
  double last_frame_time = t0;

  RelaxationProgress progress(model.time.progress_interval);
  KineticDamping damping(config.kinetic_tolerance, entry_internal, t0, e.kinetic);
  double dt_previous = s.dt;  // the last forming step (0 from a fresh state: v(0) then)
  // The last step ended with a reset (a formed part starts at rest).
  RelaxationFlags flags{.restart = formed, .at_rest = false, .reached_stop = false};
  const long first_cycle = s.cycle;
  KineticDampingObserver damping_steps(model, damping, release_end, flags);
  FrameObserver frames(model, schedule, output, false, true, last_frame_time);
  RelaxationEndObserver ends(model, progress, damping, t0, release_time, max_time, dt_previous,
                             flags);
  LoopObserver* const observers[] = {&damping_steps, &frames, &ends};
  // Below the total energy at the start of springback the blow-up check is silent.
  const LoopChecks checks{.where = " in the springback",
                          .energy_scale = energy_scale,
                          .blowup_where = " in the springback (dynamic relaxation)",
                          .blowup_remedy = "reduce the time-step safety factor"};
  try {
    run_time_loop(model, s, dt_previous, checks, observers);
  } catch (const InstabilityError& error) {
    // As run_explicit: the history up to the stop and, when the positions are finite, one last
    // frame of the state at the stop.
    const std::string last_frame =
        output ? output->write_stop_state(model, s, last_frame_time) : std::string();
    throw InstabilityError(error.what() + last_frame);
  }
  result.at_rest = flags.at_rest;
  const bool reached_stop = flags.reached_stop;

  result.cycles = s.cycle - first_cycle;
  result.relaxation_time = std::max(0.0, s.time - release_end);
  result.reference_energy = damping.reference();
  result.final_kinetic_ratio =
      result.reference_energy > 0.0 ? damping.peak(result.at_rest) / result.reference_energy : 0.0;
  result.resets = damping.resets();
  result.rest_probes = damping.probes();
  result.damping_energy += damping.removed();
  if (output) {
    output->append_history(model, s);
    if (s.time > last_frame_time) {
      output->write_frame(model, s);
    }
    output->flush();
  }
  progress.report(model, s, 1.0, std::max(0.0, (s.time - release_end) / max_time),
                  result.final_kinetic_ratio, result.resets, true);
  if (result.at_rest) {
    log_info(
        "springback: at rest at t = {:.6e} s, {:.4e} s after the release ({} cycles, {} resets; "
        "kinetic energy peak {:.2e} x the internal energy)\n",
        s.time, result.relaxation_time, result.cycles, result.resets, result.final_kinetic_ratio);
  } else if (reached_stop) {
    const std::string why =
        result.final_kinetic_ratio >= config.kinetic_tolerance
            ? fmt::format(
                  "the kinetic energy peak is {:.2e} x the internal energy, above "
                  "kinetic_tolerance = {:.1e}",
                  result.final_kinetic_ratio, config.kinetic_tolerance)
            : fmt::format(
                  "the kinetic energy peak is {:.2e} x the internal energy, below "
                  "kinetic_tolerance = {:.1e}, but the check of rest (a free run of "
                  "{:.4e} s without resets) had not finished",
                  result.final_kinetic_ratio, config.kinetic_tolerance, damping.window());
    log_warning(
        "springback by dynamic relaxation: not at rest after max_time = {:.4e} s past the release "
        "(t = {:.6e} s, {} cycles, {} resets): {}; the shape written is not the final one. Raise "
        "[springback] max_time\n",
        max_time, s.time, result.cycles, result.resets, why);
  }
  return result;
}

}  // namespace sf
