#include "core/log.hpp"

namespace sf {

Verbosity& verbosity() {
  static Verbosity v = Verbosity::normal;
  return v;
}

bool& warnings_enabled() {
  static bool enabled = true;
  return enabled;
}

}  // namespace sf
