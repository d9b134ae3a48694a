#include "solver/explicit_driver.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/build_info.hpp"
#include "core/errors.hpp"
#include "core/log.hpp"
#include "solver/case_digest.hpp"
#include "solver/checkpoint.hpp"
#include "solver/formed_part.hpp"
#include "solver/frame_output.hpp"
#include "solver/output_schedule.hpp"
#include "solver/progress.hpp"
#include "solver/springback.hpp"
#include "solver/state_gather.hpp"
#include "solver/stop_request.hpp"
#include "solver/time_step_control.hpp"

namespace sf {

namespace {

// Installs the SIGINT, SIGTERM and SIGUSR1 handlers for the time loop and puts back the default
// actions after it: a Ctrl-C during springback ends the process as before (the checkpoint at the
// end of the forming lets a restart do the springback again).
class RunRequestScope {
 public:
  // The command installs them before it meshes the case (a request met then stops the run at
  // the end of its first cycle); installing them again is harmless.
  RunRequestScope() { install_run_request_handlers(); }
  ~RunRequestScope() { restore_default_signal_actions(); }
  RunRequestScope(const RunRequestScope&) = delete;
  RunRequestScope& operator=(const RunRequestScope&) = delete;
};

// The checkpoints of one run: when they are due and writing them (collective).
class Checkpoints {
 public:
  Checkpoints(const Model& model, const RunOptions& options)
      : enabled_(options.checkpoints && options.write_results),
        file_(checkpoint_path(options.output_directory)),
        digest_(case_digest(model)),
        cycles_(model.output.checkpoint_cycles),
        seconds_(60.0 * model.output.checkpoint_minutes),
        last_(std::chrono::steady_clock::now()) {}

  const std::filesystem::path& file() const { return file_; }
  const std::string& digest() const { return digest_; }

  // Whether the case's interval asks for one after this cycle (this process's clock).
  bool due(long cycle) const {
    if (!enabled_) {
      return false;
    }
    const double since =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - last_).count();
    return (cycles_ > 0 && cycle % cycles_ == 0) || (seconds_ > 0.0 && since >= seconds_);
  }

  // Every process calls it; the output process writes the file.
  void write(const Model& model, SolutionState& s, FrameOutput* output, const LoopMark& loop) {
    if (!enabled_) {
      return;
    }
    const PhaseTimer timer(s.times.output);
    gather_checkpoint_state_to_root(s);
    if (output) {
      const CheckpointInfo info{digest_, build_info::git_hash, model.time.end_time, loop,
                                output->mark()};
      write_checkpoint(file_, s, info);
      log_info("Checkpoint  t = {:.6e} s, cycle {}: {}\n", s.time, s.cycle, file_.string());
    }
    last_ = std::chrono::steady_clock::now();
  }

 private:
  bool enabled_;
  std::filesystem::path file_;
  std::string digest_;
  int cycles_;
  double seconds_;
  std::chrono::steady_clock::time_point last_;
};

// Reads the checkpoint into the state (every process reads the file) after checking that it
// belongs to this case.
CheckpointInfo resume_state(const Model& model, const RunOptions& options,
                            const std::string& digest, SolutionState& s) {
  const std::string file = options.restart_file.string();
  CheckpointInfo info = read_checkpoint(options.restart_file, s);
  if (info.case_digest != digest) {
    throw InputError(fmt::format(
        "{}: the case changed since this checkpoint was written (its physics digest {} against "
        "the case's {}); a restart may change only control.end_time or control.stroke, the "
        "output and checkpoint intervals and the results folder; run a changed case from the "
        "start",
        file, info.case_digest, digest));
  }
  if (info.git_hash != build_info::git_hash) {
    log_warning(
        "{} was written by build {}, this is build {}: the run goes on, but its bits may differ "
        "from those of an uninterrupted run\n",
        file, info.git_hash, build_info::git_hash);
  }
  if (s.time >= model.time.end_time * (1.0 - 1e-12)) {
    log_warning(
        "{}: the checkpoint is at t = {:.6e} s, at or past the end time {:.6e} s: "
        "nothing is left to run (give a longer --stroke or --end-time to go on)\n",
        file, s.time, model.time.end_time);
  }
  log_info("Restarted   from {} at t = {:.6e} s, cycle {}\n", file, s.time, s.cycle);
  return info;
}

// Stops the run on a SIGINT or SIGTERM at the end of a cycle: the checkpoint first (so that a
// restart drops the extra frame below and gives the uninterrupted run's results), then a frame
// and a history row of the state at the stop for the user to look at.
[[noreturn]] void stop_cleanly(const Model& model, SolutionState& s, FrameOutput* output,
                               Checkpoints& checkpoints, const LoopMark& loop) {
  checkpoints.write(model, s, output, loop);  // gathers the state
  if (output) {
    output->write_stop_state(model, s, loop.last_frame_time);
  }
  const std::string file = checkpoints.file().string();
  throw RunStopped(fmt::format(
      "Stopped by {} at t = {:.6e} s, cycle {}: the last frame is the state at the stop, and the "
      "checkpoint is {}\nContinue with: sheetform run {} --restart {} -o {} (with this run's "
      "--set, "
      "--search, --stroke or --end-time options)",
      *stop_signal_name() ? stop_signal_name() : "--stop-at-cycle", s.time, s.cycle, file,
      model.case_file.string(), file, checkpoints.file().parent_path().string()));
}

// Starts the state from the case's formed part (blank.formed_part): its time, shape and
// integration-point state, and the tools of the same name where it left them; the case's other
// tools stand where their motion puts them at that time. A contact pair with a placed tool takes
// its stick forces; the distance bounds (a shortcut of the search) start afresh.
void start_from_formed_part(const Model& model, SolutionState& s, LoopMark& loop) {
  const FormedPart part = read_formed_part(model.blank.formed_part);
  const std::vector<std::string> placed = apply_formed_part(part, model, s);
  for (std::size_t t = 0; t < s.tools.size(); ++t) {
    if (std::find(placed.begin(), placed.end(), model.tools[t].name) == placed.end()) {
      s.tools[t].displacement = model.tools[t].motion.displacement(s.time);
      s.tools[t].travel = model.tools[t].motion.travel(s.time);
      s.tools[t].speed = model.tools[t].motion.speed(s.time);
    }
  }
  for (ContactState& contact : s.contacts) {
    contact.distance_bounds.resize(contact.distance_bounds.node_count());  // zero: search
  }
  loop.dt_previous = s.dt;  // the step the part's run took last
  log_info("Starts from {} at t = {:.6e} s, cycle {} (tools placed where it left them: {})\n",
           part.file, s.time, s.cycle,
           placed.empty() ? "none" : fmt::format("{}", fmt::join(placed, ", ")));
}

}  // namespace

