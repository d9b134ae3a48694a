#pragma once
// Directional properties of a plane-stress yield criterion (uniaxial yield stress and Lankford
// coefficient at an angle to the rolling direction, equibiaxial yield stress and r_b), and the
// fits of Barlat's criteria to them: Yld2000-2d's eight coefficients from eight data (Barlat et al.
// 2003, sect. 4) and Yld89's a, c, h, p from r0, r45, r90 (Barlat & Lian 1989). Associated flow:
// the plastic strain increment is normal to the yield surface. See docs/material.md.
#include "material/yield_criterion.hpp"

namespace sf {

/// Uniaxial tension at `angle` (rad) to the rolling direction: its yield stress over the rolling
/// direction's, sigma_theta / sigma_0 (-).
double uniaxial_yield_ratio(const YieldCriterion& criterion, double angle);
/// Lankford coefficient r_theta = d_eps_width / d_eps_thickness (-) of uniaxial tension at
/// `angle` (rad) to the rolling direction.
double lankford_coefficient(const YieldCriterion& criterion, double angle);
/// Equibiaxial tension (sxx = syy): its yield stress over the rolling direction's, sigma_b /
/// sigma_0 (-).
double equibiaxial_yield_ratio(const YieldCriterion& criterion);
/// Equibiaxial tension: r_b = d_eps_yy / d_eps_xx (-) (Barlat et al. 2003; 1 when isotropic).
double equibiaxial_r_value(const YieldCriterion& criterion);

/// The data Yld2000-2d is fitted to: yield stresses (any unit, or ratios; only their ratios to
/// sigma0 are used) and Lankford coefficients at 0, 45 and 90 degrees, and equibiaxial.
struct Yld2000Data {
  double sigma0 = 1.0, sigma45 = 1.0, sigma90 = 1.0, sigma_b = 1.0;
  double r0 = 1.0, r45 = 1.0, r90 = 1.0, r_b = 1.0;
};

/// Yld2000-2d coefficients with exponent `a` reproducing the eight data exactly (Newton on the
/// eight equations from alpha = 1, to 1e-12). Throws InputError (naming `what`) for data out of
/// range (not finite or not > 0) or data no coefficients reproduce (the message gives the closest
/// residual).
Yld2000Criterion fit_yld2000(const Yld2000Data& data, double a, const char* what);

/// Yld89 with exponent M reproducing r0, r45 and r90: a = 2 - 2 sqrt(r0 r90 / ((1 + r0)(1 +
/// r90))), c = 2 - a, h = sqrt(r0 (1 + r90) / ((1 + r0) r90)) in closed form, p from r45 (a root
/// found by bisection). Throws InputError (naming `what`) for r-values not > 0 or an r45 no p
/// reaches.
Yld89Criterion fit_yld89(double r0, double r45, double r90, double M, const char* what);

}  // namespace sf
