#pragma once
// The history of the case's [[history]] node groups: at each history row the mean displacement,
// velocity and rotation of a group's nodes and the sum of their reactions (docs/results-format.md,
// docs/case-file.md).
#include <span>
#include <string>
#include <vector>

#include "casefile/unit_system.hpp"
#include "model/model.hpp"
#include "solver/solution_state.hpp"

namespace sf {

/// A history column: its name and its unit ("-" for a pure number).
struct HistoryColumn {
  std::string name;
  std::string unit;
};

/// One node group at one state.
struct GroupMeasures {
  Vec3 displacement = Vec3::Zero();     ///< mm, mean over the nodes
  Vec3 velocity = Vec3::Zero();         ///< mm/s, mean (the half-step velocity, as in the frames)
  Vec3 rotation = Vec3::Zero();         ///< rad, mean of the summed rotation increments
  Vec3 reaction_force = Vec3::Zero();   ///< N, summed over the nodes
  Vec3 reaction_moment = Vec3::Zero();  ///< N mm, the nodal reaction moments summed
};

/// The nodal reactions (N, N mm per node: compute_reactions) a group's sums are taken from.
struct NodalReactionFields {
  const Matrix3X& force;
  const Matrix3X& moment;
};

/// Measures `nodes` at the state s.
GroupMeasures measure_group(const Model& model, const SolutionState& s, std::span<const int> nodes,
                            const NodalReactionFields& reactions);

/// The columns of the case's [[history]] groups, group after group, each quantity asked for as
/// x, y, z: <group>_displacement_x (length), <group>_velocity_x (velocity), <group>_rotation_x
/// (rad), <group>_reaction_force_x (force) and <group>_reaction_moment_x (force x length).
std::vector<HistoryColumn> history_group_columns(const Model& model, const UnitSystem& units);

/// Writes the values of history_group_columns at the state s into `row`, from its start; returns
/// how many it wrote. No allocation.
std::size_t record_history_groups(const Model& model, const SolutionState& s,
                                  const NodalReactionFields& reactions, std::span<double> row);

/// Whether any [[history]] group asks for reactions (then the nodal reactions are needed).
bool history_needs_reactions(const Model& model);

}  // namespace sf
