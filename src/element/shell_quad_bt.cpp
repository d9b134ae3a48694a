#include "element/shell_quad_bt.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "element/element_loop.hpp"
#include "element/element_stages.hpp"
#include "element/shell_geometry.hpp"
#include "element/shell_mass.hpp"

namespace sf {

namespace {

// Hourglass modes of the Belytschko-Lin-Tsay quad: in-plane x, y, out-of-plane, rotational x, y
// (stored in the first kBtModes of the element's kHourglassModes resultants).
constexpr int kBtModes = 5;

// The Belytschko-Lin-Tsay quad as a formulation policy of the element loop (element_loop.hpp).
class BtQuad {
 public:
  static constexpr int kNodes = 4;
  using Nodes = Quad3;

  struct Element {
    const ShellGeometry* mid = nullptr;  // at x - dt/2 v
    const ShellGeometry* end = nullptr;  // at x
    Quad3 xm;                            // mm, mid-step nodes
    Quad3 vl;                            // mm/s, velocities in the mid-step frame
    Quad3 wl;                            // rad/s, angular velocities in the mid-step frame
    double g_xz = 0.0;                   // 1/s, transverse shear strain rates
    double g_yz = 0.0;
  };

  BtQuad(const ShellPart& part, const ShellMaterial& material, double E, double nu,
         const ElementInputs& in, ShellState& /*st*/)
      : in_(in),
        geometry_(in, part.quads.data()),
        ks_g_(5.0 / 6.0 * (0.5 * E / (1.0 + nu))),  // shear correction factor 5/6
        c_(plane_stress_wave_speed(E, nu, material.density)),
        plate_(E / (12.0 * (1.0 - nu * nu))),  // D / t^3
        membrane_(E / (1.0 - nu * nu)),        // membrane stiffness / t
        kappa_(part.hourglass_coefficient),
        stiffness_form_(part.hourglass_form == HourglassForm::stiffness),
        density_(material.density),
        wave_speed_(material_wave_speed(material)) {}

  SF_ELEMENT_STAGE void prepare(int e, int begin, int end) { geometry_.prepare(e, begin, end); }

  // Velocity strains on the mid-step configuration (exact zero for a rigid rotation step).
  SF_ELEMENT_STAGE StageResult strains(int /*e*/, const int* /*nodes*/, const Quad3& xe,
                                       const Quad3& ve, const Quad3& we, Element& el,
                                       SectionStrains& s) const {
    const double dt = in_.dt;
    el.xm = xe - (0.5 * dt) * ve;
    if (const StageResult r = geometry_.mid(el.mid); !r.ok()) {
      return r;
    }
    const ShellGeometry& gm = *el.mid;
    el.vl = gm.frame.transpose() * ve;
    el.wl = gm.frame.transpose() * we;
    const Row4 bx = gm.b.row(0);
    const Row4 by = gm.b.row(1);
    Vec3 d_m;
    Vec3 d_k;
    compute_plate_strain_rates(bx, by, el.vl, el.wl, d_m, d_k);
    el.g_xz = bx.dot(el.vl.row(2)) + 0.25 * el.wl.row(1).sum();
    el.g_yz = by.dot(el.vl.row(2)) - 0.25 * el.wl.row(0).sum();
    s.membrane = dt * d_m;
    s.curvature = dt * d_k;
    return {};
  }

  SF_ELEMENT_STAGE double mid_area(const Element& el) const { return el.mid->area; }

  SF_ELEMENT_STAGE ShearUpdate transverse_shear(int e, double t, const Element& el,
                                                ShellState& st) const {
    const double dt = in_.dt;
    const double sxz_old = st.sxz[e];
    const double syz_old = st.syz[e];
    const double sxz_new = sxz_old + ks_g_ * dt * el.g_xz;
    const double syz_new = syz_old + ks_g_ * dt * el.g_yz;
    st.sxz[e] = sxz_new;
    st.syz[e] = syz_new;
    return {Vec2(sxz_new, syz_new),
            t * dt * 0.5 * ((sxz_old + sxz_new) * el.g_xz + (syz_old + syz_new) * el.g_yz)};
  }

  SF_ELEMENT_STAGE StageResult end_geometry(int /*e*/, const Quad3& /*xe*/, Element& el) const {
    return geometry_.end(el.end);
  }

  SF_ELEMENT_STAGE double time_step(const Quad3& xe, const Element& el) const {
    return quad_time_step(xe, el.end->area, wave_speed_);
  }

