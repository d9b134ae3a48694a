#include "core/log.hpp"

namespace sf {

Verbosity& verbosity() {
  static Verbosity v = Verbosity::normal;
  return v;
}

}  // namespace sf
