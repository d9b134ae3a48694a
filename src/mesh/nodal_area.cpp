#include "mesh/nodal_area.hpp"

namespace sf {

VectorX nodal_tributary_area(const Matrix3X& nodes, const QuadConn& quads,
                             const TriConn& triangles) {
  VectorX area = VectorX::Zero(nodes.cols());
  for (int e = 0; e < quads.cols(); ++e) {
    const Vec3 d1 = nodes.col(quads(2, e)) - nodes.col(quads(0, e));
    const Vec3 d2 = nodes.col(quads(3, e)) - nodes.col(quads(1, e));
    const double a = 0.5 * d1.cross(d2).norm();
    for (int k = 0; k < 4; ++k) {
      area[quads(k, e)] += 0.25 * a;
    }
  }
  for (int e = 0; e < triangles.cols(); ++e) {
    const Vec3 x1 = nodes.col(triangles(0, e));
    const Vec3 e1 = nodes.col(triangles(1, e)) - x1;
    const Vec3 e2 = nodes.col(triangles(2, e)) - x1;
    const double a = 0.5 * e1.cross(e2).norm();
    for (int k = 0; k < 3; ++k) {
      area[triangles(k, e)] += a / 3.0;
    }
  }
  return area;
}

}  // namespace sf
