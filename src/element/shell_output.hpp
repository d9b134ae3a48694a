#pragma once
// Element stress output of a shell part, in global components.
#include <span>

#include "core/types.hpp"
#include "element/shell_part.hpp"

namespace sf {

/// 6 x n_elements stresses (MPa), elements numbered as in ShellPart (quads, then triangles),,
/// components (xx, yy, zz, xy, yz, xz) in the global frame.
using StressColumns = Eigen::Matrix<double, 6, Eigen::Dynamic>;
using Stress6 = Eigen::Matrix<double, 6, 1>;

/// Per-element output for post-processing.
struct ShellStressOutput {
  StressColumns mid;     ///< at the mid-plane (middle point; mean of the two central points for
                         ///< an even count), with the transverse shear Q / t
  StressColumns top;     ///< at the outermost point on the zeta = +1 side (transverse shear 0)
  StressColumns bottom;  ///< at the outermost point on the zeta = -1 side (transverse shear 0)
  VectorX eps_p;         ///< thickness-mean equivalent plastic strain (Gauss weighted), -
};

/// Fills `out` (resized) from the state, rotating each element's corotational stresses with the
/// element frame at the coordinates x (mm). Throws InstabilityError on a degenerate element.
void compute_element_stress_output(const ShellPart& part, const Matrix3X& x,
                                   const ShellState& state, ShellStressOutput& out);

/// The same, into caller-owned arrays (resized to 6 x n_elements and n_elements): stresses (MPa)
/// at the mid-plane, top and bottom, and the thickness-mean equivalent plastic strain (-).
void compute_element_stress_output(const ShellPart& part, const Matrix3X& x,
                                   const ShellState& state, StressColumns& mid, StressColumns& top,
                                   StressColumns& bottom, VectorX& eps_p);

/// The back stress of a law with kinematic hardening (the sum of its back stresses, MPa, global
/// components as the stress columns) at the outermost points, top (zeta = +1 side) and bottom.
/// The state must hold back stresses (ShellState::back_stress not empty).
void compute_element_back_stress_output(const ShellPart& part, const Matrix3X& x,
                                        const ShellState& state, StressColumns& top,
                                        StressColumns& bottom);

/// The stress (MPa) at every integration point of element e, bottom to top, in global components
/// (xx, yy, zz, xy, yz, xz): the point's in-plane stress with the element's transverse shear
/// (Q / t, the same at every point), rotated with the element frame at the coordinates x (mm).
/// `out` holds state.n_points entries. Throws InstabilityError on a degenerate element.
void compute_point_stresses(const ShellPart& part, const Matrix3X& x, const ShellState& state,
                            int e, std::span<Stress6> out);

/// Von Mises equivalent stress (MPa) of (xx, yy, zz, xy, yz, xz).
double von_mises(const Stress6& s);

}  // namespace sf
