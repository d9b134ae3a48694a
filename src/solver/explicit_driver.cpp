#include "solver/explicit_driver.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/build_info.hpp"
#include "core/errors.hpp"
#include "core/log.hpp"
#include "element/shell_triangle_geometry.hpp"
#include "solver/case_digest.hpp"
#include "solver/checkpoint.hpp"
#include "solver/formed_part.hpp"
#include "solver/frame_observer.hpp"
#include "solver/frame_output.hpp"
#include "solver/operation_sequence.hpp"
#include "solver/output_schedule.hpp"
#include "solver/progress.hpp"
#include "solver/springback.hpp"
#include "solver/state_gather.hpp"
#include "solver/stop_request.hpp"
#include "solver/time_loop.hpp"
#include "solver/time_step_control.hpp"
#include "solver/trim.hpp"
#include "solver/trim_cut.hpp"

namespace sf {

namespace {

// A tool where its case motion puts it at time t (s).
void place_tool_by_its_motion(const RigidToolMotion& motion, double t, ToolState& tool) {
  const ToolPlacement placement = motion.placement(t);
  tool.displacement = placement.translation;
  tool.rotation = placement.rotation;
  tool.previous_rotation = placement.rotation;
  tool.angle = motion.angle(t);
  tool.travel = motion.travel(t);
  tool.speed = motion.speed(t);
}

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
        last_(std::chrono::steady_clock::now()),
        after_trim_(options.continuation != nullptr) {}

  const std::filesystem::path& file() const { return file_; }
  const std::string& digest() const { return digest_; }
  /// After a trim no checkpoint is written: the last is the one before it.
  bool after_trim() const { return after_trim_; }

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
  bool after_trim_;
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
      "checkpoint is {}{}\nContinue with: sheetform run {} --restart {} -o {} (with this run's "
      "--set, "
      "--search, --stroke or --end-time options)",
      *stop_signal_name() ? stop_signal_name() : "--stop-at-cycle", s.time, s.cycle, file,
      checkpoints.after_trim()
          ? " (written before the last trim: no checkpoint is written after a trim, a restart "
            "trims again and gives the same bits)"
          : "",
      model.case_file.string(), file, checkpoints.file().parent_path().string()));
}

// Starts the state from the case's formed part (blank.formed_part): its time, shape and
// integration-point state, and the tools of the same name where it left them; the case's other
// tools stand where their motion puts them at that time. A contact pair with a placed tool takes
// its stick forces; the distance bounds (a shortcut of the search) start afresh.
void start_from_formed_part(const Model& model, const FormedPart& part, SolutionState& s,
                            LoopMark& loop) {
  const std::vector<std::string> placed = apply_formed_part(part, model, s);
  for (std::size_t t = 0; t < s.tools.size() && model.operations.empty(); ++t) {
    if (s.tools[t].held) {
      throw InputError(fmt::format(
          "{}: tool '{}' stood still at the part's end (a trim or an operation left it out); a "
          "case without [[operations]] would keep it there: give the case [[operations]], whose "
          "first starts its motion afresh from where it stands",
          part.file, model.tools[t].name));
    }
  }
  for (std::size_t t = 0; t < s.tools.size(); ++t) {
    if (std::find(placed.begin(), placed.end(), model.tools[t].name) == placed.end()) {
      place_tool_by_its_motion(model.tools[t].motion, s.time, s.tools[t]);
    }
  }
  for (ContactState& contact : s.contacts) {
    contact.distance_bounds.resize(contact.distance_bounds.node_count());  // zero: search
  }
  loop.dt_previous = s.dt;  // the step the part's run took last
  if (!part.fields.contains("f_int")) {
    // A trimmed part: the forces (and masses, offsets) are this mesh's, made again from the
    // state. The pass at dt = 0 may move a stress by a unit in the last place (the plane-stress
    // update of a zero increment), so the part's own point state is put back after it.
    const auto shell = s.shell;
    compute_forces(model, s, 0.0);
    s.shell = shell;
  }
  log_info("Starts from {} at t = {:.6e} s, cycle {} (tools placed where it left them: {})\n",
           part.file, s.time, s.cycle,
           placed.empty() ? "none" : fmt::format("{}", fmt::join(placed, ", ")));
}

