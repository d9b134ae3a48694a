#pragma once
// Lowers the case's constraint entries ([[boundary]], [[prescribed_velocity]],
// [[prescribed_motion]]) onto the blank's nodes. Each entry holds or drives directions (global
// unit vectors) of translation and rotation on its group; at a node they combine by span, so two
// symmetry planes meeting at a corner hold what both hold. Where a node's directions are all
// global axes, it keeps the global axes (no frame); else it takes the frame of an entry whose
// axes contain them all, or one built from them (held directions first, then the prescribed
// ones). docs/case-file.md, "[[boundary]]".
#include <string>
#include <vector>

#include "casefile/case_config.hpp"
#include "model/boundary_conditions.hpp"
#include "model/model.hpp"

namespace sf {

/// The frame of a plane given by its unit normal n: columns n, t1, t2 (right-handed), t1 the
/// global axis least aligned with n made perpendicular to it.
Mat3 make_plane_frame(const Vec3& normal);

/// The frame of AxesConfig: columns x, y (as read: unit, perpendicular) and x cross y.
Mat3 make_frame(const AxesConfig& axes);

/// A [[boundary]] entry in words, e.g. "diaphragm normal to (0.866, 0.5, 0): the two in-plane
/// translations held", for `sheetform check`.
std::string describe_boundary(const BoundaryConfig& boundary);

/// Sets model.constraints (masks and node frames) and model.prescribed_motions from the case.
/// A prescribed displacement without a curve ramps from 0 at time 0 to its value at `end_time`
/// (s). Throws InputError naming the case file, the entry's line and key, and the node, for a
/// group without blank nodes, a direction held and prescribed (or prescribed twice) at a node, or
/// a prescribed direction neither along nor perpendicular to the others there.
void assemble_constraints(const CaseConfig& config, const Blank& blank, double end_time,
                          Model& model);

}  // namespace sf
