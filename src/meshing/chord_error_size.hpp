#pragma once
// Mesh size from a maximum chord error: on a curved CAD face or edge of radius R, a straight
// element of length h stands off the true surface by the sagitta s = R - sqrt(R^2 - h^2 / 4) at
// its middle; the chord error e caps it, so h <= 2 sqrt(e (2 R - e)) (about sqrt(8 R e) for
// e << R). Unlike gmsh's Mesh.MeshSizeFromCurvature (a fixed number of elements per 2 pi, whose
// chord error grows with the radius), this keeps the facets within e of every radius: what
// matters for contact, where a facet's stand-off is a false gap or penetration.
#include <limits>

namespace sf {

/// The largest element length (mm) whose chord error on a curvature of `curvature` (1/mm, the
/// largest principal curvature of a face, or an edge's curvature) is at most `chord_error` (mm):
/// 2 sqrt(e (2 R - e)), R = 1 / curvature. Infinity where nothing limits it: a flat or straight
/// place (curvature 0, or not finite), or a radius no larger than e (any chord stays within e).
double chord_error_size(double curvature, double chord_error);

/// Installs, in the current gmsh session, a mesh size callback that limits the size at every
/// point of a curve or surface to chord_error_size of its curvature there (gmsh's own curvature
/// of the CAD entity; the other size limits, element_size and curvature_elements, still apply:
/// gmsh takes the smallest). Call after the CAD file is opened, before meshing.
void set_chord_error_size(double chord_error);

}  // namespace sf
