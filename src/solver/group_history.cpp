#include "solver/group_history.hpp"

namespace sf {

GroupMeasures measure_group(const Model& model, const SolutionState& s, std::span<const int> nodes,
                            const NodalReactionFields& reactions) {
  GroupMeasures m;
  if (nodes.empty()) {
    return m;
  }
  for (int node : nodes) {
    m.displacement += s.x.col(node) - model.blank.mesh.nodes.col(node);
    m.velocity += s.v.col(node);
    m.rotation += s.rotation.col(node);
    m.reaction_force += reactions.force.col(node);
    m.reaction_moment += reactions.moment.col(node);
  }
  const double inverse_count = 1.0 / static_cast<double>(nodes.size());
  m.displacement *= inverse_count;
  m.velocity *= inverse_count;
  m.rotation *= inverse_count;
  return m;
}

std::vector<HistoryColumn> history_group_columns(const Model& model, const UnitSystem& units) {
  std::vector<HistoryColumn> columns;
  const auto add = [&columns](const std::string& stem, const std::string& unit) {
    for (const char* axis : {"_x", "_y", "_z"}) {
      columns.push_back({stem + axis, unit});
    }
  };
  for (const HistoryGroupConfig& h : model.output.history_groups) {
    if (h.displacement) {
      add(h.group + "_displacement", units.length);
    }
    if (h.velocity) {
      add(h.group + "_velocity", units.velocity());
    }
    if (h.rotation) {
      add(h.group + "_rotation", "rad");
    }
    if (h.reaction) {
      add(h.group + "_reaction_force", units.force);
      add(h.group + "_reaction_moment", units.moment());
    }
  }
  return columns;
}

std::size_t record_history_groups(const Model& model, const SolutionState& s,
                                  const NodalReactionFields& reactions, std::span<double> row) {
  std::size_t k = 0;
  const auto put = [&row, &k](const Vec3& v) {
    for (int c = 0; c < 3; ++c) {
      row[k++] = v[c];
    }
  };
  for (const HistoryGroupConfig& h : model.output.history_groups) {
    const GroupMeasures m = measure_group(model, s, model.blank.group(h.group).nodes, reactions);
    if (h.displacement) {
      put(m.displacement);
    }
    if (h.velocity) {
      put(m.velocity);
    }
    if (h.rotation) {
      put(m.rotation);
    }
    if (h.reaction) {
      put(m.reaction_force);
      put(m.reaction_moment);
    }
  }
  return k;
}

bool history_needs_reactions(const Model& model) {
  for (const HistoryGroupConfig& h : model.output.history_groups) {
    if (h.reaction) {
      return true;
    }
  }
  return false;
}

}  // namespace sf