RunSummary run_explicit(const Model& model, const RunOptions& options, SolutionState* final_state) {
  const auto wall_start = std::chrono::steady_clock::now();
  SolutionState s = make_initial_state(model);
  if (options.domain) {
    s.domain = options.domain;
  }
  const bool root = s.domain->is_root();
  for (std::size_t t = 0; t < s.tools.size(); ++t) {
    s.tools[t].displacement = model.tools[t].motion.displacement(0.0);
    s.tools[t].travel = model.tools[t].motion.travel(0.0);
    s.tools[t].speed = model.tools[t].motion.speed(0.0);
  }
  compute_forces(model, s, 0.0);

  RunRequestScope requests;
  Checkpoints checkpoints(model, options);
  OutputSchedule schedule(0.0, model.time.end_time, model.output.frames,
                          model.output.history_interval);
  LoopMark loop;
  std::unique_ptr<FrameOutput> output;
  if (options.restart_file.empty() && !model.blank.formed_part.empty()) {
    start_from_formed_part(model, s, loop);
    schedule.after_step(s.time, s.cycle);  // the frame times the part's run passed
  }
  if (!options.restart_file.empty()) {
    const CheckpointInfo info = resume_state(model, options, checkpoints.digest(), s);
    loop = info.loop;
    if (options.write_results && root) {
      output = std::make_unique<FrameOutput>(model, options.output_directory, info.output);
    }
    schedule.after_step(s.time, s.cycle);  // the frame times passed before the checkpoint
  } else {
    if (options.write_results && root) {
      output = std::make_unique<FrameOutput>(model, options.output_directory);
    }
    if (options.write_results) {
      gather_state_to_root(s);
    }
    if (output) {
      output->write_frame(model, s);
      output->append_history(model, s);
    }
  }

  // Energy scale below which the blow-up check is silent: the blank's kinetic energy at the
  // fastest tool speed, a thousandth of it (0 without moving tools).
  double max_speed = 0.0;
  for (const Tool& t : model.tools) {
    for (int k = 0; k <= 100; ++k) {
      max_speed = std::max(max_speed, std::abs(t.motion.speed(model.time.end_time * k / 100.0)));
    }
  }
  const double energy_scale = 1e-3 * 0.5 * s.mass.sum() * max_speed * max_speed;

  const double initial_dt = model.time.time_step;
  Progress progress(model, model.time.progress_interval);
  // Added mass above this share of the physical mass is worth a warning (once).
  constexpr double warn_fraction = 0.05;
  auto warn_about_added_mass = [&]() {
    const double fraction = s.scaling.added_mass / model.blank.physical_mass;
    if (!loop.warned_added_mass && fraction > warn_fraction) {
      loop.warned_added_mass = true;
      log_warning(
          "mass scaling has added {:.2f} % of the blank's mass by t = {:.6e} s, cycle {} ({} "
          "elements scaled); check that the inertia forces stay small (kinetic / internal energy) "
          "or set control.mass_scaling_max_added\n",
          100.0 * fraction, s.time, s.cycle, s.scaling.scaled_elements);
    }
  };
  warn_about_added_mass();

  try {
    while (s.time < model.time.end_time * (1.0 - 1e-12)) {
      double dt = compute_time_step(model, s);
      if (dt < 1e-3 * initial_dt) {
        throw InstabilityError(fmt::format(
            "time step collapsed to {:.3e} s (from {:.3e} s) at t = {:.6e} s, cycle {}: an "
            "element is being crushed",
            dt, initial_dt, s.time, s.cycle));
      }
      // Land exactly on the end time. Frames are written at the first step end at or past each
      // frame time, not by cutting the step to it: a step cut short and the full one after it
      // change the amplitude of the modes near the stability limit (the contact springs, capped
      // at w dt = 0.87), and frame after frame that pumped energy into the flange's contact
      // chatter (the U-channel's energy balance grew 2x per frame, to 1.5e-4 at 10 mm).
      if (model.time.land_on_end) {
        dt = std::min(dt, model.time.end_time - s.time);
      }
      check_step_advances(s, dt, "");
      advance_one_step(model, s, dt, loop.dt_previous);
      loop.dt_previous = dt;
      if (s.time > 0.1 * model.time.end_time) {
        s.peak_kinetic_ratio = std::max(s.peak_kinetic_ratio, s.energies.kinetic_ratio());
      }
      check_energy_blowup(model, s, energy_scale, "",
                          "reduce the time-step safety factor or the penalty scale");
      warn_about_added_mass();

      // A history row every history_interval cycles and at every frame (the frame's added mass,
      // time step, energies).
      const PhaseTimer output_timer(s.times.output);
      const OutputSchedule::Due due = schedule.after_step(s.time, s.cycle);
      if (options.write_results && (due.history || due.frame)) {
        gather_state_to_root(s);  // every process: the schedule is the same on all
      }
      if (output && due.history) {
        output->append_history(model, s);
      }
      if (output && due.frame) {
        output->write_frame(model, s);
        loop.last_frame_time = s.time;
      }
      progress.report(model, s, false);
      // Requests by signal or by the checkpoint interval, agreed by every process.
      const int asked = s.domain->agree_flags(
          take_run_requests() | (checkpoints.due(s.cycle) ? request_checkpoint : 0) |
          (s.cycle == options.stop_at_cycle ? request_stop : 0));
      if (asked & request_stop) {
        stop_cleanly(model, s, output.get(), checkpoints, loop);
      }
      if (asked & request_checkpoint) {
        checkpoints.write(model, s, output.get(), loop);
      }
    }
  } catch (const InstabilityError& error) {
    // Keep what a user needs to see the failure: the history up to the stop and, when the nodes
    // still have finite positions, one last frame of the state at the stop (for a NaN, the state
    // of the last completed cycle; for an inverted element or an energy blow-up, the offending
    // configuration). The frames written before stay as they are. Every process stops here
    // together (the failures are agreed), so the state can be gathered.
    if (options.write_results) {
      gather_state_to_root(s);
    }
    const std::string last_frame =
        output ? output->write_stop_state(model, s, loop.last_frame_time) : std::string();
    throw InstabilityError(error.what() + last_frame);
  }
  // The end of the forming: a checkpoint that a restart with a longer stroke or end time goes on
  // from (before the last history row, which such a restart does not repeat).
  checkpoints.write(model, s, output.get(), loop);
  // One gather for the last history row, the summary and the formed part: the formed part's
  // fields include every field output reads (state_fields.hpp, kShown).
  gather_formed_part_to_root(s);
  if (output) {
    output->append_history(model, s);
    output->flush();
    // the blank as it stands, for the next operation
    write_formed_part(formed_part_path(options.output_directory), model, s);
  }
  progress.report(model, s, true);
  const double wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  RunSummary summary = make_run_summary(model, s, wall_seconds);
  summary.ranks = s.domain->processes();
  const PhaseTimes& t = s.times;
  const double mine[6] = {t.elements, t.contact, t.time_step,
                          t.nodal,    t.output,  s.domain->communication_seconds()};
  const std::vector<double> per_rank = s.domain->gather_values(mine);
  for (std::size_t r = 0; r + 6 <= per_rank.size(); r += 6) {
    std::array<double, 6> row;
    std::copy_n(per_rank.begin() + static_cast<std::ptrdiff_t>(r), 6, row.begin());
    summary.phase_seconds_per_rank.push_back(row);
  }
  if (output) {
    for (const SearchAuditRecord& a : output->search_audits().records()) {
      summary.search_audits.push_back({a.tool, a.search, a.audits, a.last.misses,
                                       a.last.nodes_checked, a.max_misses, a.max_misses_time,
                                       a.total_misses, a.max_gap_error});
    }
  }
  // The forming summary above is the state with the tools in place; springback goes on from it,
  // on the output process alone in a distributed run (the drivers allow only the implicit
  // springback there): it has the whole state, and computes it as a serial run.
  if (model.springback && s.domain->processes() > 1) {
    if (!root) {
      return summary;
    }
    s.domain = std::make_shared<SerialDomain>();
  }
  if (model.springback) {
    restore_default_signal_actions();
    summary.springback = run_springback(model, s, output.get());
    if (output) {
      output->flush();
    }
  }
  if (final_state) {
    *final_state = std::move(s);
  }
  return summary;
}

}  // namespace sf
