#pragma once
// How close a tool comes to a shell's mid-surface (mm): the tool-to-blank clearance reported
// before a run is this distance less half the blank's thickness (docs/tool-diagnosis.md).
#include <limits>

#include "core/types.hpp"
#include "mesh/triangle_surface.hpp"

namespace sf {

/// The closest approach of two surfaces.
struct SurfaceApproach {
  double distance = std::numeric_limits<double>::infinity();  ///< mm, 0 where they meet
  Vec3 tool_point = Vec3::Zero();                             ///< mm, on the tool (translated)
  Vec3 shell_point = Vec3::Zero();                            ///< mm, on the shell's mid-surface
  /// Cosine of the angle between the tool's normal at tool_point (its averaged nodal normals
  /// interpolated there) and the direction to shell_point: > 0 where the tool faces the shell, as
  /// contact needs; 0 when the surfaces meet.
  double facing = 0.0;
};

/// The least distance between `tool` translated by `tool_offset` (mm) and a shell mid-surface of
/// quadrilaterals (each taken as its two triangles 0-1-2 and 0-2-3: exact for flat ones) and
/// triangles, with the points where it is reached: exact over the triangles (vertex-triangle,
/// edge-edge and crossing), by a tree of the tool triangles' boxes, nearest first.
SurfaceApproach closest_approach(const TriangleSurface& tool, const Vec3& tool_offset,
                                 const Matrix3X& shell_nodes, const QuadConn& quads,
                                 const TriConn& triangles);

}  // namespace sf