// The record of the operation starting now (its end is filled in when it ends).
OperationRecord start_record(const OperationSequence& operations, const SolutionState& s,
                             const FrameOutput* output) {
  OperationRecord r;
  r.name = operations.name(s.operation.index);
  r.kind = operations.kind(s.operation.index);
  r.start_time = s.operation.start_time;
  r.start_cycle = s.operation.start_cycle;
  // The frame of its start: the previous operation's last (after a restart inside it, the first
  // frame at or after its start among those the results kept)
  r.first_frame = !output ? -1
                  : s.cycle == s.operation.start_cycle
                      ? output->frame_count() - 1
                      : output->first_frame_at_or_after(s.operation.start_time);
  return r;
}

void log_operation_start(const Model& model, const OperationSequence& operations,
                         const SolutionState& s) {
  if (model.operations.empty()) {
    return;  // a case without [[operations]] says nothing of them
  }
  const int k = s.operation.index;
  const Operation& op = model.operations[static_cast<std::size_t>(k)];
  std::string in_play;
  for (std::size_t t = 0; t < model.tools.size(); ++t) {
    if (op.in_play[t]) {
      in_play += fmt::format("{}{}", in_play.empty() ? "" : ", ", model.tools[t].name);
    }
  }
  log_info("Operation   {}/{} '{}' ({}) starts at t = {:.6e} s, cycle {}; tools in play: {}\n",
           k + 1, operations.count(), op.name, operations.kind(k), s.time, s.cycle,
           in_play.empty() ? "none" : in_play);
}

// Writes the ended operation's record and its formed part (the state gathered already).
void record_operation(const Model& model, const RunOptions& options, const SolutionState& s,
                      FrameOutput* output, OperationRecord& r) {
  if (output) {
    r.last_frame = output->frame_count() - 1;
    output->write_operation(s.operation.index, r);
    write_formed_part(operation_formed_part_path(options.output_directory, r.name), model, s);
  }
  log_info("Operation   '{}' ended at t = {:.6e} s, cycle {} ({}), {:.1f} s of wall time\n", r.name,
           s.time, s.cycle, r.ended_by, r.wall_seconds);
}

// An operation before the last of the loop ended: a history row and a frame of its end, its
// record and formed part. Collective (the gather).
void end_operation(const Model& model, const RunOptions& options, SolutionState& s,
                   FrameOutput* output, LoopMark& loop, OperationRecord& r) {
  if (options.write_results) {
    gather_formed_part_to_root(s);  // its fields include every output field
  }
  if (output) {
    output->append_history(model, s);
    if (loop.last_frame_time != s.time) {
      output->write_frame(model, s);
      loop.last_frame_time = s.time;
    }
  }
  record_operation(model, options, s, output, r);
}

// Energy scale below which the blow-up check is silent: the blank's kinetic energy at the
// fastest tool speed, a thousandth of it (0 without moving tools).
double blowup_energy_scale(const Model& model, const SolutionState& s) {
  std::vector<const RigidToolMotion*> motions;
  for (const Tool& t : model.tools) {
    motions.push_back(&t.motion);
  }
  for (const Operation& op : model.operations) {
    for (const auto& m : op.motions) {
      if (m) {
        motions.push_back(&*m);
      }
    }
  }
  double max_speed = 0.0;
  for (const RigidToolMotion* m : motions) {
    for (int k = 0; k <= 100; ++k) {
      max_speed = std::max(max_speed, std::abs(m->speed(model.time.end_time * k / 100.0)));
    }
  }
  return 1e-3 * 0.5 * s.mass.sum() * max_speed * max_speed;
}

// The press line's operations on the loop: before each step, whether the one in progress has
// ended (then its end is written and the next one begins, or the loop ends with it); the last
// one's stroke or time end bounds the step.
class OperationObserver final : public LoopObserver {
 public:
  OperationObserver(const Model& model, const RunOptions& options,
                    const OperationSequence& operations, FrameOutput* output, LoopMark& loop,
                    std::vector<OperationRecord> records, const SolutionState& s,
                    std::string first_ended_by)
      : model_(model),
        options_(options),
        operations_(operations),
        output_(output),
        loop_(loop),
        records_(std::move(records)),
        current_(start_record(operations, s, output)),
        first_ended_by_(std::move(first_ended_by)),
        wall_start_(std::chrono::steady_clock::now()) {}

