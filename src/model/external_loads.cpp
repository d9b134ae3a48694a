#include "model/external_loads.hpp"

#include "element/element_block.hpp"

namespace sf {

namespace {

void add_nodal_loads(std::span<const NodalLoad> loads, double time, Matrix3X& f_ext,
                     Matrix3X& m_ext) {
  for (const NodalLoad& load : loads) {
    const Vec3 value = load.scale.value(time) * load.value;
    Matrix3X& target = load.moment ? m_ext : f_ext;
    for (int node : load.nodes) {
      target.col(node) += value;
    }
  }
}

}  // namespace

void compute_external_forces(const Model& model, double time, const Matrix3X& x, Matrix3X& f_ext,
                             Matrix3X& m_ext, std::span<const NodalLoad> released) {
  compute_nodal_loads(model, time, f_ext, m_ext, released);
  add_pressure_loads(model, time, x, f_ext);
}

void compute_nodal_loads(const Model& model, double time, Matrix3X& f_ext, Matrix3X& m_ext,
                         std::span<const NodalLoad> released) {
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
  add_nodal_loads(loads.nodal, time, f_ext, m_ext);
  add_nodal_loads(released, time, f_ext, m_ext);
}

void add_pressure_loads(const Model& model, double time, const Matrix3X& x, Matrix3X& f_ext) {
  const ShellPart& part = model.blank.part;
  const ElementBlocks blocks = element_blocks(part);
  for (const PressureLoad& load : model.loads.pressures) {
    const double p = load.scale.value(time) * load.pressure;
    for (int e : load.elements) {
      const ElementBlock& block = blocks.of(e);
      const Vec3 f = pressure_node_force(block, x, e, p);
      const int* nodes = block.element_nodes(e);
      for (int a = 0; a < block.nodes_per_element(); ++a) {
        f_ext.col(nodes[a]) += f;
      }
    }
  }
}

Vec3 pressure_node_force(const ElementBlock& block, const Matrix3X& x, int e, double p) {
  const Vec3 area = element_vector_area(block, x, e);
  return block.shape == ElementShape::quad ? Vec3((-0.25 * p) * area) : Vec3((-p / 3.0) * area);
}

Vec3 element_vector_area(const ElementBlock& block, const Matrix3X& x, int e) {
  const int* n = block.element_nodes(e);
  if (block.shape == ElementShape::quad) {
    return 0.5 * (x.col(n[2]) - x.col(n[0])).cross(x.col(n[3]) - x.col(n[1]));
  }
  const Vec3 x1 = x.col(n[0]);
  return 0.5 * (x.col(n[1]) - x1).cross(x.col(n[2]) - x1);
}

PressureDirection compute_pressure_direction(const Model& model, const PressureLoad& load,
                                             const Matrix3X& x) {
  PressureDirection d;
  Vec3 vector_area = Vec3::Zero();
  const ElementBlocks blocks = element_blocks(model.blank.part);
  for (int e : load.elements) {
    const Vec3 a = element_vector_area(blocks.of(e), x, e);
    vector_area += a;
    d.area += a.norm();
  }
  if (vector_area.norm() > 0.0) {
    d.top_normal = vector_area.normalized();
  }
  d.resultant = -load.pressure * vector_area;
  if (d.resultant.norm() > 0.0) {
    d.push = d.resultant.normalized();
  }
  return d;
}

}  // namespace sf
