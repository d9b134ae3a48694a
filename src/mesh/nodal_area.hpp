#pragma once
// Each node's share of a shell mesh's area.
#include "core/types.hpp"

namespace sf {

/// mm^2 per node: a quarter of each quadrilateral's area (half the cross product of its
/// diagonals: exact for a flat one) and a third of each triangle's, summed quads first, then
/// triangles, each in element order.
VectorX nodal_tributary_area(const Matrix3X& nodes, const QuadConn& quads,
                             const TriConn& triangles);

}  // namespace sf