  bool before_step(SolutionState& s) override {
    while (operations_.ended(s)) {
      current_.end_time = s.time;
      current_.end_cycle = s.cycle;
      current_.ended_by = operations_.ended_by(s);
      if (!first_ended_by_.empty()) {
        current_.ended_by = std::move(first_ended_by_);  // a trim's report
        first_ended_by_.clear();
      }
      current_.wall_seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start_).count();
      const int next = s.operation.index + 1;
      if (next >= operations_.count() || operations_.is_springback(next) ||
          operations_.is_trim(next)) {
        return true;  // the loop's last operation ends after the loop (its checkpoint first)
      }
      end_operation(model_, options_, s, output_, loop_, current_);
      records_.push_back(current_);
      operations_.begin(next, s);
      log_operation_start(model_, operations_, s);
      current_ = start_record(operations_, s, output_);
      wall_start_ = std::chrono::steady_clock::now();
    }
    return false;
  }
  // Land exactly on the end time (the last operation's stroke or time end). Frames are written
  // at the first step end at or past each frame time, not by cutting the step to it: a step cut
  // short and the full one after it change the amplitude of the modes near the stability limit
  // (the contact springs, capped at w dt = 0.87), and frame after frame that pumped energy into
  // the flange's contact chatter (the U-channel's energy balance grew 2x per frame, to 1.5e-4 at
  // 10 mm). An operation before the last ends at its first whole step at or past its end, so
  // that a draw split in two operations is the same draw.
  double bound_step(const SolutionState& s, double dt) override {
    return std::min(dt, operations_.landing_time(s) - s.time);
  }
  bool after_step(SolutionState& /*s*/) override { return false; }

  std::vector<OperationRecord> take_records() { return std::move(records_); }
  const OperationRecord& current() const { return current_; }

 private:
  const Model& model_;
  const RunOptions& options_;
  const OperationSequence& operations_;
  FrameOutput* output_;
  LoopMark& loop_;
  std::vector<OperationRecord> records_;
  OperationRecord current_;
  std::string first_ended_by_;  ///< what ended the first operation, when known before it ends
  std::chrono::steady_clock::time_point wall_start_;
};

// The run's own watch on itself: the largest kinetic / internal energy ratio after the first
// tenth of the run, and a warning (once) when mass scaling has added more than 5 % of the mass.
class RunChecksObserver final : public LoopObserver {
 public:
  RunChecksObserver(const Model& model, LoopMark& loop) : model_(model), loop_(loop) {}

  bool after_step(SolutionState& s) override {
    if (s.time > 0.1 * model_.time.end_time) {
      s.peak_kinetic_ratio = std::max(s.peak_kinetic_ratio, s.energies.kinetic_ratio());
    }
    warn_about_added_mass(s);
    return false;
  }

  void warn_about_added_mass(const SolutionState& s) {
    constexpr double warn_fraction = 0.05;
    const double fraction = s.scaling.added_mass / model_.blank.physical_mass;
    if (!loop_.warned_added_mass && fraction > warn_fraction) {
      loop_.warned_added_mass = true;
      log_warning(
          "mass scaling has added {:.2f} % of the blank's mass by t = {:.6e} s, cycle {} ({} "
          "elements scaled); check that the inertia forces stay small (kinetic / internal energy) "
          "or set control.mass_scaling_max_added\n",
          100.0 * fraction, s.time, s.cycle, s.scaling.scaled_elements);
    }
  }

 private:
  const Model& model_;
  LoopMark& loop_;
};

class ProgressObserver final : public LoopObserver {
 public:
  ProgressObserver(const Model& model, Progress& progress) : model_(model), progress_(progress) {}
  bool after_step(SolutionState& s) override {
    progress_.report(model_, s, false);
    return false;
  }

 private:
  const Model& model_;
  Progress& progress_;
};

// Requests by signal (stop, checkpoint), by the checkpoint interval and by --stop-at-cycle,
// agreed by every process after each step.
class RequestObserver final : public LoopObserver {
 public:
  RequestObserver(const Model& model, const RunOptions& options, FrameOutput* output,
                  Checkpoints& checkpoints, LoopMark& loop)
      : model_(model), options_(options), output_(output), checkpoints_(checkpoints), loop_(loop) {}

  bool after_step(SolutionState& s) override {
    const int asked = s.domain->agree_flags(take_run_requests() |
                                            (checkpoints_.due(s.cycle) ? request_checkpoint : 0) |
                                            (s.cycle == options_.stop_at_cycle ? request_stop : 0));
    if (asked & request_stop) {
      stop_cleanly(model_, s, output_, checkpoints_, loop_);
    }
    if (asked & request_checkpoint) {
      checkpoints_.write(model_, s, output_, loop_);
    }
    return false;
  }