  // Nodal forces and moments on the end-of-step configuration (conjugate to the strains), and
  // the hourglass control.
  SF_ELEMENT_STAGE void forces(int e, double t, const Quad3& xe, const Quad3& ve, const Quad3& we,
                               const SectionStrains& /*strains*/, const SectionResult& sr,
                               const ShearUpdate& shear, const Element& el, ShellState& st,
                               double* corners, ExactSum& hourglass_work) const {
    const ShellGeometry& g = *el.end;
    const double q_x = t * shear.stress(0);
    const double q_y = t * shear.stress(1);
    const double a = g.area;
    const Row4 gx = g.b.row(0);
    const Row4 gy = g.b.row(1);
    Quad3 fl;
    Quad3 ml;
    fl.row(0) = a * (sr.n(0) * gx + sr.n(2) * gy);
    fl.row(1) = a * (sr.n(1) * gy + sr.n(2) * gx);
    fl.row(2) = a * (q_x * gx + q_y * gy);
    ml.row(0) = a * (sr.m(1) * gy + sr.m(2) * gx);
    ml.row(0).array() -= 0.25 * a * q_y;
    ml.row(1) = a * (-sr.m(0) * gx - sr.m(2) * gy);
    ml.row(1).array() += 0.25 * a * q_x;
    ml.row(2).setZero();
    if (kappa_ > 0.0) {
      add_hourglass_forces(e, t, xe, ve, we, el, st, fl, ml, hourglass_work);
    }
    const Quad3 fg = g.frame * fl;
    const Quad3 mg = g.frame * ml;
    store_corners(fg, mg, corners);
  }

 private:
  // Hourglass control on the end-of-step geometry (Flanagan & Belytschko 1981): hourglass rates
  // q = gamma . v of the in-plane (vx, vy), out-of-plane (vz) and rotational (thx, thy) modes,
  // nodal forces f_I = Q gamma_I. See docs/element-and-material.md for coefficients.
  SF_ELEMENT_STAGE void add_hourglass_forces(int e, double t, const Quad3& xe, const Quad3& ve,
                                             const Quad3& we, const Element& el, ShellState& st,
                                             Quad3& fl, Quad3& ml, ExactSum& hourglass_work) const {
    const ShellGeometry& g = *el.end;
    const ShellGeometry& gm = *el.mid;
    const double a = g.area;
    const Row4 gx = g.b.row(0);
    const Row4 gy = g.b.row(1);
    const Quad3 vh = g.frame.transpose() * ve;
    const Quad3 wh = g.frame.transpose() * we;
    // Warping correction (always on; no effect on flat elements): the nodes' offsets from the
    // projected plane are z_I = w h_I, so a rigid rotation about e1, e2 (rates B_y.v_z, -B_x.v_z)
    // moves the nodes in-plane by (omega_y z_I, -omega_x z_I), an in-plane hourglass pattern. That
    // part is removed from the in-plane hourglass rates: q_x = gamma.v_x + (gamma.z) B_x.v_z,
    // q_y = gamma.v_y + (gamma.z) B_y.v_z (Belytschko-Wong-Chiang 1992 idea); the forces below
    // are the transpose of this operator, so power = f.v stays exact. The stiffness form
    // integrates the rates into displacements, so it takes them on the mid-step configuration,
    // where a rigid rotation step is exactly skew (as the strains do); the viscous form takes them
    // on the end-of-step geometry (power = f.v exactly).
    const ShellGeometry& gr = stiffness_form_ ? gm : g;
    const Quad3& vr = stiffness_form_ ? el.vl : vh;
    const Quad3& wr = stiffness_form_ ? el.wl : wh;
    const Quad3& xr = stiffness_form_ ? el.xm : xe;
    const Vec3 e3 = gr.frame.col(2);
    const Vec3 centre = 0.25 * xr.rowwise().sum();
    const Row4 z = e3.transpose() * (xr.colwise() - centre);
    const double gz_r = gr.gamma.dot(z);
    const double q[kBtModes] = {gr.gamma.dot(vr.row(0)) + gz_r * gr.b.row(0).dot(vr.row(2)),
                                gr.gamma.dot(vr.row(1)) + gz_r * gr.b.row(1).dot(vr.row(2)),
                                gr.gamma.dot(vr.row(2)), gr.gamma.dot(wr.row(0)),
                                gr.gamma.dot(wr.row(1))};
    // Forces on the end-of-step geometry, the transpose of the (corrected) rate operator there.
    const double gz =
        stiffness_form_
            ? g.gamma.dot(g.frame.col(2).transpose() * (xe.colwise() - 0.25 * xe.rowwise().sum()))
            : gz_r;
    double res[kBtModes];
    double* hs = st.hourglass.data() + kHourglassModes * static_cast<std::ptrdiff_t>(e);
    const double power = stiffness_form_ ? stiffness_resultants(t, a, gx, gy, q, hs, res)
                                         : viscous_resultants(t, a, q, hs, res);
    fl.row(0) += res[0] * g.gamma;
    fl.row(1) += res[1] * g.gamma;
    fl.row(2) += res[2] * g.gamma + (res[0] * gz) * gx + (res[1] * gz) * gy;
    ml.row(0) += res[3] * g.gamma;
    ml.row(1) += res[4] * g.gamma;
    hourglass_work.add(in_.dt * power);
  }

