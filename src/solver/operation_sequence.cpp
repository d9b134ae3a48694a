#include "solver/operation_sequence.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "casefile/case_config_operations.hpp"
#include "core/errors.hpp"
#include "core/exact_sum.hpp"
#include "model/operation_plan.hpp"

namespace sf {
namespace {

using End = OperationConfig::End;
using Kind = OperationConfig::Kind;

// The contact pairs and drawbeads of tool t start afresh: no stick forces, and a full search
// first.
void reset_pairs_of(const Model& model, std::size_t t, SolutionState& s) {
  for (std::size_t c = 0; c < model.contacts.size() && c < s.contacts.size(); ++c) {
    if (static_cast<std::size_t>(model.contacts[c].tool) == t) {
      s.contacts[c].stick_force.setZero();
      s.contacts[c].distance_bounds.resize(s.contacts[c].distance_bounds.node_count());
    }
  }
  for (std::size_t b = 0; b < model.drawbeads.size() && b < s.drawbeads.size(); ++b) {
    if (static_cast<std::size_t>(model.drawbeads[b].tool) == t) {
      s.drawbeads[b].restraint.setZero();
    }
  }
}

}  // namespace

int OperationSequence::count() const {
  return model_.operations.empty() ? 1 : static_cast<int>(model_.operations.size());
}

bool OperationSequence::is_springback(int k) const {
  return !model_.operations.empty() &&
         model_.operations[static_cast<std::size_t>(k)].kind == Kind::springback;
}

bool OperationSequence::is_trim(int k) const {
  return !model_.operations.empty() &&
         model_.operations[static_cast<std::size_t>(k)].kind == Kind::trim;
}

std::string OperationSequence::name(int k) const {
  return model_.operations.empty() ? "forming"
                                   : model_.operations[static_cast<std::size_t>(k)].name;
}

std::string OperationSequence::kind(int k) const {
  return model_.operations.empty() ? "forming"
                                   : std::string(operation_kind_name(
                                         model_.operations[static_cast<std::size_t>(k)].kind));
}

void OperationSequence::hold(std::size_t t, SolutionState& s) const {
  ToolState& tool = s.tools[t];
  if (tool.held) {
    return;
  }
  if (const auto& driven = model_.tools[t].force_control) {
    // Its kinetic energy goes with its velocity, as the springback's hold counts it.
    const double removed = 0.5 * driven->mass() * tool.speed * tool.speed;
    s.energies.kinetic -= removed;
    s.energies.damping += removed;
  }
  tool.held = true;
  tool.speed = 0.0;
  tool.velocity = 0.0;
  reset_pairs_of(model_, t, s);
}

void OperationSequence::bring_into_play(int k, std::size_t t, bool moved, SolutionState& s) const {
  ToolState& tool = s.tools[t];
  if (!model_.tools[t].force_control) {
    tool.origin = origin_at_start(model_, k, static_cast<int>(t), tool.origin, moved, s.time,
                                  {tool.travel, {tool.rotation, tool.displacement}, tool.angle});
  }
  if (tool.held) {
    reset_pairs_of(model_, t, s);
  }
  tool.held = false;
}

void OperationSequence::begin(int k, SolutionState& s) const {
  s.operation = OperationState{k, s.time, s.cycle, model_.time.end_time, 0.0};
  if (model_.operations.empty()) {
    return;
  }
  const Operation& op = model_.operations[static_cast<std::size_t>(k)];
  for (std::size_t t = 0; t < s.tools.size(); ++t) {
    if (!op.in_play[t]) {
      hold(t, s);
    } else if (k > 0 || op.motions[t] || s.tools[t].held) {
      // (held at the first operation: a formed part's run left it standing, after a trim or
      // out of play; it starts its motion afresh from there, as in one case)
      bring_into_play(k, t, !s.tools[t].held, s);
    }
  }
  if (op.end == End::stroke) {
    const ToolState& tool = s.tools[static_cast<std::size_t>(op.tool)];
    s.operation.end_time = checked_stroke_end(model_, op, tool.origin, s.time, tool.travel);
  } else {
    s.operation.end_time = s.time + op.time;
  }
}

void OperationSequence::resume(SolutionState& s) const {
  if (model_.operations.empty()) {
    s.operation.end_time = model_.time.end_time;
  }
}

double OperationSequence::landing_time(const SolutionState& s) const {
  if (!model_.time.land_on_end) {
    return std::numeric_limits<double>::infinity();
  }
  const int k = s.operation.index;
  // the loop's last operation: the case's, or the one before a springback or a trim
  const bool last = k + 1 == count() || is_springback(k + 1) || is_trim(k + 1);
  const bool planned = model_.operations.empty() ||
                       model_.operations[static_cast<std::size_t>(k)].end == End::stroke ||
                       model_.operations[static_cast<std::size_t>(k)].end == End::time;
  return last && planned ? s.operation.end_time : std::numeric_limits<double>::infinity();
}

double OperationSequence::push(const Operation& op, const SolutionState& s) const {
  const auto t = static_cast<std::size_t>(op.tool);
  return -s.tools[t].force.dot(model_.tools[t].direction());
}

double OperationSequence::out_of_balance_ratio(SolutionState& s) const {
  // |f_ext + f_contact - f_int| over |f_ext| (2-norms over the blank's free components), summed
  // exactly over the nodes this process owns and then over every process.
  std::array<ExactSum, 2> sums;
  const std::span<const int> owned = s.domain->owned_nodes();
  const Eigen::Index n = owned.empty() ? s.x.cols() : static_cast<Eigen::Index>(owned.size());
  const NodalConstraints& constraints = model_.constraints;
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index i = owned.empty() ? k : owned[static_cast<std::size_t>(k)];
    Vec3 residual = s.f_ext.col(i) + s.f_contact.col(i) - s.f_int.col(i);
    Vec3 applied = s.f_ext.col(i);
    Vec3 no_moment = Vec3::Zero();
    const unsigned held = constraints.constrained_bits(static_cast<std::size_t>(i));
    if (held != 0) {
      constraints.zero_components(static_cast<int>(i), held, residual, no_moment);
      constraints.zero_components(static_cast<int>(i), held, applied, no_moment);
    }
    sums[0].add(residual.squaredNorm());
    sums[1].add(applied.squaredNorm());
  }
  s.domain->reduce(sums);
  const double applied = sums[1].round();
  return applied > 0.0 ? std::sqrt(sums[0].round() / applied) : 0.0;
}

