#pragma once
// What a finished run reports: printed at the end and written as summary.json beside the results,
// for users and for the regression suite.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "implicit/static_step.hpp"
#include "model/model.hpp"
#include "results/results_writer.hpp"
#include "solver/group_history.hpp"
#include "solver/reactions.hpp"
#include "solver/solution_state.hpp"
#include "solver/springback.hpp"

namespace sf {

struct DrawInResult {
  std::string name;
  double computed = 0.0;         ///< mm
  double measured = -1.0;        ///< mm, < 0 when none was given
  double measured_stroke = 0.0;  ///< mm of stroke of the measured value; 0 = at the end
  double end_stroke = 0.0;       ///< mm, the stroke tool's travel at the end of the run
  /// The measured value applies to this run's end (no measured_stroke, or the run ended there).
  bool comparable = false;
  std::string source;
};

struct ToolSummary {
  std::string name;
  double travel = 0.0;       ///< mm, at the end
  double speed = 0.0;        ///< mm/s along the direction, at the end
  double final_force = 0.0;  ///< N, pushing force along the motion at the end
  double peak_force = 0.0;   ///< N
  bool force_controlled = false;
  double applied_force = 0.0;  ///< N, force-controlled tools: the applied force at the end
  bool turns = false;          ///< its motion (or an operation's) turns it
  double angle = 0.0;          ///< degrees, a turning tool's turn at the end
  double torque = 0.0;         ///< N mm, a turning tool's press torque at the end (press_torque)
};

/// The search audit of one contact pair (audit = true), over the run.
struct SearchAuditSummary {
  std::string tool;
  std::string search;
  int audits = 0;                ///< frames and history rows audited
  int final_misses = 0;          ///< misses at the last audit
  int final_nodes_checked = 0;   ///< nodes within the cutoff at the last audit
  int max_misses = 0;            ///< most misses in one audit
  double max_misses_time = 0.0;  ///< s
  long total_misses = 0;         ///< summed over the audits
  double max_gap_error = 0.0;    ///< mm
};

/// A [[history]] group at the end of the run (of forming, when a springback follows).
struct HistoryGroupResult {
  std::string group;
  int nodes = 0;
  HistoryGroupConfig quantities;  ///< which of the values below the case asked for
  GroupMeasures values;           ///< mean motion and summed reaction (group_history.hpp)
};

/// One part of a blank of several at the end of the run.
struct PartSummary {
  std::string name;
  double initial_thickness = 0.0;   ///< mm
  double min_thickness = 0.0;       ///< mm
  double max_thinning = 0.0;        ///< -, largest 1 - t / t0 of the part's elements
  double max_plastic_strain = 0.0;  ///< -, over the part's integration points
};

struct RunSummary {
  long cycles = 0;
  double end_time = 0.0;              ///< s
  double wall_seconds = 0.0;          ///< s
  double ns_per_element_cycle = 0.0;  ///< whole loop wall time per element and cycle
  double element_share = 0.0;         ///< share of the wall time in the element forces
  double contact_share = 0.0;         ///< share of the wall time in contact (search + penalty)
  /// ns per element-cycle of each phase (PhaseTimes); `other` = the whole loop less the phases
  /// (the set-up before the first step, the final output)
  struct PhaseCosts {
    double elements = 0.0, contact = 0.0, time_step = 0.0, nodal = 0.0, output = 0.0, other = 0.0;
  } phase_ns;
  double contact_ns_per_node_cycle = 0.0;  ///< contact wall time per blank node and cycle
  int elements = 0;
  int nodes = 0;
  int threads = 1;  ///< OpenMP threads the run used (sheetform run --threads)
  int ranks = 1;    ///< MPI ranks sharing the blank (mpirun -np)
  /// s, each rank's wall time per phase (PhaseTimes: elements, contact, time step, nodal,
  /// output), then its time in messages (part of those phases, waiting included), rank 0 first:
  /// the load balance of a distributed run
  std::vector<std::array<double, 6>> phase_seconds_per_rank;
  Energies energies;
  bool drawbeads = false;            ///< the run has drawbead lines (their work is reported)
  double peak_kinetic_ratio = 0.0;   ///< largest kinetic/internal after the first tenth
  double physical_mass = 0.0;        ///< tonne, the blank's mass before scaling
  double added_mass = 0.0;           ///< tonne, added by mass scaling (at the start and in the run)
  double added_mass_fraction = 0.0;  ///< added / physical mass
  int scaled_elements = 0;           ///< elements that received mass
  double min_time_step = 0.0;        ///< s, smallest stable step of the run (safety included)
  double max_time_step = 0.0;        ///< s, largest stable step of the run
  int min_time_step_element = -1;    ///< the element limiting min_time_step
  double min_thickness = 0.0;        ///< mm
  double max_thickness = 0.0;        ///< mm
  double max_plastic_strain = 0.0;
  /// A blank of several parts (a tailor-welded blank): each part's figures, in the case's order;
  /// empty for a blank of one part.
  std::vector<PartSummary> parts;
  std::vector<ToolSummary> tools;
  std::vector<DrawInResult> draw_ins;
  std::vector<SearchAuditSummary> search_audits;  ///< filled by the driver when results are written
  /// The constraints' reactions per case entry at the end of the run (forming, or the static
  /// analysis's last increment), solver/reactions.hpp.
  std::vector<ConstraintReaction> reactions;
  std::vector<HistoryGroupResult> history_groups;  ///< the case's [[history]] groups
  std::string units = "mm-s-tonne-N-MPa";          ///< the case's unit system
  std::optional<ImplicitStepSummary> static_step;  ///< a static analysis
  std::optional<SpringbackSummary> springback;     ///< after an explicit forming run
  /// The press line's operations as run ([[operations]]; empty for a case without them)
  std::vector<OperationRecord> operations;
};

/// The summary of the state at the end of a run; the reactions (per constraint entry and summed
/// over the history groups) from compute_reactions.
RunSummary make_run_summary(const Model& model, const SolutionState& state, double wall_seconds);

/// The summary's costs per element-cycle and node-cycle (ns) and time shares from the phase
/// times and the element-cycles and node-cycles run (a run through a trim sums them over its
/// meshes); make_run_summary counts cycles x the model's elements and nodes.
void set_per_unit_costs(RunSummary& summary, const PhaseTimes& times, double element_cycles,
                        double node_cycles);
/// The end-of-run summary as text for the console.
std::string format_run_summary(const RunSummary& summary);
/// Writes summary.json (machine-readable, with the version and git hash).
void write_run_summary_json(const RunSummary& summary, const std::filesystem::path& file);

}  // namespace sf
