#include "element/shell_quad_bt.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <variant>

#include "element/corner_forces.hpp"
#include "element/shell_geometry.hpp"
#include "element/shell_geometry_batch.hpp"
#include "element/shell_mass.hpp"
#include "element/shell_nodal_access.hpp"
#include "element/shell_section_update.hpp"

namespace sf {

namespace {

// Hourglass modes of the Belytschko-Lin-Tsay quad: in-plane x, y, out-of-plane, rotational x, y
// (stored in the first kBtModes of the element's kHourglassModes resultants).
constexpr int kBtModes = 5;

// The element loop, instantiated once per material type (the variant is visited outside it).
template <class Law>
void compute_forces(const ShellPart& part, const ShellMaterial& material, const Law& law,
                    const ElementInputs& in, ShellState& st, int begin, int end,
                    ElementOutputs& out) {
  const Matrix3X& x = in.x;
  const double dt = in.dt;
  const double shear_modulus = 0.5 * law.E / (1.0 + law.nu);
  const double ks_g = 5.0 / 6.0 * shear_modulus;  // shear correction factor 5/6
  const double c = plane_stress_wave_speed(law.E, law.nu, material.density);
  const double plate = law.E / (12.0 * (1.0 - law.nu * law.nu));  // D / t^3
  const double membrane = law.E / (1.0 - law.nu * law.nu);        // membrane stiffness / t
  const double kappa = part.hourglass_coefficient;
  const bool stiffness_form = part.hourglass_form == HourglassForm::stiffness;
  const SectionConstants section = make_section_constants(part.section);
  const auto kernel = point_kernel(law, in.rate_dt());  // the material update's constants
  const int* conn = part.quads.data();
  const double* xd = x.data();
  const double* vd = in.v.data();
  const double* wd = in.omega.data();
  double* hg_state = st.hourglass.data();
  const double* material_angle = part.material_angle.empty() ? nullptr : part.material_angle.data();
  const double wave_speed = material_wave_speed(material);  // mm/s, for the elements' time steps

  QuadGeometryBlock geometry;  // of the block of elements holding e
  for (int e = begin; e < end; ++e) {
    out.current = e;
    const int lane = (e - begin) % kBlockLanes;  // begin is a multiple of kBlockLanes
    if (lane == 0) {
      compute_quad_geometry_block(xd, vd, conn, e, std::min(kBlockLanes, end - e), dt, geometry);
    }
    const int* nodes = conn + 4 * static_cast<std::ptrdiff_t>(e);
    Quad3 xe;
    Quad3 ve;
    Quad3 we;
    gather_nodes(xd, nodes, xe);
    gather_nodes(vd, nodes, ve);
    gather_nodes(wd, nodes, we);
    if (!ve.allFinite() || !we.allFinite()) {
      return out.fail(e, ElementFailure::Kind::non_finite_velocity);
    }

    // 1. Velocity strains on the mid-step configuration (exact zero for a rigid rotation step).
    const Quad3 xm = xe - (0.5 * dt) * ve;
    const ShellGeometry& gm = geometry.mid[lane];
    if (!geometry.mid_ok[lane]) {
      return out.fail(e, ElementFailure::Kind::invalid_geometry, "mid-step");
    }
    const Quad3 vl = gm.frame.transpose() * ve;
    const Quad3 wl = gm.frame.transpose() * we;
    const Row4 bx = gm.b.row(0);
    const Row4 by = gm.b.row(1);
    Vec3 d_m;
    Vec3 d_k;
    compute_plate_strain_rates(bx, by, vl, wl, d_m, d_k);
    const double g_xz = bx.dot(vl.row(2)) + 0.25 * wl.row(1).sum();
    const double g_yz = by.dot(vl.row(2)) - 0.25 * wl.row(0).sum();
    const Vec3 dt_d_m = dt * d_m;
    const Vec3 dt_d_k = dt * d_k;

    // 2. Material update through the thickness (shell_section_update.hpp).
    const double t = st.thickness[e];
    const SectionResult sr =
        update_section(kernel, section, e, t, dt_d_m, dt_d_k, material_angle, st);
    double work = sr.work;
    // Transverse shear: elastic, shear-corrected, constant through the thickness.
    const double sxz_old = st.sxz[e];
    const double syz_old = st.syz[e];
    const double sxz_new = sxz_old + ks_g * dt * g_xz;
    const double syz_new = syz_old + ks_g * dt * g_yz;
    st.sxz[e] = sxz_new;
    st.syz[e] = syz_new;
    const double q_x = t * sxz_new;
    const double q_y = t * syz_new;
    work += t * dt * 0.5 * ((sxz_old + sxz_new) * g_xz + (syz_old + syz_new) * g_yz);
    out.internal_work.add(gm.area * work);
    out.plastic_work.add(gm.area * sr.plastic_work);
    if (!sr.n.allFinite() || !sr.m.allFinite() || !std::isfinite(q_x + q_y)) {
      return out.fail(e, ElementFailure::Kind::non_finite_stress);
    }
    // Thickness: plane stress gives d_ezz at each point; the mean over the thickness stretches
    // it.
    st.thickness[e] = t * (1.0 + sr.d_ezz_mean);

    // 3. Nodal forces and moments on the end-of-step configuration (conjugate to step 1).
    const ShellGeometry& g = geometry.end[lane];
    if (!geometry.end_ok[lane]) {
      return out.fail(e, ElementFailure::Kind::invalid_geometry, "end of step");
    }
    if (out.element_dt) {
      out.element_dt[e] = quad_time_step(xe, g.area, wave_speed);  // the next step's bound, at x
    }
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

    // 4. Hourglass control on the end-of-step geometry (Flanagan & Belytschko 1981): hourglass
    //    rates q = gamma . v of the in-plane (vx, vy), out-of-plane (vz) and rotational (thx,
    //    thy) modes, nodal forces f_I = Q gamma_I. See docs/element-and-material.md for
    //    coefficients.
    if (kappa > 0.0) {
      const Quad3 vh = g.frame.transpose() * ve;
      const Quad3 wh = g.frame.transpose() * we;
      // Warping correction (always on; no effect on flat elements): the nodes' offsets from the
      // projected plane are z_I = w h_I, so a rigid rotation about e1, e2 (rates B_y.v_z,
      // -B_x.v_z) moves the nodes in-plane by (omega_y z_I, -omega_x z_I), an in-plane hourglass
      // pattern. That part is removed from the in-plane hourglass rates: q_x = gamma.v_x +
      // (gamma.z) B_x.v_z, q_y = gamma.v_y + (gamma.z) B_y.v_z (Belytschko-Wong-Chiang 1992 idea);
      // the forces below are the transpose of this operator, so power = f.v stays exact.
      // The stiffness form integrates the rates into displacements, so it takes them on the
      // mid-step configuration, where a rigid rotation step is exactly skew (as the strains do);
      // the viscous form takes them on the end-of-step geometry (power = f.v exactly).
      const ShellGeometry& gr = stiffness_form ? gm : g;
      const Quad3& vr = stiffness_form ? vl : vh;
      const Quad3& wr = stiffness_form ? wl : wh;
      const Quad3& xr = stiffness_form ? xm : xe;
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
          stiffness_form
              ? g.gamma.dot(g.frame.col(2).transpose() * (xe.colwise() - 0.25 * xe.rowwise().sum()))
              : gz_r;
      double coef[kBtModes];
      double res[kBtModes];
      double power = 0.0;
      double* hs = hg_state + kHourglassModes * static_cast<std::ptrdiff_t>(e);
      if (!stiffness_form) {
        // Viscous: Q = a q, a = kappa/2 m w (m the nodal mass or inertia, w the highest
        // frequency of that kind). Its work over the step is taken as the driver takes the work
        // of every force, on the trapezoidal rule with the previous step's resultants (stored):
        // 1/2 (Q_n + Q_n+1) q; with a q^2 instead, a mode that alternates sign every step (the
        // highest ones) would be counted as dissipating what the trapezoidal element work does
        // not see, and the internal energy, the rest of that work, would go negative.
        const double m_node = 0.25 * material.density * t * a;
        const double i_node = rotational_inertia_factor(a, t) * m_node;
        coef[0] = 0.5 * kappa * m_node * 2.0 * c / std::sqrt(a);
        coef[1] = coef[0];
        coef[2] = 0.5 * kappa * m_node * 4.0 * c * t / (std::sqrt(12.0) * a);
        coef[3] = 0.5 * kappa * std::sqrt(2.0 * plate * t * t * t * i_node);
        coef[4] = coef[3];
        for (int mode = 0; mode < kBtModes; ++mode) {
          res[mode] = coef[mode] * q[mode];
          power += 0.5 * (hs[mode] + res[mode]) * q[mode];
          hs[mode] = res[mode];
        }
      } else {
        // Stiffness: Q += k dt q (the hourglass displacement increment), stored in the
        // corotational frame; k scaled by the element's membrane and bending stiffness (|B|^2 =
        // B_x.B_x + B_y.B_y). Power of the mid-step resultant (trapezoidal, as the driver's
        // work).
        const double ab2 = a * (gx.squaredNorm() + gy.squaredNorm());  // 2 for a square
        const double d_plate = plate * t * t * t;
        coef[0] = 0.125 * kappa * membrane * t * ab2;
        coef[1] = coef[0];
        coef[2] = 0.25 * kappa * d_plate * ab2 * ab2 / a;
        coef[3] = 0.25 * kappa * d_plate * ab2;
        coef[4] = coef[3];
        for (int mode = 0; mode < kBtModes; ++mode) {
          const double old_res = hs[mode];
          res[mode] = old_res + coef[mode] * dt * q[mode];
          hs[mode] = res[mode];
          power += 0.5 * (old_res + res[mode]) * q[mode];
        }
      }
      fl.row(0) += res[0] * g.gamma;
      fl.row(1) += res[1] * g.gamma;
      fl.row(2) += res[2] * g.gamma + (res[0] * gz) * gx + (res[1] * gz) * gy;
      ml.row(0) += res[3] * g.gamma;
      ml.row(1) += res[4] * g.gamma;
      out.hourglass_work.add(dt * power);
    }

    const Quad3 fg = g.frame * fl;
    const Quad3 mg = g.frame * ml;
    store_corners(fg, mg, out.corners + kCornerWidth * 4 * static_cast<std::ptrdiff_t>(e));
  }
}

}  // namespace

void compute_bt_quad_forces(const ShellPart& part, const ShellMaterial& material,
                            const ElementInputs& in, ShellState& state, int begin, int end,
                            ElementOutputs& out) {
  std::visit(
      [&](const auto& law) { compute_forces(part, material, law, in, state, begin, end, out); },
      material.law);
}

}  // namespace sf
