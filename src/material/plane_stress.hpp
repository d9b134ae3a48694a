#pragma once
// Plane-stress materials for shells. Stress and strain are Voigt vectors in the element's
// corotational frame: stress (sxx, syy, sxy) in MPa, strain (exx, eyy, gxy) with ENGINEERING shear
// gxy = 2 exy. Each material is a value type with a nested State and a pure `update`.
#include <variant>

#include "core/types.hpp"
#include "material/general_plasticity.hpp"
#include "material/hardening.hpp"
#include "material/hill48_coefficients.hpp"

namespace sf {

/// State of one integration point of a plane-stress material.
struct PlaneStressState {
  Vec3 stress = Vec3::Zero();  ///< (sxx, syy, sxy), MPa
  double eps_p = 0.0;          ///< equivalent plastic strain, -
};

/// Result of one strain increment at one integration point.
struct PlaneStressUpdate {
  Vec3 stress;   ///< new (sxx, syy, sxy), MPa
  double eps_p;  ///< new equivalent plastic strain, -
  /// Through-thickness strain increment, - (plane stress + plastic incompressibility).
  double d_ezz;
  bool plastic;  ///< true when the step was plastic
  /// Plastic work increment per unit volume, MPa (= N mm / mm^3): sigma_mid . d_eps^p with
  /// sigma_mid = (sigma_n + sigma_{n+1}) / 2, so that the element's trapezoidal stress work
  /// sigma_mid . d_eps equals the elastic energy change plus this, exactly. 0 for elastic steps.
  double d_plastic_work = 0.0;
};

/// Linear isotropic elasticity in plane stress (Hooke).
struct ElasticPlaneStress {
  using State = PlaneStressState;
  double E = 0.0;   ///< Young's modulus, MPa
  double nu = 0.0;  ///< Poisson's ratio, -

  /// New state after the strain increment d_strain = (d_exx, d_eyy, d_gxy).
  PlaneStressUpdate update(const State& old, const Vec3& d_strain) const;
};

/// Von Mises (J2) elastic-plastic plane stress with isotropic hardening, integrated by the closed-
/// point return mapping of Simo & Taylor (1986), Simo & Hughes (1998) sect. 3.4 (Newton on the
/// consistency parameter, relative tolerance 1e-10 on the yield condition). Equal to
/// Hill48PlaneStress with r0 = r45 = r90 = 1.
struct J2PlaneStress {
  using State = PlaneStressState;
  double E = 0.0;   ///< Young's modulus, MPa
  double nu = 0.0;  ///< Poisson's ratio, -
  Hardening hardening = LinearHardening{};

  /// New state after the strain increment d_strain = (d_exx, d_eyy, d_gxy). Throws
  /// InstabilityError if the return mapping fails (non-finite input).
  PlaneStressUpdate update(const State& old, const Vec3& d_strain) const;
};

/// Hill (1948) orthotropic elastic-plastic plane stress with isotropic elasticity, associated
/// flow and isotropic hardening (hardening gives sigma_y of the rolling direction, the reference).
/// The return is the closed-point (backward-Euler) return of the J2 law generalised to the Hill
/// matrix P: C^-1 and P are diagonalised together (a 2 x 2 generalised eigenproblem for the normal
/// components; the shear decouples), so the stress is a closed-form scaling in that basis and only
/// a scalar consistency equation is solved (Newton, relative tolerance 1e-10 on the yield
/// condition). See docs/material.md.
///
/// FRAME: stress and strain are in the MATERIAL axes (x = rolling direction, y = transverse
/// direction). The caller rotates d_strain (engineering shear) into the rolling-direction frame
/// with rotate_strain and the stress back with rotate_stress; State.stress is stored in material
/// axes. Used directly (unrotated), the element frame is taken as the material frame. The shell
/// element does the rotation with ShellPart::material_angle and keeps its stored stress in the
/// element frame (see kUsesMaterialAxes).
struct Hill48PlaneStress {
  using State = PlaneStressState;
  double E = 0.0;    ///< Young's modulus, MPa
  double nu = 0.0;   ///< Poisson's ratio, -
  double r0 = 1.0;   ///< Lankford coefficient at 0 deg to the rolling direction, -
  double r45 = 1.0;  ///< Lankford coefficient at 45 deg, -
  double r90 = 1.0;  ///< Lankford coefficient at 90 deg, -
  Hardening hardening = LinearHardening{};  ///< flow stress in the rolling direction

