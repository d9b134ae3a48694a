#pragma once
// Whether a CAD, STL or ASCII .msh file is whole, checked on its bytes before gmsh and
// OpenCASCADE read it: their readers take a truncated file as far as it goes (an ASCII STL loses
// its last triangles with only a warning), loop in it (a truncated BREP), or believe its counts (a
// .msh that claims two billion nodes runs gmsh out of memory). Format-level checks only: a file
// that passes may still be wrong inside, which the readers report (in the sandbox).
#include <filesystem>
#include <string_view>

#include "meshing/mesh_import.hpp"

namespace sf {

/// InputError naming `file` and what is missing when its bytes are not a whole file of `format`:
/// STEP: starts with ISO-10303-21; and ends with END-ISO-10303-21; (ISO 10303-21, section 5).
/// IGES: its last record is the Terminate record (section letter T in column 73), whose counts of
///   Start, Global, Directory and Parameter records match the file's (IGES 5.3, section 2.2).
/// BREP: a "TShapes n" section with n shapes (each ending with its sub-shape list, "... *"), then
///   the reference of the main shape.
/// STL: binary when its size is 84 + 50 n bytes for the n triangles its header counts; otherwise
///   ASCII from "solid" to "endsolid", every facet whole (facet, outer loop, three vertices,
///   endloop, endfacet).
/// MSH (ASCII, versions 2 and 4): the node and element counts of $Nodes and $Elements fit in the
///   file (at least 8 bytes a node, 6 an element).
/// Other formats: nothing to check here.
void check_file_is_whole(const std::filesystem::path& file, MeshFormat format,
                         std::string_view bytes);

/// Reads `file` and checks it as above.
void check_file_is_whole(const std::filesystem::path& file, MeshFormat format);

}  // namespace sf
