#pragma once
// Elastic-plastic plane stress with any yield criterion (yield_criterion.hpp), isotropic hardening
// (hardening.hpp) and optional nonlinear kinematic hardening (Armstrong & Frederick 1966; Chaboche
// 1986: a sum of back stresses), integrated by a closest-point (backward Euler) return mapping:
// Newton on the relative stress and the plastic multiplier with a line search, converged to 1e-10
// of the flow stress (Simo & Hughes 1998 sect. 3.6; Scherzinger 2017 for the line search). Gives
// the consistent (algorithmic) tangent for implicit steps. Isotropic elasticity.
//
// The law, with eta = s - sum_i alpha_i the relative stress and d_lambda the equivalent plastic
// strain increment:
//   f = sigma_eq(eta) - sigma_y(eps_p) <= 0,
//   d_eps^p = d_lambda n, n = d sigma_eq / d eta (engineering shear),
//   d alpha_i = C_i (eta / sigma_eq(eta)) d_lambda - gamma_i alpha_i d_lambda.
// The back stresses follow the relative stress's direction, so the rule holds for every criterion;
// under uniaxial tension along the rolling direction alpha_xx = C / gamma (1 - exp(-gamma eps_p)),
// Armstrong and Frederick's closed form. FRAME: material axes, like Hill48PlaneStress.
#include <array>
#include <limits>

#include "core/types.hpp"
#include "material/hardening.hpp"
#include "material/material_failure.hpp"
#include "material/yield_criterion.hpp"

namespace sf {

/// One Armstrong-Frederick back stress: d alpha = C m d_lambda - gamma alpha d_lambda.
struct BackStressTerm {
  double C = 0.0;      ///< MPa, initial kinematic hardening modulus
  double gamma = 0.0;  ///< -, rate of saturation (alpha saturates at C / gamma; 0: linear Prager)
};

/// At most this many back stresses per material (Chaboche's usual two or three, plus one).
inline constexpr int kMaxBackStresses = 4;

/// The kinematic part of the hardening: `count` back stresses (0: isotropic hardening only).
struct KinematicHardening {
  int count = 0;
  std::array<BackStressTerm, kMaxBackStresses> terms{};
};

/// kMaxBackStresses zero vectors (Eigen leaves a default-constructed Vec3 uninitialised).
inline std::array<Vec3, kMaxBackStresses> zero_back_stresses() {
  std::array<Vec3, kMaxBackStresses> back;
  back.fill(Vec3::Zero());
  return back;
}

/// Strain-rate dependence of the flow stress (Cowper & Symonds 1957), in the viscoplastic form:
///   sigma_y(eps_p, rate) = sigma_y(eps_p) (1 + (rate / D)^(1/q)),
/// rate = d_lambda / dt, the step's equivalent plastic strain rate (1/s), solved for inside the
/// return (so the factor does not lag a step behind, and an elastic step sees the rate-free flow
/// stress). D = 0: rate-independent.
struct CowperSymonds {
  double D = 0.0;  ///< 1/s, the rate at which the flow stress doubles
  double q = 1.0;  ///< -, the exponent's reciprocal
  bool active() const { return D > 0.0; }
};

/// The state of one point: stress, plastic strain and back stresses (material axes).
struct GeneralPlasticityState {
  Vec3 stress = Vec3::Zero();  ///< (sxx, syy, sxy), MPa
  double eps_p = 0.0;          ///< equivalent plastic strain, -
  /// Back stresses alpha_i (tensor shear), MPa; those beyond the law's count stay zero.
  std::array<Vec3, kMaxBackStresses> back = zero_back_stresses();
};

/// The result of one strain increment.
struct GeneralPlasticityUpdate {
  GeneralPlasticityState state;  ///< the new state
  double d_ezz = 0.0;            ///< through-thickness strain increment, -
  bool plastic = false;          ///< true when the step was plastic
  /// Plastic work increment per unit volume, MPa: sigma_mid . d_eps^p (as PlaneStressUpdate).
  double d_plastic_work = 0.0;
  double d_eps_p = 0.0;  ///< the equivalent plastic strain increment d_lambda, -
  int iterations = 0;    ///< Newton iterations of the return (0 when elastic)
  /// MPa, the rate-free flow stress sigma_y(eps_p) at the new plastic strain (the store that
  /// flow_at_old reads back).
  double flow_stress = 0.0;
};

/// The law's constants.
struct GeneralPlasticity {
  double E = 0.0;   ///< Young's modulus, MPa
  double nu = 0.0;  ///< Poisson's ratio, -
  YieldCriterion criterion = VonMisesCriterion{};
  Hardening hardening = LinearHardening{};  ///< flow stress of the rolling direction, MPa
  KinematicHardening kinematic{};
  CowperSymonds rate{};  ///< off by default

  /// New state after the strain increment d_strain = (d_exx, d_eyy, d_gxy) in material axes.
  /// With `tangent`, also the consistent tangent d stress / d strain (MPa; engineering shear).
  /// Throws InstabilityError if the return mapping does not converge (the message gives the
  /// criterion, the trial stress and the residual).
  /// `flow_at_old`: the flow stress at old.eps_p when the caller knows it (MPa; a store of the
  /// last update's flow_stress), NaN to evaluate it.
  /// `dt`: the step's duration (s) for the rate dependence; 0 (a static step's pseudo-time, or
  /// no rate dependence) takes the rate-free flow stress.
  GeneralPlasticityUpdate update(const GeneralPlasticityState& old, const Vec3& d_strain,
                                 Mat3* tangent = nullptr,
                                 double flow_at_old = std::numeric_limits<double>::quiet_NaN(),
                                 double dt = 0.0) const;
  /// The same, a failure returned in `failure` instead of thrown (the element loop's form); the
  /// update is not to be used when failure.failed().
  GeneralPlasticityUpdate update_or_fail(
      const GeneralPlasticityState& old, const Vec3& d_strain, MaterialFailure& failure,
      Mat3* tangent = nullptr, double flow_at_old = std::numeric_limits<double>::quiet_NaN(),
      double dt = 0.0) const;
};

/// The element loops' handle on the law (material/plane_stress_kernels.hpp: point_kernel). Works
/// in the material axes; shell_section_update.hpp updates its points one at a time, with their
/// back stresses.
struct GeneralKernel {
  static constexpr bool kMaterialAxes = true;
  const GeneralPlasticity* law;
  double dt = 0.0;  ///< s, the step's duration for the rate dependence (0: rate-free)
};

/// Throws InputError naming `what` unless E > 0, -1 < nu < 0.5, the criterion and hardening are
/// admissible, and every back stress has C >= 0, gamma >= 0, both finite, count in
/// [0, kMaxBackStresses], and the rate dependence (if on) has finite D > 0 and q > 0.
void check_general_plasticity(const GeneralPlasticity& law, const char* what);

}  // namespace sf
