#pragma once
// What stops an element pass, a code the element loop records instead of an exception (issue
// 17, issue 34): threads must not throw out of a parallel region, and the run must report the
// same element whatever the thread count. Each thread stops its share at its first failure; the
// pass then reports the lowest failing element of all, which is the one a serial pass stops at.
#include <climits>
#include <string>

#include "material/material_failure.hpp"

namespace sf {

struct ElementFailure {
  enum class Kind {
    none,
    non_finite_velocity,  ///< a node's velocity or angular velocity
    non_finite_stress,
    invalid_geometry,   ///< quad: inverted, collapsed or non-finite; triangle: collapsed
    inverted,           ///< triangle: the normal flipped within the step
    material,           ///< a point's material update failed (`material` says how)
    directors_not_set,  ///< a program error: initialize_directors was not called
    internal,           ///< an exception escaped the loop: a program error, its text kept
  };
  int element = INT_MAX;  ///< index in the part's state
  int triangle = -1;      ///< the triangle's index among the triangles; -1 for a quad
  Kind kind = Kind::none;
  const char* when = "";  ///< "mid-step" or "end of step" (geometry)
  MaterialFailure material;
  std::string internal_text;

  bool failed() const { return kind != Kind::none; }
  /// A program error, not a state the run reached (the pass throws std::runtime_error for it).
  bool program_error() const { return kind == Kind::directors_not_set || kind == Kind::internal; }

  /// Keeps the failure of the lower element (the first one a serial pass would meet).
  void keep_lowest(const ElementFailure& other) {
    if (other.failed() && (!failed() || other.element < element)) {
      *this = other;
    }
  }

  /// The message a serial pass has always stopped with (InstabilityError text).
  std::string message() const;
};

}  // namespace sf
