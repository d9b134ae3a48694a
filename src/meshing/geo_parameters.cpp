#include "meshing/geo_parameters.hpp"

#include <fmt/core.h>

#include <gmsh.h>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/quoted.hpp"
#include "meshing/gmsh_session.hpp"

namespace sf {
namespace {

void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file);
  out << text;
  if (!out) {
    throw InputError(quoted(file) + ": cannot write this temporary gmsh file");
  }
}

/// The ONELAB number `name`, set by a DefineConstant[ ... Name "name" ] of a parsed .geo.
double read_onelab_number(const std::string& name) {
  std::vector<double> value;
  gmsh::onelab::getNumber(name, value);
  return value.empty() ? std::numeric_limits<double>::quiet_NaN() : value.front();
}

/// Parses `file` as it is and checks that it defines every parameter (gmsh's Exists()).
void check_parameters_defined(const std::filesystem::path& file,
                              std::span<const GeoParameter> parameters,
                              const std::filesystem::path& folder) {
  gmsh::onelab::clear();
  run_gmsh_step(file, "reading the file", [&] { gmsh::open(file.string()); });
  std::string check;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    check += fmt::format(
        "DefineConstant[ sheetform_defined_{0} = {{Exists({1}), Name \"sheetform/defined/{0}\"}} "
        "];\n",
        i, parameters[i].name);
  }
  write_text(folder / "check.geo", check);
  run_gmsh_step(file, "checking its parameters",
                [&] { gmsh::merge((folder / "check.geo").string()); });
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    if (read_onelab_number(fmt::format("sheetform/defined/{}", i)) != 1.0) {
      throw GeoParameterError(
          i, fmt::format("{} does not define {}: declare it in the file with DefineConstant[ {} = "
                         "<default> ]; (gmsh then takes the value set before the file is parsed)",
                         quoted(file), parameters[i].name, parameters[i].name));
    }
  }
}

}  // namespace

void open_with_parameters(const std::filesystem::path& file,
                          std::span<const GeoParameter> parameters,
                          const std::filesystem::path& scratch) {
  const std::string path = std::filesystem::absolute(file).generic_string();
  if (path.find('"') != std::string::npos) {
    throw InputError(quoted(file) + ": a .geo path holding '\"' cannot take parameters");
  }
  check_parameters_defined(file, parameters, scratch);
  std::string wrapper;
  for (const GeoParameter& p : parameters) {
    wrapper += fmt::format("{} = {:.17g};\n", p.name, p.value);
  }
  wrapper += fmt::format("Include \"{}\";\n", path);
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    wrapper += fmt::format(
        "DefineConstant[ sheetform_value_{0} = {{{1}, Name \"sheetform/value/{0}\"}} ];\n", i,
        parameters[i].name);
  }
  const std::filesystem::path wrapper_file = scratch / file.filename();
  write_text(wrapper_file, wrapper);
  gmsh::onelab::clear();
  run_gmsh_step(file, "reading the file", [&] { gmsh::open(wrapper_file.string()); });
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const double kept = read_onelab_number(fmt::format("sheetform/value/{}", i));
    if (kept != parameters[i].value) {
      throw GeoParameterError(
          i, fmt::format("{} assigns {} itself ({} = {:g} once the file is read, not the {:g} "
                         "set): declare it with DefineConstant[ {} = {:g} ]; instead of a plain "
                         "assignment, so that it can be set",
                         quoted(file), parameters[i].name, parameters[i].name, kept,
                         parameters[i].value, parameters[i].name, kept));
    }
  }
}

}  // namespace sf
