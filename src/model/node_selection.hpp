#pragma once
// Blank nodes chosen by position ([[node_group]], docs/case-file.md): on a plane, inside a box,
// on the blank's outline, or the one nearest to a point. For a blank from a file that carries no
// physical groups (a CAD face, an STL or another code's mesh), where supports, loads and history
// points must still be named.
#include <string>

#include "casefile/case_config.hpp"
#include "mesh/mesh_data.hpp"

namespace sf {

/// The nodes of `blank` that meet every criterion of `config` (NodeGroupConfig), named
/// config.name, sorted. `tolerance` (mm) is config.tolerance, or 1 % of the blank's shortest
/// element edge when that is 0. Throws InputError starting with `where` ("case.toml:40:
/// node_group[0]") when no node is chosen, saying what was asked and where the blank lies.
NodeGroup select_nodes(const NodeGroupConfig& config, const PartMesh& blank,
                       const std::string& where);

/// The default tolerance: 1 % of the shortest edge of the blank's elements (mm).
double default_node_tolerance(const PartMesh& blank);

/// Whether each node lies on the blank's outline: an edge of one element only.
std::vector<char> outline_nodes(const PartMesh& blank);

}  // namespace sf