  // Viscous: Q = a q, a = kappa/2 m w (m the nodal mass or inertia, w the highest frequency of
  // that kind). Its work over the step is taken as the driver takes the work of every force, on
  // the trapezoidal rule with the previous step's resultants (stored): 1/2 (Q_n + Q_n+1) q; with
  // a q^2 instead, a mode that alternates sign every step (the highest ones) would be counted as
  // dissipating what the trapezoidal element work does not see, and the internal energy, the rest
  // of that work, would go negative. Returns the power (N mm/s).
  SF_ELEMENT_STAGE double viscous_resultants(double t, double a, const double (&q)[kBtModes],
                                             double* hs, double (&res)[kBtModes]) const {
    const double m_node = 0.25 * density_ * t * a;
    const double i_node = rotational_inertia_factor(a, t) * m_node;
    double coef[kBtModes];
    coef[0] = 0.5 * kappa_ * m_node * 2.0 * c_ / std::sqrt(a);
    coef[1] = coef[0];
    coef[2] = 0.5 * kappa_ * m_node * 4.0 * c_ * t / (std::sqrt(12.0) * a);
    coef[3] = 0.5 * kappa_ * std::sqrt(2.0 * plate_ * t * t * t * i_node);
    coef[4] = coef[3];
    double power = 0.0;
    for (int mode = 0; mode < kBtModes; ++mode) {
      res[mode] = coef[mode] * q[mode];
      power += 0.5 * (hs[mode] + res[mode]) * q[mode];
      hs[mode] = res[mode];
    }
    return power;
  }

  // Stiffness: Q += k dt q (the hourglass displacement increment), stored in the corotational
  // frame; k scaled by the element's membrane and bending stiffness (|B|^2 = B_x.B_x + B_y.B_y).
  // Power of the mid-step resultant (trapezoidal, as the driver's work).
  SF_ELEMENT_STAGE double stiffness_resultants(double t, double a, const Row4& gx, const Row4& gy,
                                               const double (&q)[kBtModes], double* hs,
                                               double (&res)[kBtModes]) const {
    const double ab2 = a * (gx.squaredNorm() + gy.squaredNorm());  // 2 for a square
    const double d_plate = plate_ * t * t * t;
    double coef[kBtModes];
    coef[0] = 0.125 * kappa_ * membrane_ * t * ab2;
    coef[1] = coef[0];
    coef[2] = 0.25 * kappa_ * d_plate * ab2 * ab2 / a;
    coef[3] = 0.25 * kappa_ * d_plate * ab2;
    coef[4] = coef[3];
    double power = 0.0;
    for (int mode = 0; mode < kBtModes; ++mode) {
      const double old_res = hs[mode];
      res[mode] = old_res + coef[mode] * in_.dt * q[mode];
      hs[mode] = res[mode];
      power += 0.5 * (old_res + res[mode]) * q[mode];
    }
    return power;
  }

  const ElementInputs& in_;
  QuadGeometryStage geometry_;
  double ks_g_;      // MPa, shear-corrected shear modulus
  double c_;         // mm/s, plate wave speed (viscous hourglass)
  double plate_;     // MPa, D / t^3
  double membrane_;  // MPa, membrane stiffness / t
  double kappa_;     // -, hourglass coefficient
  bool stiffness_form_;
  double density_;     // tonne/mm^3
  double wave_speed_;  // mm/s, for the time step
};

}  // namespace

void run_bt_quads(const ElementBlock& block, const ShellPart& part, const ShellMaterial& material,
                  const ElementInputs& in, ShellState& state, int begin, int end,
                  ElementOutputs& out) {
  run_block_elements<BtQuad>(block, part, material, in, state, begin, end, out);
}

}  // namespace sf
