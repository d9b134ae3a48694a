#pragma once
// Plane-stress materials for shells. Stress and strain are Voigt vectors in the element's
// corotational frame: stress (sxx, syy, sxy) in MPa, strain (exx, eyy, gxy) with ENGINEERING shear
// gxy = 2 exy. Each material is a value type with a nested State and a pure `update`.
#include <variant>

#include "core/types.hpp"
#include "material/hardening.hpp"

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
  double
      d_ezz;  ///< through-thickness strain increment, - (plane stress + plastic incompressibility)
  bool plastic;  ///< true when the step was plastic
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
/// consistency parameter, relative tolerance 1e-10 on the yield condition).
struct J2PlaneStress {
  using State = PlaneStressState;
  double E = 0.0;   ///< Young's modulus, MPa
  double nu = 0.0;  ///< Poisson's ratio, -
  Hardening hardening = LinearHardening{};

  /// New state after the strain increment d_strain = (d_exx, d_eyy, d_gxy). Throws
  /// InstabilityError if the return mapping fails (non-finite input).
  PlaneStressUpdate update(const State& old, const Vec3& d_strain) const;
};

/// A shell part's material law, chosen once per part (visit it outside element loops).
using Material = std::variant<ElasticPlaneStress, J2PlaneStress>;

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
/// Throws InputError (naming `what`) unless E > 0, -1 < nu < 0.5 and the hardening is admissible.
void check_material(const Material& material, const char* what);

}  // namespace sf
