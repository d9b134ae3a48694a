#pragma once
// The applied loads on the blank (gravity, nodal forces and moments, pressures following the
// deforming surface) at a time and configuration: shared by the explicit loop and the static
// analysis (which runs its load curves over a pseudo-time).
#include "model/model.hpp"

namespace sf {

/// Sets f_ext (N) and m_ext (N mm), 3 x nodes, to the model's loads at `time` (s) on the
/// coordinates x (mm).
void compute_external_forces(const Model& model, double time, const Matrix3X& x, Matrix3X& f_ext,
                             Matrix3X& m_ext);

}  // namespace sf
