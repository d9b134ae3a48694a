#include "solver/progress.hpp"

#include "core/log.hpp"

namespace sf {

Progress::Progress(const Model& model, int interval_cycles)
    : interval_cycles_(interval_cycles), start_(std::chrono::steady_clock::now()), last_(start_) {
  log_info("{:>9} {:>12} {:>7} {:>11} {:>8} {:>9} {:>8} {:>8}\n", "cycle", "time [s]", "stroke",
           "dt [s]", "KE/IE", "energy", "mass+", "ETA");
}

void Progress::report(const Model& model, const SolutionState& s, bool final) {
  const auto now = std::chrono::steady_clock::now();
  const bool due = interval_cycles_ > 0 ? s.cycle % interval_cycles_ == 0
                                        : std::chrono::duration<double>(now - last_).count() >= 2.0;
  if (!due && !final) {
    return;
  }
  last_ = now;
  const double fraction = model.time.end_time > 0.0 ? s.time / model.time.end_time : 1.0;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  log_info("{:>9} {:>12.5e} {:>6.1f}% {:>11.3e} {:>8.4f} {:>8.1e} {:>7.2f}% {:>7.0f}s\n", s.cycle,
           s.time, 100.0 * fraction, s.stable_dt, s.energies.kinetic_ratio(),
           s.energies.balance_error(), 100.0 * s.scaling.added_mass / model.blank.physical_mass,
           eta);
}

}  // namespace sf
