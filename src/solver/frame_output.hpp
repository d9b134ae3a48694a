#pragma once
// Turns the solution state into results frames and history rows (HDF5 + XDMF, see
// docs/results-format.md). Buffers are allocated once; frames are rare, so this is off the hot
// path.
#include <filesystem>
#include <functional>
#include <memory>

#include "model/model.hpp"
#include "results/results_writer.hpp"
#include "solver/contact_output.hpp"
#include "solver/formability_output.hpp"
#include "solver/group_history.hpp"
#include "solver/search_audit_recorder.hpp"
#include "solver/solution_state.hpp"

namespace sf {

/// Where the output of a run stands, as a checkpoint keeps it: the frames and history rows in
/// results.h5, the run they belong to, the cycle of the last history row, and the search audits'
/// counts over the run (their per-node fields are not kept: the next audit makes them).
struct OutputMark {
  int frames = 0;
  std::size_t history_rows = 0;
  long last_history_cycle = -1;
  std::string run_id;
  std::vector<SearchAuditRecord> audits;
  long last_audit_cycle = -1;
};

/// Reads one history column's value from the state (frame_output.cpp: each column is named and
/// read in one place).
using HistoryReader =
    std::function<double(const Model&, const SolutionState&, const SearchAuditRecorder&)>;

class FrameOutput {
 public:
  /// Creates the results directory's files, and writes the resolved case and build information.
  FrameOutput(const Model& model, const std::filesystem::path& directory);
  /// Takes up the results a run wrote in `directory` up to its checkpoint `mark` (a restart):
  /// what it wrote after the checkpoint is dropped, to be written again. With
  /// `blank_mesh_changed` (the model built again on a trimmed part), the blank's frames from
  /// now on are of the model's mesh (ResultsWriter::change_topology).
  FrameOutput(const Model& model, const std::filesystem::path& directory, const OutputMark& mark,
              bool blank_mesh_changed = false);
  /// Writes the buffered history rows and returns where the output stands (for a checkpoint).
  OutputMark mark();
  void write_frame(const Model& model, const SolutionState& state);
  /// Buffers a history row of the current state (none if this cycle has one already).
  void append_history(const Model& model, const SolutionState& state);
  void flush();
  /// After a run stopped on an InstabilityError: the history up to the stop and, when the
  /// positions are finite and newer than the last frame (time last_frame_time, s), one last frame
  /// of the state at the stop; then flushes. Returns the sentence to append to the error message.
  std::string write_stop_state(const Model& model, const SolutionState& state,
                               double last_frame_time);
  /// From now on, frames carry springback_displacement = x - x_formed (mm) with x_formed these
  /// coordinates (the end of forming). Before this call, a case with [springback] writes the field
  /// as zeros, so that every frame has the same arrays.
  void set_springback_reference(const Matrix3X& x_formed);
  /// From now on, element stresses are turned to global components with the element frames at
  /// these coordinates (mm) rather than the current ones: a linear analysis refers its stresses
  /// to the undeformed geometry (null = the current coordinates again).
  void set_stress_geometry(const Matrix3X* x) { stress_geometry_ = x; }
  /// Frames written so far.
  int frame_count() const { return writer_->frame_count(); }
  /// The first frame at or after `time` (s) among those written.
  int first_frame_at_or_after(double time) const { return writer_->first_frame_at_or_after(time); }
  /// Writes operation number `index`'s record (results.h5 /operations/<index>).
  void write_operation(int index, const OperationRecord& record) {
    writer_->write_operation(index, record);
  }
  /// The records of the operations before operation `count` (a restart inside it).
  std::vector<OperationRecord> read_operations(int count) const {
    return writer_->read_operations(count);
  }
  /// The search audits run with the frames and history rows (contact pairs with audit = true).
  const SearchAuditRecorder& search_audits() const { return audits_; }

 private:
  /// The parts (blank, then the tools) and sizes the buffers.
  std::vector<PartTopology> set_up(const Model& model);

  std::unique_ptr<ResultsWriter> writer_;
  SearchAuditRecorder audits_;
  Matrix3X displacement_;
  bool has_springback_field_ = false;
  const Matrix3X* stress_geometry_ = nullptr;
  bool needs_reactions_ = false;      ///< a [[history]] group records reactions
  Matrix3X reaction_force_;           ///< N per node, at the last history row
  Matrix3X reaction_moment_;          ///< N mm per node
  Matrix3X springback_reference_;     ///< mm, x_formed (empty until set)
  Matrix3X springback_displacement_;  ///< mm
  VectorX plastic_strain_;
  VectorX part_index_;          ///< per element, its part (index into Blank::parts), as a double
  VectorX added_mass_percent_;  ///< per element, written when mass scaling is on
  Eigen::Matrix<double, 6, Eigen::Dynamic> stress_mid_, stress_top_, stress_bottom_;
  /// MPa, the back stresses of a law with kinematic hardening at the outer points (else unused).
  Eigen::Matrix<double, 6, Eigen::Dynamic> back_stress_top_, back_stress_bottom_;
  std::vector<Matrix3X> tool_coordinates_;
  std::vector<Matrix3X> tool_displacement_;
  ContactFieldsOutput contact_fields_;
  FormabilityFieldsOutput formability_fields_;
  std::vector<HistoryReader> history_readers_;  ///< the columns before the groups', in order
  std::vector<double> row_;
  long last_history_cycle_ = -1;  ///< one row per cycle at most
};

/// The history columns with their units (the case's), in order: time, the step taken and the
/// stable step with its limiting element, the energies, the added mass, then per tool its travel,
/// speed, force and contact node count, the draw-ins, per audited contact pair its search misses,
/// then the [[history]] groups' columns (docs/results-format.md).
std::vector<HistoryColumn> history_columns(const Model& model);

}  // namespace sf