 private:
  const Model& model_;
  const RunOptions& options_;
  FrameOutput* output_;
  Checkpoints& checkpoints_;
  LoopMark& loop_;
};

// What a trim removed and left, in words.
std::string trim_report(const TrimSummary& t) {
  std::string pieces;
  if (t.piece_elements.size() > 1) {
    pieces = fmt::format("; {} pieces of {} elements", t.piece_elements.size(),
                         fmt::join(t.piece_elements, ", "));
  }
  std::string cut;
  if (t.elements_cut > 0 || t.nodes_moved > 0) {
    cut = fmt::format(
        "; {} elements cut into {} pieces, {} nodes made on the line, {} moved onto it (up to "
        "{:.3g} mm), smallest piece {:.2f} of its element",
        t.elements_cut, t.pieces_made, t.nodes_made, t.nodes_moved, t.largest_move,
        t.smallest_fraction);
  }
  return fmt::format("trimmed: {} of {} elements and {} nodes removed{}{}", t.elements_removed,
                     t.elements_before, t.nodes_removed, cut, pieces);
}

// Before any work: a trim needs the results folder (the part goes through it) and a way to
// build the model again on the trimmed mesh.
void refuse_trim_without_rebuild(const Model& model, const RunOptions& options) {
  for (const Operation& op : model.operations) {
    if (op.kind == OperationConfig::Kind::trim &&
        (!options.rebuild.model || !options.write_results)) {
      throw InputError(fmt::format(
          "{}: a trim needs a run that writes its results and can build the model again on the "
          "trimmed part (sheetform run does both)",
          op.entry));
    }
  }
}

// A trim's line as the part meets it: its polyline, or its tool's triangles where the tool
// stands.
TrimOutline trim_outline(const Model& model, const Operation& op, const SolutionState& s) {
  TrimOutline outline{.points = op.trim_line,
                      .direction = op.trim_direction,
                      .keep_inside = op.keep_inside,
                      .tool_triangles = {},
                      .offset = op.trim_offset};
  if (op.trim_tool >= 0) {
    const TriangleSurface& surface = model.tools[static_cast<std::size_t>(op.trim_tool)].surface;
    const ToolState& tool = s.tools[static_cast<std::size_t>(op.trim_tool)];
    for (int t = 0; t < surface.num_triangles(); ++t) {
      const Tri3 corners = gather_triangle(surface.nodes(), surface.triangles(), t);
      outline.tool_triangles.push_back(
          tool.rotation == Mat3::Identity()
              ? Tri3(corners.colwise() + tool.displacement)
              : Tri3((tool.rotation * corners).colwise() + tool.displacement));
    }
  }
  return outline;
}

