#pragma once
// How many elements an element size asks of the surfaces in the current gmsh session, before gmsh
// meshes them (inside the sandboxed child).

namespace sf {

/// Elements of size element_size (mm) on the current model's surfaces: each surface's area taken
/// as the product of its bounding box's two longest sides (exact for a rectangle in a coordinate
/// plane, the right order of size for the others); a triangle of side h covers 0.43 h^2, a quad
/// h^2 (recombine).
double estimate_element_count(double element_size, bool recombine);

/// The area (mm^2) the estimate above takes.
double estimated_surface_area();

}  // namespace sf
