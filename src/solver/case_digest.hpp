#pragma once
// Digests that tell whether two runs compute the same thing: the meshes every MPI rank built,
// and a case's physics (what a restart must find unchanged since its checkpoint).
#include <cstdint>
#include <string>

#include "model/model.hpp"

namespace sf {

/// FNV-1a over the bytes of the blank's and the tools' meshes (nodes, quads, triangles).
std::uint64_t mesh_digest(const Model& model);

/// The physics of a case: its resolved case text without what may change between a run and its
/// restart (the end time and stroke, the output and checkpoint schedule, the progress lines, the
/// results folder, comments, the meshes' paths), together with the meshes themselves. 16 hex
/// digits.
std::string case_digest(const Model& model);

}  // namespace sf
