#pragma once
// What a case will cost before it runs, and what it asks for beyond the case's [limits]: the
// cycles, elements, memory, frames and output size `check` prints, and the tools that penetrate
// the blank at the start. A run refuses (InputError, exit 2) before any work what exceeds a limit,
// so that no input runs until killed (docs/case-file.md, [limits]).
#include <string>
#include <vector>

#include "casefile/case_config.hpp"
#include "model/model.hpp"

namespace sf {

/// Blank nodes inside a tool at time 0: closer to its surface than half the blank's thickness, or
/// on its far side (within the contact cutoff).
struct InitialPenetration {
  std::string tool;
  int nodes = 0;                 ///< blank nodes that penetrate
  int deepest_node = -1;         ///< the blank node that penetrates most (-1: none)
  double depth = 0.0;            ///< mm, half thickness - signed distance at that node
  Vec3 position = Vec3::Zero();  ///< mm, that node's coordinates
  double thickness = 0.0;        ///< mm, the blank's thickness at that node
};

struct RunEstimate {
  double cycles = 0.0;     ///< explicit cycles (0 for a static analysis)
  double end_time = 0.0;   ///< s, what the cycles are counted to
  double time_step = 0.0;  ///< s, the initial step they are counted by
  long elements = 0;       ///< blank elements
  long tool_triangles = 0;
  double element_cycles = 0.0;                   ///< cycles x blank elements
  double memory_bytes = 0.0;                     ///< the run's resident memory, estimated
  int frames = 0;                                ///< frames after the initial one
  double output_bytes = 0.0;                     ///< results.h5, estimated
  std::vector<InitialPenetration> penetrations;  ///< one per contact pair
};

/// Estimates the cost of the case's run. Memory: 100 MB (libraries, gmsh) + 6 kB per blank
/// element + 0.5 kB per tool triangle, measured peaks of the square cups (900 to 22,500 quads:
/// 96 to 220 MB). Output: every frame's arrays (8 bytes per value) and the history rows.
RunEstimate estimate_run(const CaseConfig& config, const Model& model);

/// Prints the estimate (check and run print it with the model).
void print_run_estimate(const RunEstimate& estimate, const Model& model);

/// Throws InputError naming the case file, the [limits] key and the figures when the estimate
/// exceeds a limit.
void enforce_run_limits(const CaseConfig& config, const RunEstimate& estimate);

}  // namespace sf
