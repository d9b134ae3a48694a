#pragma once
// The free edges of a triangle surface (edges of one triangle only) and how they join up: a
// closed surface (a solid's skin) has none; an open one (a die face, a punch without its top)
// has one boundary per outline or hole.
#include "mesh/triangle_surface.hpp"

namespace sf {

struct SurfaceBoundary {
  int free_edges = 0;  ///< edges of exactly one triangle
  /// Connected sets of free edges (joined at shared nodes): one per outline or hole, fewer where
  /// two outlines touch at a node.
  int boundaries = 0;
  double length = 0.0;  ///< mm, the free edges' total length

  bool closed() const { return free_edges == 0; }
};

/// The boundary of `surface`, a manifold surface (as orient_surface leaves it: an edge shared by
/// more than two triangles, which it refuses, would count once per triangle).
SurfaceBoundary surface_boundary(const TriangleSurface& surface);

}  // namespace sf
