#include "model/external_loads.hpp"

namespace sf {

void compute_external_forces(const Model& model, double time, const Matrix3X& x, Matrix3X& f_ext,
                             Matrix3X& m_ext) {
  const ExternalLoads& loads = model.loads;
  f_ext.setZero();
  m_ext.setZero();
  if (!loads.gravity.isZero()) {
    const Vec3 g =
        (loads.gravity_scale.empty() ? 1.0 : loads.gravity_scale.value(time)) * loads.gravity;
    for (Eigen::Index i = 0; i < f_ext.cols(); ++i) {
      f_ext.col(i) = model.blank.physical_nodal_mass[i] * g;
    }
  }
  for (const NodalLoad& load : loads.nodal) {
    const Vec3 value = load.scale.value(time) * load.value;
    Matrix3X& target = load.moment ? m_ext : f_ext;
    for (int node : load.nodes) {
      target.col(node) += value;
    }
  }
  const QuadConn& quads = model.blank.part.quads;
  const TriConn& triangles = model.blank.part.triangles;
  const Eigen::Index n_quads = quads.cols();
  for (const PressureLoad& load : loads.pressures) {
    const double p = load.scale.value(time) * load.pressure;
    for (int e : load.elements) {
      // Vector area of the element, shared equally by its nodes; the pressure on the top face
      // pushes along -normal. Quad: (x3 - x1) x (x4 - x2) / 2; triangle: (x2 - x1) x (x3 - x1) / 2.
      if (e < n_quads) {
        const Vec3 area = 0.5 * (x.col(quads(2, e)) - x.col(quads(0, e)))
                                    .cross(x.col(quads(3, e)) - x.col(quads(1, e)));
        const Vec3 f = (-0.25 * p) * area;
        for (int a = 0; a < 4; ++a) {
          f_ext.col(quads(a, e)) += f;
        }
      } else {
        const Eigen::Index k = e - n_quads;
        const Vec3 x1 = x.col(triangles(0, k));
        const Vec3 area = 0.5 * (x.col(triangles(1, k)) - x1).cross(x.col(triangles(2, k)) - x1);
        const Vec3 f = (-p / 3.0) * area;
        for (int a = 0; a < 3; ++a) {
          f_ext.col(triangles(a, k)) += f;
        }
      }
    }
  }
}

}  // namespace sf
