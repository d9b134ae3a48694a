#pragma once
// The blank's critical time step must be one an explicit run can advance by: a step of 0 (the
// wave speed overflowing, young = 1e300), a subnormal one or a non-finite one would cycle at
// t = 0 forever or end the run in one step.
#include "casefile/case_config.hpp"
#include "element/shell_mass.hpp"
#include "model/model.hpp"

namespace sf {

/// Throws InputError unless `physical` (the blank's critical step, s, at its physical density,
/// before the safety factor) and model.time.time_step (the run's, after mass scaling) are
/// positive normal numbers. The message names the case file and the keys that made it: the
/// material's young, density and poisson when the wave speed is not a positive finite number
/// (or is so large that the step is not normal), else the limiting element's size.
void check_critical_time_step(const CaseConfig& config, const Blank& blank,
                              const StableStep& physical);

/// The same for the step after mass scaling (control.mass_scaling_dt).
void check_scaled_time_step(const CaseConfig& config, const Model& model);

}  // namespace sf
