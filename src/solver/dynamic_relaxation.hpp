#pragma once
// The explicit springback route: the tool forces at the end of forming are released slowly (the
// tools withdrawn without touching the part again), then dynamic relaxation brings the blank to
// rest. The comparison route for the implicit springback step; docs/static-analysis.md.
#include "casefile/case_config.hpp"
#include "model/model.hpp"
#include "solver/frame_output.hpp"
#include "solver/solution_state.hpp"

namespace sf {

struct DynamicRelaxationResult {
  double release_time = 0.0;         ///< s, the tool forces went to zero over this time
  double relaxation_time = 0.0;      ///< s, after the release, until at rest (or max_time)
  long cycles = 0;                   ///< explicit cycles, release and relaxation
  double final_kinetic_ratio = 0.0;  ///< kinetic / internal energy at the end
  bool at_rest = false;              ///< the kinetic tolerance was reached before max_time

  // final_kinetic_ratio is measured as the stop rule measures it, a peak of the kinetic energy
  // over reference_energy (right after a reset the kinetic energy itself is 0 and says nothing):
  // at rest, the largest kinetic energy of the final check of rest (a free run without resets);
  // at max_time, the larger of the last peak before a reset and the peak since.
  /// N mm, what kinetic_tolerance multiplies: the larger of the internal (+ hourglass) energy at
  /// the start of springback and at the end
  double reference_energy = 0.0;
  /// blank nodes that got a released load (the formed state's static internal force and moment,
  /// less the case's own loads)
  int frozen_load_nodes = 0;
  /// N, the sum of the released forces at the start of the release
  Vec3 frozen_force = Vec3::Zero();
  /// N, the sum of the contact forces at the end of forming (the released forces' sum differs
  /// from it by the blank's inertia and the boundary reactions)
  Vec3 contact_force = Vec3::Zero();
  /// kinetic-damping resets (every velocity zeroed at a peak of the kinetic energy)
  long resets = 0;
  /// rest probes started (free runs without resets that check the blank is at rest; the last one
  /// succeeded when at_rest)
  int rest_probes = 0;
  /// N mm, the kinetic energy the resets (and the stopped force-controlled tools) took out; part
  /// of energies.damping
  double damping_energy = 0.0;
};

/// Continues the run from `state` (the end of forming: time, positions, stresses, the contact
/// forces of the last cycle in state.f_contact) with the contact switched off: the contact forces
/// act as nodal loads ramped linearly to zero over config.release_time, then the blank relaxes
/// with kinetic damping (every velocity zeroed at each peak of the kinetic energy) until the
/// kinetic energy falls below config.kinetic_tolerance x the internal energy or config.max_time
/// has passed after the release (a warning then, not an error). Writes frames (about
/// control.output_frames / 4 of them, at least 2) and history rows to `output` (may be null).
/// Throws InstabilityError when the run goes unstable.
DynamicRelaxationResult run_dynamic_relaxation(const Model& model, SolutionState& state,
                                               FrameOutput* output, const SpringbackConfig& config);

}  // namespace sf
