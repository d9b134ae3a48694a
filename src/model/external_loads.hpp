#pragma once
// The applied loads on the blank (gravity, nodal forces and moments, pressures following the
// deforming surface) at a time and configuration: shared by the explicit loop and the static
// analysis (which runs its load curves over a pseudo-time).
#include <span>

#include "element/element_block.hpp"
#include "model/model.hpp"

namespace sf {

/// Sets f_ext (N) and m_ext (N mm), 3 x nodes, to the model's loads at `time` (s) on the
/// coordinates x (mm), and the `released` nodal loads (summed after the model's nodal loads).
/// The same as compute_nodal_loads then add_pressure_loads.
void compute_external_forces(const Model& model, double time, const Matrix3X& x, Matrix3X& f_ext,
                             Matrix3X& m_ext, std::span<const NodalLoad> released = {});

/// Sets f_ext (N) and m_ext (N mm) to the loads that do not depend on the configuration: gravity,
/// the model's nodal loads, then the `released` ones, at `time` (s).
void compute_nodal_loads(const Model& model, double time, Matrix3X& f_ext, Matrix3X& m_ext,
                         std::span<const NodalLoad> released = {});

/// Adds the pressure loads at `time` (s) on the coordinates x (mm) to f_ext (N): each load in
/// turn, its elements in ascending order, each element's share to its nodes.
void add_pressure_loads(const Model& model, double time, const Matrix3X& x, Matrix3X& f_ext);

/// The force (N) pressure p (MPa) puts on each node of blank element e (of `block`) on the
/// coordinates x: its vector area shared equally by its nodes, pushing the top face along -normal.
Vec3 pressure_node_force(const ElementBlock& block, const Matrix3X& x, int e, double p);

/// The vector area (mm^2) of blank element e (of `block`) on the coordinates x: along the
/// element's normal, which points to its top side (the +normal side a pressure acts on). Quad:
/// (x3 - x1) x (x4 - x2) / 2; triangle: (x2 - x1) x (x3 - x1) / 2.
Vec3 element_vector_area(const ElementBlock& block, const Matrix3X& x, int e);

/// Where a pressure load pushes, on the coordinates x: for users to check that their elements'
/// top side is the one they meant.
struct PressureDirection {
  double area = 0.0;               ///< mm^2, summed over the load's elements
  Vec3 top_normal = Vec3::Zero();  ///< the area-weighted mean normal of their top sides (unit)
  Vec3 push = Vec3::Zero();        ///< unit direction of the resultant (-top_normal for p > 0)
  Vec3 resultant = Vec3::Zero();   ///< N, -p x the summed vector area, at scale factor 1
};

/// The direction of `load` on the blank of `model` at the coordinates x (mm).
PressureDirection compute_pressure_direction(const Model& model, const PressureLoad& load,
                                             const Matrix3X& x);

}  // namespace sf
