#pragma once
// Lumped mass, rotational inertia and critical time step of a shell part.
#include <span>
#include <vector>

#include "core/types.hpp"
#include "element/shell_part.hpp"

namespace sf {

/// Lumped nodal mass (tonne) and rotational inertia (tonne mm^2). Each quad gives
/// m_e / 4 = rho t A / 4 to each of its nodes and each triangle m_e / 3 = rho t A / 3; each node
/// gets alpha times its mass share as rotational inertia, alpha = (A + t^2) / 4 (mm^2; see
/// rotational_inertia_factor, and docs/element-and-material.md for why it also suits triangles).
/// `mass` and `rotational_inertia` are resized to x.cols() and overwritten. Throws InstabilityError
/// on a degenerate element.
void compute_lumped_mass(const ShellPart& part, const Matrix3X& x, const ShellState& state,
                         VectorX& mass, VectorX& rotational_inertia);

/// Critical time step of a part and the element that limits it.
struct StableStep {
  double dt = 0.0;   ///< s, before any safety factor
  int element = -1;  ///< index of the limiting element (-1 for an empty part)
};

/// dt = min over elements of L / c, with c = sqrt(E / (rho (1 - nu^2))) the plate wave speed of
/// the element's material and
/// L = A / max(side length) for a quad, the LS-DYNA default characteristic length of a quad shell
/// (ISDO = 0), and L = 2 A / max(side length), the smallest altitude, for a triangle. Element
/// indices as in ShellPart (quads first). Throws InstabilityError on a degenerate element.
StableStep compute_stable_time_step(const ShellPart& part, const Matrix3X& x,
                                    const ShellState& state);

/// The same critical step for every element (s, before any safety factor, each at its own
/// material's wave speed) into element_dt, which holds one value per element (sized by the caller;
/// not resized, so no allocation in the time loop). Returns the smallest and its element. Throws
/// InstabilityError on a degenerate element.
StableStep compute_element_time_steps(const ShellPart& part, const Matrix3X& x,
                                      std::span<double> element_dt);

/// The plate wave speed c (mm/s) of a material at its density.
double material_wave_speed(const ShellMaterial& material);

/// L / c (s) of a quad with nodes xe and projected area `area` (mm^2, compute_shell_geometry's):
/// L = A / max side (LS-DYNA ISDO = 0), c = wave_speed (mm/s). The element force pass and
/// compute_element_time_steps both use it (the same bits).
double quad_time_step(const Quad3& xe, double area, double wave_speed);

/// The smallest of per-element steps and its element (the first one in element order on a tie).
StableStep smallest_time_step(std::span<const double> element_dt);

/// Each element's mass rho t A (tonne, at its material's density and the thickness in `state`) and
/// its rotational inertia factor alpha = (A + t^2) / 4 (mm^2), so that it gives m / 4 of mass and
/// alpha m / 4 of rotational inertia to each of its nodes (as compute_lumped_mass). Both vectors
/// are resized to the element count.
void compute_element_masses(const ShellPart& part, const Matrix3X& x, const ShellState& state,
                            std::vector<double>& mass, std::vector<double>& inertia_factor);

}  // namespace sf
