#include "element/shell_geometry_batch.hpp"

#include <algorithm>
#include <cstddef>

#include "element/shell_nodal_access.hpp"

// Compiled for generic x86-64 and for x86-64-v3 (GCC function multiversioning); with the build's
// -ffp-contract=off both perform the same correctly rounded operations per lane. Everything the
// function calls on blocks is inline, so each variant carries its own copy.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && \
    !defined(SF_NO_MULTIVERSIONING)
#define SF_GEOMETRY_CLONES __attribute__((target_clones("default", "arch=x86-64-v3")))
#else
#define SF_GEOMETRY_CLONES
#endif

namespace sf {

SF_GEOMETRY_CLONES void compute_quad_geometry_block(const double* xd, const double* vd,
                                                    const int* conn, int e0, int count, double dt,
                                                    QuadGeometryBlock& out) {
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

SF_GEOMETRY_CLONES void compute_quad_area_block(const double* xd, const int* conn, int e0,
                                                int count, double (&area)[kBlockLanes],
                                                bool (&ok)[kBlockLanes]) {
  Block xe[3][4];
  for (int j = 0; j < kBlockLanes; ++j) {
    // Lanes past the end repeat the last element (computed, not used).
    const int* nodes = conn + 4 * static_cast<std::ptrdiff_t>(e0 + std::min(j, count - 1));
    Quad3 xq;
    gather_nodes(xd, nodes, xq);
    for (int c = 0; c < 3; ++c) {
      for (int i = 0; i < 4; ++i) {
        xe[c][i][j] = xq(c, i);
      }
    }
  }
  GeometryLanes<Block> g;
  const BlockMask valid = compute_geometry_lanes(xe, g);
  for (int j = 0; j < count; ++j) {
    area[j] = g.area[j];
    ok[j] = valid[j] != 0;
  }
}

}  // namespace sf
