#pragma once
// The corotational geometries of a block of quads (kBlockLanes consecutive elements) at the
// mid-step and end-of-step configurations, computed together in SIMD lanes: the frame and
// gradient of one element are a chain of square roots and divisions the processor cannot
// overlap, those of four elements run side by side. Each lane gives the bits of
// compute_shell_geometry for its element (shell_geometry.hpp: one kernel for both).
#include <algorithm>

#include "core/simd_block.hpp"
#include "core/types.hpp"
#include "element/shell_geometry.hpp"
#include "element/shell_nodal_access.hpp"

namespace sf {

/// Geometries of elements e0 .. e0 + count - 1 at lanes 0 .. count - 1; *_ok false: the element
/// is inverted, collapsed or not finite there (the loop throws when it reaches it).
struct QuadGeometryBlock {
  ShellGeometry mid[kBlockLanes];  ///< at x - dt/2 v (the strains' configuration)
  ShellGeometry end[kBlockLanes];  ///< at x (the forces' configuration)
  bool mid_ok[kBlockLanes];
  bool end_ok[kBlockLanes];
};

/// Fills `out` for the count (1..kBlockLanes) quads from e0 of the connectivity conn (4 nodes per
/// element), nodal coordinates xd and velocities vd (3 x n column-major), step dt.
inline void compute_quad_geometry_block(const double* xd, const double* vd, const int* conn, int e0,
                                        int count, double dt, QuadGeometryBlock& out) {
  Block xm[3][4];
  Block xe[3][4];
  for (int j = 0; j < kBlockLanes; ++j) {
    // Lanes past the end repeat the last element (computed, not used).
    const int* nodes = conn + 4 * static_cast<std::ptrdiff_t>(e0 + std::min(j, count - 1));
    Quad3 xq;
    Quad3 vq;
    gather_nodes(xd, nodes, xq);
    gather_nodes(vd, nodes, vq);
    const Quad3 xmq = xq - (0.5 * dt) * vq;  // as the element loops form it
    for (int c = 0; c < 3; ++c) {
      for (int i = 0; i < 4; ++i) {
        xe[c][i][j] = xq(c, i);
        xm[c][i][j] = xmq(c, i);
      }
    }
  }
  GeometryLanes<Block> mid;
  GeometryLanes<Block> end;
  const BlockMask mid_ok = compute_geometry_lanes(xm, mid);
  const BlockMask end_ok = compute_geometry_lanes(xe, end);
  for (int j = 0; j < count; ++j) {
    unpack_geometry(mid, j, out.mid[j]);
    unpack_geometry(end, j, out.end[j]);
    out.mid_ok[j] = mid_ok[j] != 0;
    out.end_ok[j] = end_ok[j] != 0;
  }
}

}  // namespace sf
