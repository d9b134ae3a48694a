#pragma once
// Static description and integration-point state of a Belytschko-Lin-Tsay shell part.
#include <array>
#include <vector>

#include "core/types.hpp"
#include "material/plane_stress.hpp"

namespace sf {

/// Through-thickness integration rule: n_points Gauss-Legendre points, ordered from the bottom
/// (zeta = -1 side) to the top (zeta = +1 side, the side the normal e3 points to).
struct ShellSection {
  int n_points = 5;
  std::array<double, 9> zeta{};    ///< positions in [-1, 1]; z = zeta t / 2
  std::array<double, 9> weight{};  ///< Gauss weights, summing to 2
};

/// The Gauss-Legendre rule with n_points (1..9) points; exact for polynomials of degree
/// 2 n_points - 1 in zeta. Throws InputError outside 1..9.
ShellSection make_gauss_section(int n_points);

/// Integration-point state of a shell part, structure of arrays. In-plane quantities are indexed
/// e * n_points + k (k = 0 bottom .. n_points - 1 top); stresses are components in the element's
/// corotational frame (e1, e2, e3).
struct ShellState {
  int n_elements = 0;
  int n_points = 0;
  std::vector<double> sxx, syy, sxy;  ///< MPa, in-plane stress per point
  std::vector<double> eps_p;          ///< -, equivalent plastic strain per point
  std::vector<double> sxz, syz;       ///< MPa, per element: transverse shear stress averaged over
                                      ///< the thickness (Q / t, shear-corrected)
  std::vector<double> thickness;      ///< mm, per element, current
};

/// A stress-free state with uniform thickness (mm).
ShellState make_shell_state(int n_elements, int n_points, double thickness);

/// A shell part: connectivity (node indices, counter-clockwise seen from the +normal side),
/// section, material and the viscous hourglass coefficient.
struct ShellPart {
  QuadConn quads;
  ShellSection section = make_gauss_section(5);
  Material material = ElasticPlaneStress{};
  double density = 0.0;                ///< tonne/mm^3
  double hourglass_coefficient = 0.1;  ///< -, fraction (x 4) of critical damping, see docs
};

}  // namespace sf
