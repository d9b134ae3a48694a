#include "element/element_failure.hpp"

namespace sf {

std::string ElementFailure::message() const {
  std::string name = "shell element " + std::to_string(element);
  if (triangle >= 0) {
    name += " (triangle " + std::to_string(triangle) + ")";
  }
  switch (kind) {
    case Kind::none:
      return name + ": no failure";
    case Kind::non_finite_velocity:
      return name + ": non-finite nodal velocity or angular velocity";
    case Kind::non_finite_stress:
      return name + ": non-finite stress";
    case Kind::invalid_geometry:
      return name +
             (triangle >= 0 ? ": collapsed or non-finite geometry ("
                            : ": inverted, collapsed or non-finite geometry (") +
             when + ")";
    case Kind::inverted:
      return name + ": inverted (the normal flipped within the step)";
    case Kind::material:
      return name + ": " + material.message();
    case Kind::directors_not_set:
      return name + ": directors not initialised (initialize_directors)";
    case Kind::internal:
      return name + ": " + internal_text;
  }
  return name;
}

}  // namespace sf
