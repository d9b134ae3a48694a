#pragma once
// The restraining and uplift force per unit length of a round drawbead, from its geometry and the
// sheet (docs/drawbeads.md): the sheet, rigid-plastic in plane strain, is drawn over the groove's
// entry shoulder, under the bead and over the exit shoulder. Each bend onto a radius and each
// unbend off it adds M / rho to the tension (M the plane-strain plastic moment per unit width, rho
// the radius of the mid-surface), and the friction over each arc multiplies it by exp(mu alpha)
// (Marciniak, Duncan & Hu, Mechanics of Sheet Metal Forming, 2nd ed. 2002, ch. 6, "bending and
// unbending under tension" and the drawbead example; the bending-plus-friction sequence of Nine
// 1978 and Stoughton 1988). The moment of each of the six bends is that of the hardening curve at
// the strain each fibre has gathered in the bends before it (isotropic hardening, no Bauschinger
// effect).
#include <functional>

namespace sf {

/// A round bead pressed into a groove with rounded shoulders (mm).
struct RoundBeadGeometry {
  double bead_radius = 0.0;      ///< R_b, the bead's crest radius
  double shoulder_radius = 0.0;  ///< R_s, the groove's shoulder radius (both shoulders)
  /// h, how far the bead's crest stands into the groove when the binder is closed: the depth of
  /// the sheet's mid-surface under the crest below its plane outside the bead
  double depth = 0.0;
  /// c, the side clearance: the bead's and a shoulder's centres are R_b + R_s + t + c apart
  /// across the bead (c = 0: the sheet is pinched between them at a 90 degree wrap)
  double clearance = 0.0;
};

/// The sheet drawn through the bead.
struct RoundBeadSheet {
  double thickness = 0.0;  ///< t, mm
  /// The uniaxial flow stress (MPa) at an equivalent plastic strain (-): the hardening curve
  std::function<double(double)> flow_stress;
  double friction = 0.0;  ///< Coulomb coefficient mu on the bead and the shoulders
};

/// The plastic moment per unit width (N mm / mm) of the k-th bend or unbend (k = 0..5: on the
/// entry shoulder, the bead, the exit shoulder, a bend then an unbend each), over mid-surface
/// radii rho_s and rho_b (mm): M_k = 2 int_0^{t/2} S(e_k(z)) z dz, S = 2/sqrt(3) sigma the
/// plane-strain flow stress (von Mises), e_k(z) = 2/sqrt(3) z (sum_{j<k} 1/rho_j + 1/(2 rho_k))
/// the fibre's equivalent strain gathered by the bends before and half of this one (Simpson's
/// rule, 64 intervals: exact for a linear hardening curve).
double round_bead_bend_moment(const RoundBeadSheet& sheet, double rho_s, double rho_b, int k);

/// What the sheet drawn through the bead does.
struct RoundBeadForces {
  double wrap_angle = 0.0;   ///< theta, rad: the arc on each shoulder (the bead's is 2 theta)
  double restraining = 0.0;  ///< N/mm: the tension the bead adds to the sheet drawn through it
  double uplift = 0.0;       ///< N/mm: the force the sheet pushes the bead out of the groove with
};

/// The wrap angle theta (rad) of the sheet's mid-surface on a shoulder: the line touching the
/// shoulder circle (radius R_s + t/2) and the bead circle (R_b + t/2) on opposite sides, the bead
/// centre `depth` lower relative to the shoulder's than at depth 0. Solves
/// a sin(theta) + (R - h) cos(theta) = R, R = R_s + R_b + t, a = R + c.
double round_bead_wrap_angle(const RoundBeadGeometry& bead, double thickness);

/// The forces of the sheet drawn steadily through the bead, with no tension before it. With
/// dT_k = M_k / rho_k for the six bends (rho = R + t/2; M_k = S t^2 / 4 for a constant flow
/// stress) and f = exp(mu theta), the spans' tensions are
///   T_1 = dT_0 f + dT_1                (entry shoulder: bend, arc theta, unbend),
///   T_2 = (T_1 + dT_2) f^2 + dT_3      (bead: bend, arc 2 theta, unbend),
///   T   = (T_2 + dT_4) f + dT_5        (exit shoulder): the restraining force;
/// the uplift is (T_1 + T_2) sin(theta), what the two spans pull the bead into the groove with.
/// Zero at theta = 0 (a bead that does not touch the sheet).
/// Throws InputError for a radius or thickness that is not > 0, a flow stress that is not > 0 at
/// zero strain, a negative depth, clearance or friction.
RoundBeadForces round_bead_forces(const RoundBeadGeometry& bead, const RoundBeadSheet& sheet);

}  // namespace sf