  /// New state after the strain increment d_strain = (d_exx, d_eyy, d_gxy) in material axes.
  /// Throws InstabilityError if the return mapping fails (non-finite input).
  PlaneStressUpdate update(const State& old, const Vec3& d_strain) const;
};

/// A shell part's material law, chosen once per part (visit it outside element loops). J2 and
/// Hill48 with isotropic hardening have closed-form returns (modal_return_batch.hpp); every other
/// plastic law (Barlat's criteria, kinematic hardening) is a GeneralPlasticity.
using Material =
    std::variant<ElasticPlaneStress, J2PlaneStress, Hill48PlaneStress, GeneralPlasticity>;

/// True for a law whose update works in the material (rolling-direction) axes, which the element
/// must rotate into and out of (Hill48); false for isotropic laws, which take the element frame
/// as it is. A compile-time switch, so isotropic element loops carry no rotation code.
template <class Law>
inline constexpr bool kUsesMaterialAxes = false;
template <>
inline constexpr bool kUsesMaterialAxes<Hill48PlaneStress> = true;
template <>
inline constexpr bool kUsesMaterialAxes<GeneralPlasticity> = true;

/// Components of a strain (exx, eyy, gxy; engineering shear) in axes rotated by `angle` (rad,
/// counter-clockwise about e3) from the current ones: e' = R^T e R, R = [[c, -s], [s, c]].
/// rotate_strain(rotate_strain(e, a), -a) = e.
Vec3 rotate_strain(const Vec3& strain, double angle);
/// Components of a stress (sxx, syy, sxy; tensor shear) in axes rotated by `angle` (rad,
/// counter-clockwise about e3): s' = R^T s R. The work s . e (Voigt) is invariant.
Vec3 rotate_stress(const Vec3& stress, double angle);

/// rotate_strain with c = cos(angle), s = sin(angle) already known (no trigonometry; for loops
/// that rotate many points by one angle).
inline Vec3 rotate_strain(const Vec3& e, double c, double s) {
  const double cc = c * c;
  const double ss = s * s;
  const double cs = c * s;
  return {cc * e(0) + ss * e(1) + cs * e(2), ss * e(0) + cc * e(1) - cs * e(2),
          2.0 * cs * (e(1) - e(0)) + (cc - ss) * e(2)};
}
/// rotate_stress with c = cos(angle), s = sin(angle) already known.
inline Vec3 rotate_stress(const Vec3& t, double c, double s) {
  const double cc = c * c;
  const double ss = s * s;
  const double cs = c * s;
  return {cc * t(0) + ss * t(1) + 2.0 * cs * t(2), ss * t(0) + cc * t(1) - 2.0 * cs * t(2),
          cs * (t(1) - t(0)) + (cc - ss) * t(2)};
}

/// Plane-stress elastic stiffness C (MPa), Voigt with engineering shear.
Mat3 plane_stress_stiffness(double E, double nu);
/// Von Mises equivalent stress of a plane-stress state (MPa).
double von_mises_plane_stress(const Vec3& stress);
/// Plate (plane-stress) elastic wave speed c = sqrt(E / (rho (1 - nu^2))): mm/s for E in MPa and
/// rho in tonne/mm^3.
double plane_stress_wave_speed(double E, double nu, double rho);

/// Young's modulus (MPa) of any material.
double young_modulus(const Material& material);
/// Poisson's ratio of any material.
double poisson_ratio(const Material& material);
/// Throws InputError (naming `what`) unless E > 0, -1 < nu < 0.5, the hardening is admissible
/// and (Hill48) r0, r45, r90 are finite and > 0.
void check_material(const Material& material, const char* what);

}  // namespace sf
