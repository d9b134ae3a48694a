#pragma once
// Turns the solution state into results frames and history rows (HDF5 + XDMF, see
// docs/results-format.md). Buffers are allocated once; frames are rare, so this is off the hot
// path.
#include <filesystem>
#include <memory>

#include "io/results_writer.hpp"
#include "model/model.hpp"
#include "solver/solution_state.hpp"

namespace sf {

class FrameOutput {
 public:
  /// Creates the results directory's files, and writes the resolved case and build information.
  FrameOutput(const Model& model, const std::filesystem::path& directory);
  void write_frame(const Model& model, const SolutionState& state);
  void append_history(const Model& model, const SolutionState& state);
  void flush();

 private:
  std::unique_ptr<ResultsWriter> writer_;
  Matrix3X displacement_;
  VectorX plastic_strain_;
  Eigen::Matrix<double, 6, Eigen::Dynamic> stress_mid_, stress_top_, stress_bottom_;
  std::vector<Matrix3X> tool_coordinates_;
  std::vector<Matrix3X> tool_displacement_;
  std::vector<double> row_;
};

/// The history columns, in order: time, dt, the energies, then per tool its travel, force and
/// contact node count.
std::vector<std::string> history_columns(const Model& model);

}  // namespace sf