// The run after a trim: every process reads the part as the operation before left it (the
// output process wrote it), trims it, builds the model again on the trimmed mesh, and runs it
// on from the trim, in the same results. Collective.
RunSummary go_on_after_trim(const Model& model, const RunOptions& options, const SolutionState& s,
                            const OperationSequence& operations,
                            std::vector<OperationRecord> records, const OutputMark& mark,
                            std::chrono::steady_clock::time_point wall_start,
                            SolutionState* final_state) {
  const int trim = s.operation.index + 1;
  const Operation& op = model.operations[static_cast<std::size_t>(trim)];
  s.domain->agree_flags(0);  // the part is on the disk before any process reads it
  const FormedPart part = read_formed_part(
      operation_formed_part_path(options.output_directory, operations.name(trim - 1)));
  TrimSummary summary;
  const TrimOutline outline = trim_outline(model, op, s);
  const auto trimmed = std::make_shared<const FormedPart>(
      op.trim_cut ? trim_by_cutting(part, outline, op.sliver_fraction, &summary)
                  : trim_by_removal(part, outline, &summary));
  const std::string report = trim_report(summary);
  log_info("Trim        '{}' at t = {:.6e} s: {}\n", op.name, s.time, report);
  if (op.trim_cut && summary.smallest_fraction < op.sliver_fraction) {
    log_warning(
        "{}: a piece of a cut element is {:.3f} of its element, below sliver_fraction {:g}: the "
        "node that would have moved onto the line is in a node group its edge leaves (a "
        "symmetry plane); its time step is that much smaller\n",
        op.entry, summary.smallest_fraction, op.sliver_fraction);
  }
  if (summary.piece_elements.size() > 1) {
    log_warning(
        "{}: the trimmed part falls into {} pieces; a piece that no tool or constraint holds "
        "floats free in the operations after it\n",
        op.entry, summary.piece_elements.size());
  }
  const auto rebuild_start = std::chrono::steady_clock::now();
  const Model next = options.rebuild.model(blank_mesh_of(*trimmed));
  log_info("Trim        the model built again on the trimmed mesh in {:.2f} s\n",
           std::chrono::duration<double>(std::chrono::steady_clock::now() - rebuild_start).count());
  RunOptions on = options;
  on.start_part = trimmed;
  on.restart_file.clear();
  on.checkpoints = false;  // a restart goes on from the last checkpoint before the trim
  on.domain = options.rebuild.domain ? options.rebuild.domain(next) : nullptr;
  auto continuation = std::make_shared<RunContinuation>();
  continuation->operation = trim;
  continuation->output = mark;
  continuation->records = std::move(records);
  continuation->trim_report = report;
  continuation->times = s.times;
  continuation->peak_kinetic_ratio = s.peak_kinetic_ratio;
  const RunContinuation* before = options.continuation.get();
  const double cycles = static_cast<double>(s.cycle - (before ? before->cycle : 0));
  continuation->element_cycles =
      (before ? before->element_cycles : 0.0) + cycles * element_count(model.blank.part);
  continuation->node_cycles = (before ? before->node_cycles : 0.0) +
                              cycles * static_cast<double>(model.blank.mesh.nodes.cols());
  continuation->cycle = s.cycle;
  continuation->wall_start = wall_start;
  on.continuation = continuation;
  return run_explicit(next, on, final_state);
}

}  // namespace

