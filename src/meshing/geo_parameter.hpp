#pragma once
// A number set in a .geo file before gmsh parses it (a mesh source's `parameters`), e.g. the
// element count of a mesh-convergence study.
#include <cstddef>
#include <string>

#include "core/errors.hpp"

namespace sf {

struct GeoParameter {
  std::string name;    ///< a .geo identifier the file declares with DefineConstant[ name = ... ]
  double value = 0.0;  ///< in the file's own units (mm for lengths)
  /// Where the value was given, for messages: "case.toml:12:15" or the command-line override;
  /// empty when unknown. Not part of the resolved case.
  std::string location;
};

/// A parameter a .geo file cannot take (it does not define it, or assigns it itself); index() is
/// its position in the parameters given.
class GeoParameterError : public InputError {
 public:
  GeoParameterError(std::size_t index, const std::string& message)
      : InputError(message), index_(index) {}
  std::size_t index() const { return index_; }

 private:
  std::size_t index_;
};

}  // namespace sf
