#pragma once
// Runs the search audit (src/contact/search_audit.hpp) of every contact pair that asks for it
// (`audit = true`) on the current state, keeps the per-node results for the results frames and
// the counts over the run for the history and the summary.
#include <string>
#include <vector>

#include "contact/search_audit.hpp"
#include "model/model.hpp"
#include "solver/solution_state.hpp"

namespace sf {

/// The audit of one contact pair over a run.
struct SearchAuditRecord {
  int contact = -1;    ///< index into Model::contacts
  std::string tool;    ///< the tool's name
  std::string search;  ///< the audited search
  VectorX miss;       ///< per blank node, 1 where the search's triangle is not an exact closest one
  VectorX gap_error;  ///< per blank node, mm: the search's signed distance - the exact one
  SearchAuditCount last;       ///< the latest audit
  int audits = 0;              ///< audits run (frames and history rows)
  int max_misses = 0;          ///< most misses in one audit
  double max_misses_time = 0;  ///< s, when
  long total_misses = 0;       ///< summed over the audits
  double max_gap_error = 0;    ///< mm, largest |gap error| of the run
};

class SearchAuditRecorder {
 public:
  /// One record per contact pair with audit = true (none: empty()).
  explicit SearchAuditRecorder(const Model& model);
  bool empty() const { return records_.empty(); }
  /// Audits the state (once per cycle: a second call in the same cycle does nothing).
  void record(const Model& model, const SolutionState& state);
  const std::vector<SearchAuditRecord>& records() const { return records_; }
  /// The cycle of the last audit (-1: none yet).
  long last_cycle() const { return last_cycle_; }
  /// A restart: the counts over the run so far (audits, misses, their maxima) and the cycle of
  /// the last audit, from a checkpoint; the per-node fields are those of the next audit.
  void restore(const std::vector<SearchAuditRecord>& counts, long last_cycle);

 private:
  std::vector<SearchAudit> audits_;
  std::vector<SearchAuditRecord> records_;
  long last_cycle_ = -1;
};

}  // namespace sf
