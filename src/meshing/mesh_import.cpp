#include "meshing/mesh_import.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <gmsh.h>
#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <string_view>

#include "core/errors.hpp"

namespace sf {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// Every accepted extension (lower case) and its format: the one table behind mesh_format,
// accepted_mesh_extensions and the case reader's check of `mesh`.
struct ExtensionFormat {
  std::string_view extension;
  MeshFormat format;
};
constexpr std::array<ExtensionFormat, 12> kFormats{{{".geo", MeshFormat::geo},
                                                    {".msh", MeshFormat::msh},
                                                    {".step", MeshFormat::step},
                                                    {".stp", MeshFormat::step},
                                                    {".iges", MeshFormat::iges},
                                                    {".igs", MeshFormat::iges},
                                                    {".brep", MeshFormat::brep},
                                                    {".stl", MeshFormat::stl},
                                                    {".bdf", MeshFormat::nastran},
                                                    {".nas", MeshFormat::nastran},
                                                    {".unv", MeshFormat::unv},
                                                    {".vtk", MeshFormat::vtk}}};

}  // namespace

std::optional<MeshFormat> find_mesh_format(const std::filesystem::path& file) {
  const std::string ext = lower(file.extension().string());
  for (const auto& [extension, format] : kFormats) {
    if (ext == extension) {
      return format;
    }
  }
  return std::nullopt;
}

MeshFormat mesh_format(const std::filesystem::path& file) {
  if (const auto format = find_mesh_format(file)) {
    return *format;
  }
  const std::string ext = lower(file.extension().string());
  if (ext == ".inp" || ext == ".vtu" || ext == ".med") {
    // gmsh 4.8 (Debian 12) has no reader for these (an .inp or .vtu would go to its .geo parser).
    throw InputError(fmt::format(
        "'{}': gmsh 4.8 cannot read {} files; write the mesh as Nastran bulk data (.bdf), UNV, "
        "legacy VTK or gmsh .msh (accepted: {})",
        file.string(), ext == ".inp" ? "Abaqus .inp" : (ext == ".vtu" ? "XML VTK .vtu" : "MED"),
        accepted_mesh_extensions()));
  }
  throw InputError(fmt::format("'{}': unknown mesh file extension '{}' (expected {})",
                               file.string(), ext, accepted_mesh_extensions()));
}

std::string accepted_mesh_extensions() {
  std::string text;
  for (std::size_t k = 0; k < kFormats.size(); ++k) {
    text += (k == 0 ? "" : (k + 1 == kFormats.size() ? " or " : ", "));
    text += kFormats[k].extension;
  }
  return text;
}

bool is_cad(MeshFormat format) {
  return format == MeshFormat::step || format == MeshFormat::iges || format == MeshFormat::brep;
}

bool is_imported(MeshFormat format) {
  return format != MeshFormat::geo && format != MeshFormat::msh;
}

bool is_meshed(MeshFormat format) {
  return format == MeshFormat::geo || is_cad(format);
}

void set_cad_read_options(MeshFormat format, const MeshImportOptions& options) {
  if (format == MeshFormat::step) {
    // STEP carries its length unit: OpenCASCADE converts it to mm. (gmsh 4.8 refuses this option
    // for IGES, and BREP has no unit.)
    gmsh::option::setString("Geometry.OCCTargetUnit", "MM");
  }
  if (format == MeshFormat::iges) {
    // IGES tools often come as loose trimmed faces: sew them into one conforming surface.
    gmsh::option::setNumber("Geometry.OCCSewFaces", 1);
    gmsh::option::setNumber("Geometry.Tolerance", 1e-5);
  }
  gmsh::option::setNumber("Geometry.OCCScaling", options.scale);
  gmsh::option::setNumber("Geometry.OCCImportLabels", 0);  // names are the case's, not the file's
}

namespace {

// The entities of dimension `dim` (2 surfaces, 1 curves) listed in `tags` (all when empty) made
// the physical group `name`; InputError naming the file for a tag the file lacks or no entity.
void group_entities(const std::filesystem::path& file, int dim, const std::vector<int>& tags,
                    const std::string& name) {
  const char* kind = dim == 2 ? "surface" : "curve";
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, dim);
  std::vector<int> all;
  for (const auto& [d, tag] : entities) {
    all.push_back(tag);
  }
  std::sort(all.begin(), all.end());
  if (all.empty()) {
    throw InputError(fmt::format("'{}': no {}s in the file", file.string(), kind));
  }
  const std::vector<int> chosen = tags.empty() ? all : tags;
  for (const int tag : chosen) {
    if (!std::binary_search(all.begin(), all.end(), tag)) {
      throw InputError(fmt::format("'{}': {} {} is not in the file (its {}s: {})", file.string(),
                                   kind, tag, kind, fmt::join(all, ", ")));
    }
  }
  const int group = gmsh::model::addPhysicalGroup(dim, chosen);
  gmsh::model::setPhysicalName(dim, group, name);
}

}  // namespace

void group_imported_surfaces(const std::filesystem::path& file, const MeshImportOptions& options) {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  std::vector<std::string> named;
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    if (dim == 2 && !name.empty()) {
      named.push_back(name);
    }
  }
  if (!named.empty()) {
    if (!options.surfaces.empty()) {
      throw InputError(fmt::format(
          "'{}': the file names its parts ({}): choose one with group, not with surfaces",
          file.string(), fmt::join(named, ", ")));
    }
    return;
  }
  gmsh::model::removePhysicalGroups();  // unnamed ones (a UNV file's material numbers)
  group_entities(file, 2, options.surfaces, options.group);
}

void group_imported_curves(const std::filesystem::path& file, const MeshImportOptions& options) {
  gmsh::model::removePhysicalGroups();
  group_entities(file, 1, options.curves, options.group);
}

}  // namespace sf
