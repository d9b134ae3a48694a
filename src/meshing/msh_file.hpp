#pragma once
// The MSH 4.1 binary file that gmsh writes in the sandbox (meshing/gmsh_job.hpp), read here
// without gmsh: the file crosses from the sandboxed child to this process, so it is parsed as
// untrusted bytes, every count checked against what is left of the file before anything is
// allocated. Only what gmsh 4.8 writes with Mesh.Binary = 1 (8-byte sizes, this machine's byte
// order) is accepted: $MeshFormat, $PhysicalNames, $Entities, $Nodes, $Elements, $Periodic.
#include <filesystem>
#include <string_view>

#include "meshing/gmsh_model.hpp"

namespace sf {

/// Parses `bytes`, the content of an MSH 4.1 binary file, into a model whose file is `source`
/// (the user's file it was made from, for messages). Physical groups are sorted by (dim, tag);
/// each group's element blocks follow the file's entity order. InputError naming `source` for
/// anything out of format.
GmshModel parse_msh41_binary(std::string_view bytes, const std::filesystem::path& source);

/// Reads `file` (a regular file, not a link, at most max_bytes) and parses it as above.
GmshModel read_msh41_binary(const std::filesystem::path& file, const std::filesystem::path& source,
                            double max_bytes);

/// The gmsh element type's nodes per element (0 for a type gmsh 4.8 does not have) and name.
int gmsh_nodes_per_element(int type);
std::string gmsh_type_name(int type);

}  // namespace sf
