#pragma once
// Plane-stress yield criteria as equivalent-stress functions sigma_eq(s) (MPa), homogeneous of
// degree one, with their gradient and Hessian: von Mises, Hill (1948), Barlat & Lian (1989,
// Yld89) and Barlat et al. (2003, Yld2000-2d). Stress s = (sxx, syy, sxy) in the material axes
// (x = rolling direction), tensor shear; the gradient's third component is d sigma_eq / d sxy, so
// that d_eps^p = d_lambda * gradient has ENGINEERING shear, like every strain in material/. Each
// criterion is normalised so that sigma_eq equals the stress of uniaxial tension along the
// rolling direction: the hardening curve is the rolling direction's. See docs/material.md.
#include <array>
#include <variant>

#include "core/types.hpp"
#include "material/hill48_coefficients.hpp"

namespace sf {

/// von Mises: sigma_eq^2 = sxx^2 - sxx syy + syy^2 + 3 sxy^2.
struct VonMisesCriterion {};

/// Hill (1948), from its coefficients (hill48_coefficients of plane_stress.hpp).
struct Hill48Criterion {
  Hill48Coefficients k{0.5, 0.5, 0.5, 1.5};  ///< F, G, H, N (these: von Mises)
};

/// Barlat et al. (2003) Yld2000-2d: phi = phi'(X') + phi''(X'') = 2 sigma_eq^a with
/// phi' = |X'1 - X'2|^a, phi'' = |2 X''2 + X''1|^a + |2 X''1 + X''2|^a, X1, X2 the principal values
/// of X' = L' s and X'' = L'' s,
///   L'  = [[2 a1, -a1, 0], [-a2, 2 a2, 0], [0, 0, 3 a7]] / 3,
///   L'' = [[-2 a3 + 2 a4 + 8 a5 - 2 a6, a3 - 4 a4 - 4 a5 + 4 a6, 0],
///          [4 a3 - 4 a4 - 4 a5 + a6, -2 a3 + 8 a4 + 2 a5 - 2 a6, 0], [0, 0, 9 a8]] / 9.
/// All alpha = 1 is isotropic (a = 2: von Mises).
struct Yld2000Criterion {
  std::array<double, 8> alpha{1, 1, 1, 1, 1, 1, 1, 1};  ///< alpha_1 .. alpha_8, -
  double a = 8.0;                                       ///< exponent, - (>= 2)
};

/// Barlat & Lian (1989) Yld89 in plane stress: a |K1 + K2|^M + a |K1 - K2|^M + c |2 K2|^M =
/// 2 sigma_eq^M, K1 = (sxx + h syy) / 2, K2 = sqrt(((sxx - h syy) / 2)^2 + p^2 sxy^2). With
/// a = 2 - c the rolling direction's uniaxial stress is sigma_eq. a = c = h = p = 1 is isotropic
/// (M = 2: von Mises).
struct Yld89Criterion {
  double a = 1.0;  ///< -
  double c = 1.0;  ///< -
  double h = 1.0;  ///< -
  double p = 1.0;  ///< -
  double M = 8.0;  ///< exponent, - (>= 2)
};

using YieldCriterion =
    std::variant<VonMisesCriterion, Hill48Criterion, Yld2000Criterion, Yld89Criterion>;

/// An equivalent stress with its first and second derivatives with respect to (sxx, syy, sxy).
struct EquivalentStress {
  double value = 0.0;            ///< MPa
  Vec3 gradient = Vec3::Zero();  ///< -
  Mat3 hessian = Mat3::Zero();   ///< 1/MPa
};

/// sigma_eq(s) with derivatives. At s = 0 (no direction) the derivatives are returned as zero.
EquivalentStress equivalent_stress(const YieldCriterion& criterion, const Vec3& stress);
/// sigma_eq(s) only (MPa).
double equivalent_stress_value(const YieldCriterion& criterion, const Vec3& stress);

/// Throws InputError naming `what` unless the criterion's parameters are finite, its exponent is
/// >= 2 and its equivalent stress is convex and positive in every direction (checked on a sample
/// of the stress plane: Yld2000-2d and Yld89 coefficients fitted to unusual data may not be).
void check_yield_criterion(const YieldCriterion& criterion, const char* what);

/// The criterion's name for messages and reports ("von Mises", "Hill48", "Yld2000-2d", "Yld89").
const char* criterion_name(const YieldCriterion& criterion);

}  // namespace sf
