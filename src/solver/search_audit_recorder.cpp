#include "solver/search_audit_recorder.hpp"

#include <algorithm>

namespace sf {

SearchAuditRecorder::SearchAuditRecorder(const Model& model) {
  for (std::size_t c = 0; c < model.contacts.size(); ++c) {
    if (!model.contacts[c].audit) {
      continue;
    }
    const ContactInterface& contact = model.contacts[c];
    audits_.emplace_back(*contact.pair.surface);
    SearchAuditRecord record;
    record.contact = static_cast<int>(c);
    record.tool = model.tools[static_cast<std::size_t>(contact.tool)].name;
    record.search = std::string(contact.pair.search->name());
    record.miss = VectorX::Zero(model.blank.mesh.nodes.cols());
    record.gap_error = VectorX::Zero(model.blank.mesh.nodes.cols());
    records_.push_back(std::move(record));
  }
}

void SearchAuditRecorder::record(const Model& model, const SolutionState& s) {
  if (records_.empty() || s.cycle == last_cycle_ || s.contact_off) {  // nothing to audit
    return;
  }
  last_cycle_ = s.cycle;
  for (std::size_t a = 0; a < records_.size(); ++a) {
    SearchAuditRecord& r = records_[a];
    const ContactInterface& contact = model.contacts[static_cast<std::size_t>(r.contact)];
    const ToolState& tool = s.tools[static_cast<std::size_t>(contact.tool)];
    r.last = audits_[a].run(*contact.pair.search, s.x, {tool.rotation, tool.displacement},
                            contact.pair.cutoff, r.miss, r.gap_error);
    ++r.audits;
    r.total_misses += r.last.misses;
    if (r.last.misses > r.max_misses) {
      r.max_misses = r.last.misses;
      r.max_misses_time = s.time;
    }
    r.max_gap_error = std::max(r.max_gap_error, r.last.max_gap_error);
  }
}

void SearchAuditRecorder::restore(const std::vector<SearchAuditRecord>& counts, long last_cycle) {
  for (std::size_t a = 0; a < records_.size() && a < counts.size(); ++a) {
    SearchAuditRecord& r = records_[a];
    const SearchAuditRecord& c = counts[a];
    r.last = c.last;
    r.audits = c.audits;
    r.max_misses = c.max_misses;
    r.max_misses_time = c.max_misses_time;
    r.total_misses = c.total_misses;
    r.max_gap_error = c.max_gap_error;
  }
  last_cycle_ = last_cycle;
}

}  // namespace sf
