#pragma once
// The coefficients of Hill's (1948) quadratic yield function in plane stress, from r-values.
#include "core/types.hpp"

namespace sf {

/// Hill (1948) quadratic anisotropic yield function coefficients, normalised with the rolling
/// direction (RD) as reference: G + H = 1, so sigma_eq = sigma_y in uniaxial tension along RD.
/// From the Lankford coefficients: G = 1/(1 + r0), H = r0/(1 + r0), F = r0/(r90 (1 + r0)),
/// N = (r0 + r90)(1 + 2 r45) / (2 r90 (1 + r0)).
struct Hill48Coefficients {
  double F, G, H, N;  ///< -
};
/// Hill48 coefficients from r0, r45, r90 (> 0; not checked here, see check_material).
Hill48Coefficients hill48_coefficients(double r0, double r45, double r90);
/// Hill48 plane-stress equivalent stress (MPa) of (sxx, syy, sxy) in material axes:
/// sigma_eq^2 = G sxx^2 + F syy^2 + H (sxx - syy)^2 + 2 N sxy^2.
double hill48_equivalent_stress(const Hill48Coefficients& c, const Vec3& stress);

}  // namespace sf
