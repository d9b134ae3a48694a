#pragma once
// Each node's share of a shell mesh's area.
#include "core/types.hpp"

namespace sf {

/// mm^2 per node: a quarter of each quadrilateral's area (half the cross product of its
/// diagonals: exact for a flat one) and a third of each triangle's, summed quads first, then
/// triangles, each in element order.
VectorX nodal_tributary_area(const Matrix3X& nodes, const QuadConn& quads,
                             const TriConn& triangles);

/// mm^2, a node's area now from its area and half thickness at the start and its half thickness
/// now (mm): plastic flow keeps the volume, so the area grows as the sheet thins. A half
/// thickness now that is not > 0 (not yet known) gives the start area.
inline double area_now(double start_area, double start_half_thickness, double half_thickness) {
  return half_thickness > 0.0 ? start_area * start_half_thickness / half_thickness : start_area;
}

}  // namespace sf
