#pragma once
// The six degrees of freedom of a shell node, in the order every nodal mask and equation uses:
// translations ux, uy, uz (mm), rotations rx, ry, rz (rad).

namespace sf {

/// Names of the six nodal degrees of freedom, in order (bit k of a nodal mask is kDofNames[k]).
inline constexpr const char* kDofNames[6] = {"ux", "uy", "uz", "rx", "ry", "rz"};

}  // namespace sf
