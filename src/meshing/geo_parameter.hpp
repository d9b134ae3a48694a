#pragma once
// A number set in a .geo file before gmsh parses it (a mesh source's `parameters`), e.g. the
// element count of a mesh-convergence study.
#include <string>

namespace sf {

struct GeoParameter {
  std::string name;    ///< a .geo identifier the file declares with DefineConstant[ name = ... ]
  double value = 0.0;  ///< in the file's own units (mm for lengths)
  /// Where the value was given, for messages: "case.toml:12:15" or the command-line override;
  /// empty when unknown. Not part of the resolved case.
  std::string location;
};

}  // namespace sf
