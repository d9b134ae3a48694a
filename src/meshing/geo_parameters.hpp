#pragma once
// Opening a .geo with parameters set before gmsh parses it (inside the sandboxed gmsh session).
#include <filesystem>
#include <span>

#include "meshing/geo_parameter.hpp"

namespace sf {

/// Opens `file` in the current gmsh session with `parameters` set before it is parsed. Each must
/// be a variable the file declares with DefineConstant[ name = default ] (DefineConstant keeps a
/// value set before it; a plain assignment would override it). gmsh 4.8's API cannot set or list
/// parser variables, so the file is parsed twice: once as it is, to check with Exists() that it
/// defines every parameter, then through a wrapper .geo written in `scratch` that assigns the
/// parameters and Includes the file, reading each value back afterwards. GeoParameterError for a
/// parameter the file does not define or overrides.
void open_with_parameters(const std::filesystem::path& file,
                          std::span<const GeoParameter> parameters,
                          const std::filesystem::path& scratch);

}  // namespace sf
