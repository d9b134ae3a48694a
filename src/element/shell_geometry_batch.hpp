#pragma once
// The corotational geometries of a block of quads (kBlockLanes consecutive elements) at the
// mid-step and end-of-step configurations, computed together in SIMD lanes: the frame and
// gradient of one element are a chain of square roots and divisions the processor cannot
// overlap, those of four elements run side by side. Each lane gives the bits of
// compute_shell_geometry for its element (shell_geometry.hpp: one kernel for both).
#include "core/simd_block.hpp"  // kBlockLanes
#include "core/types.hpp"
#include "element/shell_geometry.hpp"

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
/// element), nodal coordinates xd and velocities vd (3 x n column-major), step dt. Compiled for
/// generic x86-64 and for x86-64-v3 (AVX2: one instruction per block), chosen at run time; both
/// give the same bits (shell_geometry_batch.cpp).
void compute_quad_geometry_block(const double* xd, const double* vd, const int* conn, int e0,
                                 int count, double dt, QuadGeometryBlock& out);

/// The projected areas (mm^2, ShellGeometry::area) of the count (1..kBlockLanes) quads from e0 at
/// the configuration xd, and whether each element is valid there (the time-step loop's need).
/// Multiversioned as compute_quad_geometry_block.
void compute_quad_area_block(const double* xd, const int* conn, int e0, int count,
                             double (&area)[kBlockLanes], bool (&ok)[kBlockLanes]);

}  // namespace sf
