#pragma once
// Which rigid-body motions the boundary conditions leave free: the check before an implicit static
// step (a free mode makes the stiffness singular), and the holds that would remove them.
#include <array>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "model/node_frames.hpp"

namespace sf {

struct RigidBodyModes {
  int free_count = 0;  ///< rigid-body modes (of 6) the held degrees of freedom leave free
  /// Readable description of a basis of the free modes, e.g. "translation along z", "rotation
  /// about an axis along x through (0, 0, 0) mm".
  std::vector<std::string> free_modes;
  /// {node, dof} (dof 0..5 = ux, uy, uz, rx, ry, rz): a minimal set of extra holds that removes
  /// every free mode; translations only where possible (the 3-2-1 rule), chosen as far apart as
  /// possible for a well-conditioned support; empty when free_count == 0.
  std::vector<std::array<int, 2>> added;
};

/// The rigid-body modes of a body of 6-dof nodes at coordinates x (mm) that the held degrees of
/// freedom leave free. held: one 6-bit mask per node (bits 0-2 translations x, y, z; bits 3-5
/// rotations about x, y, z), the same convention as NodalConstraints::mask in
/// src/model/boundary_conditions.hpp. A rigid motion with translation a and rotation w about the
/// centroid c moves node i by a + w x (x_i - c) and turns it by w. Deterministic (no random
/// numbers; ties broken by lowest node index). Throws std::invalid_argument for no nodes, a mask
/// count other than the node count, or a coordinate that is not finite.
///
/// Rotations are measured by the motion they cause at the body's radius L (the largest distance
/// of a node from the centroid), so translations and rotations weigh alike: a mode counts as free
/// when the held degrees of freedom hold it with an eigenvalue of R_h^T R_h below 1e-12 of the
/// largest (or of 1), i.e. when its support has a lever arm below about 1e-6 L.
/// docs/static-linear-algebra.md describes the algorithm.
/// frames: the nodes whose masks refer to their own axes (a held bit k of such a node holds the
/// component along its axis k); default: every node in the global axes. The added holds are then
/// in each node's axes too.
RigidBodyModes find_free_rigid_body_modes(const Matrix3X& x, const std::vector<unsigned char>& held,
                                          const NodeFrames& frames = {});

}  // namespace sf