double OperationSequence::clearance(const Operation& op, const SolutionState& s) const {
  const auto t = static_cast<std::size_t>(op.tool);
  const Vec3 relative =
      s.tools[t].displacement - s.tools[static_cast<std::size_t>(op.gap_to)].displacement;
  return op.reference_clearance - relative.dot(model_.tools[t].direction());
}

bool OperationSequence::ended(SolutionState& s) const {
  s.operation.peak_kinetic = std::max(s.operation.peak_kinetic, s.energies.kinetic);
  const bool past_end = s.time >= s.operation.end_time * (1.0 - 1e-12);
  if (model_.operations.empty()) {
    return past_end;
  }
  const Operation& op = model_.operations[static_cast<std::size_t>(s.operation.index)];
  bool met = false;
  switch (op.end) {
    case End::stroke:
    case End::time:
      return past_end;
    case End::force:
      met = push(op, s) >= op.force;
      break;
    case End::gap:
      met = clearance(op, s) <= op.gap;
      break;
    case End::rest:
      // The kinetic energy passes through zero twice in every swing of a vibration, so the
      // forces must balance too: an energy ratio `rest` goes with a force ratio sqrt(rest).
      last_balance_ = out_of_balance_ratio(s);
      met = s.operation.peak_kinetic > 0.0 &&
            s.energies.kinetic <= op.rest * s.operation.peak_kinetic &&
            last_balance_ <= std::sqrt(op.rest);
      break;
    case End::none:
      return true;
  }
  if (!met && past_end) {
    throw InstabilityError(fmt::format(
        "{} did not end within its time = {:g} s (t = {:.6e} s, cycle {}): {}; give it a longer "
        "time, or check its tools' motions",
        op.entry, op.time, s.time, s.cycle, ended_by(s)));
  }
  return met;
}

std::string OperationSequence::ended_by(const SolutionState& s) const {
  if (model_.operations.empty()) {
    return fmt::format("the end time {:.6g} s", model_.time.end_time);
  }
  const Operation& op = model_.operations[static_cast<std::size_t>(s.operation.index)];
  const auto tool_name = [&](int t) { return model_.tools[static_cast<std::size_t>(t)].name; };
  switch (op.end) {
    case End::stroke:
      return fmt::format("stroke {:g} mm of '{}'", op.stroke, tool_name(op.tool));
    case End::time:
      return fmt::format("time {:g} s", op.time);
    case End::force:
      return fmt::format("push on '{}' {:.6g} N (end at {:g} N)", tool_name(op.tool), push(op, s),
                         op.force);
    case End::gap:
      return fmt::format("gap from '{}' to '{}' {:.6g} mm (end at {:g} mm)", tool_name(op.tool),
                         tool_name(op.gap_to), clearance(op, s), op.gap);
    case End::rest:
      return fmt::format(
          "kinetic energy {:.3e} N mm, {:.3e} of its peak {:.3e} (end at {:g}); out-of-balance "
          "force {:.3e} of the applied (end at {:.3g})",
          s.energies.kinetic,
          s.operation.peak_kinetic > 0.0 ? s.energies.kinetic / s.operation.peak_kinetic : 0.0,
          s.operation.peak_kinetic, op.rest, last_balance_, std::sqrt(op.rest));
    case End::none:
      break;
  }
  return op.kind == Kind::trim ? "trimmed" : "springback converged";
}

double damping_in_effect(const Model& model, const SolutionState& s) {
  if (model.operations.empty()) {
    return model.loads.damping;
  }
  return model.operations[static_cast<std::size_t>(s.operation.index)].damping;
}

}  // namespace sf
