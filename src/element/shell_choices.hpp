#pragma once
// The shell choices a case makes ([blank]): the through-thickness rule, the quadrilateral's
// formulation and its hourglass form, each an enum with its one name table (core/choice.hpp).
#include <array>

#include "core/choice.hpp"

namespace sf {

/// Through-thickness quadrature family.
enum class ThroughThicknessRule {
  gauss,    ///< Gauss-Legendre, 1..9 points, exact to degree 2n - 1, interior points only
  lobatto,  ///< Gauss-Lobatto, 2..9 points, exact to degree 2n - 3, includes both surfaces
};

/// Hourglass control form (Flanagan & Belytschko 1981).
enum class HourglassForm {
  viscous,    ///< forces proportional to the hourglass velocity (LS-DYNA type 1 style)
  stiffness,  ///< forces from the accumulated hourglass displacement, stored per element
};

/// The quadrilateral's formulation (docs/element-and-material.md, "Formulations").
enum class ShellFormulation {
  /// Belytschko-Lin-Tsay: one point, Flanagan-Belytschko hourglass control of the form and
  /// coefficient ShellPart::hourglass_form / hourglass_coefficient.
  belytschko_tsay,
  /// One point with physical stabilisation from assumed strains: the quintessential-bending
  /// membrane (Belytschko & Bindeman 1993), fully integrated curvature and the MITC4 transverse
  /// shear (Dvorkin & Bathe 1984), all at the material's elastic moduli; no user coefficient.
  assumed_strain,
};

inline constexpr std::array<Choice<ThroughThicknessRule>, 2> kThroughThicknessRuleNames{{
    {ThroughThicknessRule::gauss, "gauss", "Gauss-Legendre, interior points"},
    {ThroughThicknessRule::lobatto, "lobatto",
     "Gauss-Lobatto: the bottom and top surfaces are points"},
}};

inline constexpr std::array<Choice<ShellFormulation>, 2> kShellFormulationNames{{
    {ShellFormulation::belytschko_tsay, "belytschko_tsay",
     "Belytschko-Lin-Tsay quads with the hourglass control below, and C0 DSG3 triangles: exact on "
     "flat meshes, 15 % to 20 times too flexible on curved and warped shells"},
    {ShellFormulation::assumed_strain, "assumed_strain",
     "quads and triangles with one in-plane point, directors, assumed bending strains from arc "
     "differences of the directors, MITC4 transverse shear, a physical stabilisation with no "
     "coefficient that follows the material's incremental stiffness: right on flat, curved and "
     "warped shells (docs/shell-obstacle-course.md); the forming validation's element"},
}};

inline constexpr std::array<Choice<HourglassForm>, 2> kHourglassFormNames{{
    {HourglassForm::viscous, "viscous",
     "forces from hourglass velocities, a fraction of critical damping"},
    {HourglassForm::stiffness, "stiffness",
     "forces from accumulated hourglass displacements, the coefficient times the element's "
     "membrane/bending stiffness"},
}};

}  // namespace sf
