#pragma once
// The degrees of freedom a static step solves for: the case's constraints, plus, where they
// leave rigid-body modes free, a minimal set of holds that removes them (or an error naming the
// modes, as the case asks).
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "casefile/case_config.hpp"
#include "core/types.hpp"
#include "implicit/dof_map.hpp"

namespace sf {

struct StaticConstraints {
  DofMap dofs;
  std::vector<std::string> free_modes;  ///< the rigid-body modes the case left free
  std::vector<std::string> added;       ///< the holds added for them, e.g. "node 3 (gmsh 4) uz"
  std::vector<std::array<int, 2>> added_holds;  ///< the same as {node, dof} (in the node's axes)
};

/// x: node coordinates (mm); held: the case's holds (6-bit mask per node: held and prescribed
/// degrees of freedom, neither solved for), in each node's axes (frames: those that have their
/// own; default none); node_name names a node in messages. With RigidBodyModes::error, throws
/// InputError naming the free modes.
StaticConstraints make_static_constraints(const Matrix3X& x, std::vector<unsigned char> held,
                                          ImplicitConfig::RigidBodyModes mode,
                                          const std::function<std::string(int)>& node_name,
                                          const NodeFrames& frames = {});

}  // namespace sf