RunSummary run_explicit(const Model& model, const RunOptions& options, SolutionState* final_state) {
  const RunContinuation* const continuation = options.continuation.get();
  const auto wall_start =
      continuation ? continuation->wall_start : std::chrono::steady_clock::now();
  const int first_operation = continuation ? continuation->operation : 0;
  refuse_trim_without_rebuild(model, options);
  SolutionState s = make_initial_state(model);
  if (options.domain) {
    s.domain = options.domain;
  }
  const bool root = s.domain->is_root();
  for (std::size_t t = 0; t < s.tools.size(); ++t) {
    place_tool_by_its_motion(model.tools[t].motion, 0.0, s.tools[t]);
  }
  const OperationSequence operations(model);
  const bool fresh = options.restart_file.empty();
  if (fresh) {
    operations.begin(first_operation, s);  // before the first forces: a tool out of play has no
                                           // contact
  }
  compute_forces(model, s, 0.0);

  RunRequestScope requests;
  Checkpoints checkpoints(model, options);
  OutputSchedule schedule(0.0, model.time.end_time, model.output.frames,
                          model.output.history_interval);
  LoopMark loop;
  std::unique_ptr<FrameOutput> output;
  if (fresh && (options.start_part || !model.blank.formed_part.empty())) {
    start_from_formed_part(
        model, options.start_part ? *options.start_part : read_formed_part(model.blank.formed_part),
        s, loop);
    operations.begin(first_operation, s);  // it starts where the part's run ended
    if (continuation) {
      s.times = continuation->times;
      s.peak_kinetic_ratio = continuation->peak_kinetic_ratio;
    }
    schedule.after_step(s.time, s.cycle);  // the frame times the part's run passed
  }
  if (!fresh) {
    const CheckpointInfo info = resume_state(model, options, checkpoints.digest(), s);
    loop = info.loop;
    operations.resume(s);
    if (options.write_results && root) {
      output = std::make_unique<FrameOutput>(model, options.output_directory, info.output);
    }
    schedule.after_step(s.time, s.cycle);  // the frame times passed before the checkpoint
  } else if (continuation) {
    // after a trim: the results go on, with the trimmed mesh from the next frame on
    if (options.write_results && root) {
      output = std::make_unique<FrameOutput>(model, options.output_directory, continuation->output,
                                             true);
    }
    loop.last_frame_time = s.time;  // the frame of the operation before the trim
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
      loop.last_frame_time = s.time;
    }
  }
  if (fresh) {
    log_operation_start(model, operations, s);
  }

  Progress progress(model, model.time.progress_interval);
  // The operations ended before a checkpoint a restart goes on from are in results.h5.
  std::vector<OperationRecord> records_before;
  if (continuation) {
    records_before = continuation->records;
  } else if (!fresh && output && !model.operations.empty()) {
    records_before = output->read_operations(s.operation.index);
  }
  OperationObserver operation_steps(model, options, operations, output.get(), loop,
                                    std::move(records_before), s,
                                    continuation ? continuation->trim_report : std::string());
  RunChecksObserver run_checks(model, loop);
  run_checks.warn_about_added_mass(s);
  FrameObserver frames(model, schedule, output.get(), options.write_results, false,
                       loop.last_frame_time);
  ProgressObserver progress_lines(model, progress);
  RequestObserver requests_and_checkpoints(model, options, output.get(), checkpoints, loop);
  LoopObserver* const observers[] = {&operation_steps, &run_checks, &frames, &progress_lines,
                                     &requests_and_checkpoints};
  const LoopChecks checks{
      .where = "",
      .energy_scale = blowup_energy_scale(model, s),
      .blowup_where = "",
      .blowup_remedy = "reduce the time-step safety factor or the penalty scale"};
  try {
    run_time_loop(model, s, loop.dt_previous, checks, observers);
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
  std::vector<OperationRecord> records = operation_steps.take_records();
  OperationRecord current = operation_steps.current();
  // The end of the forming: a checkpoint that a restart with a longer stroke or end time goes on
  // from (before the last history row, which such a restart does not repeat).
  checkpoints.write(model, s, output.get(), loop);
  // One gather for the last history row, the summary and the formed part: the formed part's
  // fields include every field output reads (state_fields.hpp, kShown).
  gather_formed_part_to_root(s);
  if (output) {
    output->append_history(model, s);
    if (!model.operations.empty() && loop.last_frame_time != s.time) {
      output->write_frame(model, s);  // the last operation's end (a force, gap or rest end)
      loop.last_frame_time = s.time;
    }
    output->flush();
    // the blank as it stands, for the next operation
    write_formed_part(formed_part_path(options.output_directory), model, s);
  }
  if (!model.operations.empty()) {
    record_operation(model, options, s, output.get(), current);
    records.push_back(current);
  }
  if (const int next = s.operation.index + 1;
      next < operations.count() && operations.is_trim(next)) {
    const OutputMark mark = output ? output->mark() : OutputMark{};
    output.reset();  // results.h5 closed: the next model's output takes it up
    return go_on_after_trim(model, options, s, operations, std::move(records), mark, wall_start,
                            final_state);
  }
  progress.report(model, s, true);
  const double wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  RunSummary summary = make_run_summary(model, s, wall_seconds);
  if (continuation) {
    const double cycles = static_cast<double>(s.cycle - continuation->cycle);
    set_per_unit_costs(
        summary, s.times, continuation->element_cycles + cycles * element_count(model.blank.part),
        continuation->node_cycles + cycles * static_cast<double>(model.blank.mesh.nodes.cols()));
  }
  summary.operations = records;
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
  // on the output process alone in a distributed run (implicit or by dynamic relaxation): it has
  // the whole state, gathered above, and computes it as a serial run.
  if (model.springback && s.domain->processes() > 1) {
    if (!root) {
      return summary;
    }
    s.domain = std::make_shared<SerialDomain>();
  }
  if (model.springback) {
    restore_default_signal_actions();
    const bool as_operation = !model.operations.empty();
    OperationRecord springback_record;
    const auto springback_start = std::chrono::steady_clock::now();
    if (as_operation) {
      operations.begin(operations.count() - 1, s);
      log_operation_start(model, operations, s);
      springback_record = start_record(operations, s, output.get());
    }
    summary.springback = run_springback(model, s, output.get());
    if (output) {
      output->flush();
    }
    if (as_operation) {
      springback_record.end_time = s.time;
      springback_record.end_cycle = s.cycle;
      springback_record.ended_by = operations.ended_by(s);
      springback_record.wall_seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - springback_start)
              .count();
      if (output) {
        springback_record.last_frame = output->frame_count() - 1;
        output->write_operation(s.operation.index, springback_record);
        // the part as it sprang back (the output process has the whole state here)
        write_formed_part(
            operation_formed_part_path(options.output_directory, springback_record.name), model, s);
      }
      summary.operations.push_back(springback_record);
    }
  }
  if (final_state) {
    *final_state = std::move(s);
  }
  return summary;
}

}  // namespace sf
