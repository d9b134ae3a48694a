#pragma once
// A closed (or open) line from the curves of a gmsh model: a trim line drawn in a .geo file (a
// Physical Curve), kept in a .msh file, or made of a CAD file's curves (meshing/mesh_import.hpp,
// curves_only). The curves' line elements are joined end to end into one closed loop of points.
#include <string>
#include <vector>

#include "core/types.hpp"
#include "meshing/gmsh_model.hpp"

namespace sf {

/// The points of the 1-D physical group `group` of `model` in order along it (mm, the model's
/// coordinates): its line elements (the two end nodes of each, whatever its order) joined end to
/// end into one closed loop, the first point not repeated at the end. Ends closer than
/// `tolerance` (mm) are one point: separate CAD curves meet only within the CAD system's
/// tolerance. Throws InputError naming model.file and the group for: no 1-D group of that name
/// (listing the groups), no line elements in it, a loop that is not closed (an end that meets no
/// other, at its coordinates), a branch (a point where three or more lines meet), or more than
/// one loop.
std::vector<Vec3> closed_curve_points(const GmshModel& model, const std::string& group,
                                      double tolerance);

/// The same for an open line (a drawbead's): its line elements joined end to end from one end
/// to the other (from the end with the lower node index), both ends included. Throws InputError
/// for a missing group, no line elements, a closed line, a branch, or more than one line.
std::vector<Vec3> open_curve_points(const GmshModel& model, const std::string& group,
                                    double tolerance);

}  // namespace sf
