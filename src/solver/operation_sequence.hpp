#pragma once
// The press line's operations on the one explicit time loop (docs/process-chain.md): which one
// the run is in, starting the next (the tools in or out of play, their motions' origins, the end
// it waits for) and whether the current one has ended after a step. A case without
// [[operations]] is one forming operation ending at time.end_time.
#include <string>

#include "model/model.hpp"
#include "results/results_writer.hpp"
#include "solver/solution_state.hpp"

namespace sf {

class OperationSequence {
 public:
  explicit OperationSequence(const Model& model) : model_(model) {}

  /// Operations of the run (1 for a case without [[operations]]).
  int count() const;
  /// Whether operation k is the springback (run by the implicit springback, not the loop).
  bool is_springback(int k) const;
  /// Whether operation k is a trim (run between two models, solver/explicit_driver.cpp).
  bool is_trim(int k) const;
  /// The operation's name and kind ("forming" for a case without [[operations]]).
  std::string name(int k) const;
  std::string kind(int k) const;

  /// Starts operation k at the state's time: tools out of play stand still out of contact, the
  /// others move by the rule of model/operation_plan.hpp; s.operation is set, with the end time
  /// of a stroke or time end (or the latest a force, gap or rest end may take). Throws
  /// InputError for a stroke the tool has passed already or never reaches.
  void begin(int k, SolutionState& s) const;

  /// After a restart: a case without [[operations]] ends at time.end_time, which a restart may
  /// have changed (--stroke, --end-time).
  void resume(SolutionState& s) const;

  /// s, the time the next step must not pass: the stroke or time end of the loop's last
  /// operation (the case's last, or the one before a springback or a trim) when the case lands
  /// on its end; +inf otherwise.
  double landing_time(const SolutionState& s) const;

  /// After a step: whether the current operation's end is reached (it also keeps the peak kinetic
  /// energy a rest end compares with). Throws InstabilityError when a force, gap or rest end is
  /// not reached within the operation's time.
  bool ended(SolutionState& s) const;

  /// What ended the current operation, in words, for the summary.
  std::string ended_by(const SolutionState& s) const;

 private:
  double clearance(const Operation& op, const SolutionState& s) const;
  /// -, the out-of-balance force of the blank over the applied force (collective)
  double out_of_balance_ratio(SolutionState& s) const;
  double push(const Operation& op, const SolutionState& s) const;
  void hold(std::size_t t, SolutionState& s) const;
  void bring_into_play(int k, std::size_t t, bool moved, SolutionState& s) const;

  const Model& model_;
  mutable double last_balance_ = 0.0;  ///< the last out-of-balance ratio of a rest end
};

/// 1/s, the mass-proportional damping in effect: the operation's (control.damping unless it
/// gives its own).
double damping_in_effect(const Model& model, const SolutionState& s);

}  // namespace sf
