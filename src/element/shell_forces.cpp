#include "element/shell_forces.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>

#include "core/errors.hpp"
#include "element/shell_geometry.hpp"

namespace sf {

namespace {

// The element loop, instantiated once per material type (the variant is visited outside it).
template <class Law>
ShellForceResult compute_forces(const ShellPart& part, const Law& law, const Matrix3X& x,
                                const Matrix3X& v, const Matrix3X& omega, double dt, ShellState& st,
                                Matrix3X& f_int, Matrix3X& m_int) {
  const int n_el = static_cast<int>(part.quads.cols());
  const int np = part.section.n_points;
  const double shear_modulus = 0.5 * law.E / (1.0 + law.nu);
  const double ks_g = 5.0 / 6.0 * shear_modulus;  // shear correction factor 5/6
  const double c = plane_stress_wave_speed(law.E, law.nu, part.density);
  const double plate = law.E / (12.0 * (1.0 - law.nu * law.nu));  // D / t^3
  const double kappa = part.hourglass_coefficient;
  ShellForceResult result;

  for (int e = 0; e < n_el; ++e) {
    const Quad3 xe = gather_quad(x, part.quads, e);
    const Quad3 ve = gather_quad(v, part.quads, e);
    const Quad3 we = gather_quad(omega, part.quads, e);
    if (!ve.allFinite() || !we.allFinite()) {
      throw InstabilityError("shell element " + std::to_string(e) +
                             ": non-finite nodal velocity or angular velocity");
    }

    // 1. Velocity strains on the mid-step configuration (exact zero for a rigid rotation step).
    ShellGeometry gm;
    const Quad3 xm = xe - (0.5 * dt) * ve;
    compute_shell_geometry_or_throw(xm, e, "mid-step", gm);
    const Quad3 vl = gm.frame.transpose() * ve;
    const Quad3 wl = gm.frame.transpose() * we;
    const Row4 bx = gm.b.row(0);
    const Row4 by = gm.b.row(1);
    // Membrane (Mindlin: v^ = v^m - z e3 x theta^), eps(z) = eps_m - z kappa, engineering shear.
    const Vec3 d_m(bx.dot(vl.row(0)), by.dot(vl.row(1)), by.dot(vl.row(0)) + bx.dot(vl.row(1)));
    const Vec3 d_k(-bx.dot(wl.row(1)), by.dot(wl.row(0)), bx.dot(wl.row(0)) - by.dot(wl.row(1)));
    const double g_xz = bx.dot(vl.row(2)) + 0.25 * wl.row(1).sum();
    const double g_yz = by.dot(vl.row(2)) - 0.25 * wl.row(0).sum();

    // 2. Material update through the thickness, resultants N = int s dz, M = -int z s dz.
    const double t = st.thickness[e];
    Vec3 n_res = Vec3::Zero();
    Vec3 m_res = Vec3::Zero();
    double d_ezz_mean = 0.0;
    double work = 0.0;
    for (int k = 0; k < np; ++k) {
      const std::size_t i = static_cast<std::size_t>(e) * np + k;
      const double z = 0.5 * t * part.section.zeta[k];
      const double hw = 0.5 * t * part.section.weight[k];
      const Vec3 d_eps = dt * (d_m - z * d_k);
      typename Law::State old;
      old.stress = Vec3(st.sxx[i], st.syy[i], st.sxy[i]);
      old.eps_p = st.eps_p[i];
      const PlaneStressUpdate up = law.update(old, d_eps);
      st.sxx[i] = up.stress(0);
      st.syy[i] = up.stress(1);
      st.sxy[i] = up.stress(2);
      st.eps_p[i] = up.eps_p;
      n_res += hw * up.stress;
      m_res -= (hw * z) * up.stress;
      d_ezz_mean += 0.5 * part.section.weight[k] * up.d_ezz;
      work += hw * 0.5 * (old.stress + up.stress).dot(d_eps);
    }
    // Transverse shear: elastic, shear-corrected, constant through the thickness.
    const double sxz_old = st.sxz[e];
    const double syz_old = st.syz[e];
    st.sxz[e] = sxz_old + ks_g * dt * g_xz;
    st.syz[e] = syz_old + ks_g * dt * g_yz;
    const double q_x = t * st.sxz[e];
    const double q_y = t * st.syz[e];
    work += t * dt * 0.5 * ((sxz_old + st.sxz[e]) * g_xz + (syz_old + st.syz[e]) * g_yz);
    result.internal_work += gm.area * work;
    if (!n_res.allFinite() || !m_res.allFinite() || !std::isfinite(q_x + q_y)) {
      throw InstabilityError("shell element " + std::to_string(e) + ": non-finite stress");
    }
    // Thickness: plane stress gives d_ezz at each point; the mean over the thickness stretches it.
    st.thickness[e] = t * (1.0 + d_ezz_mean);

    // 3. Nodal forces and moments on the end-of-step configuration (conjugate to step 1).
    ShellGeometry g;
    compute_shell_geometry_or_throw(xe, e, "end of step", g);
    const double a = g.area;
    const Row4 gx = g.b.row(0);
    const Row4 gy = g.b.row(1);
    Quad3 fl;
    Quad3 ml;
    fl.row(0) = a * (n_res(0) * gx + n_res(2) * gy);
    fl.row(1) = a * (n_res(1) * gy + n_res(2) * gx);
    fl.row(2) = a * (q_x * gx + q_y * gy);
    ml.row(0) = a * (m_res(1) * gy + m_res(2) * gx);
    ml.row(0).array() -= 0.25 * a * q_y;
    ml.row(1) = a * (-m_res(0) * gx - m_res(2) * gy);
    ml.row(1).array() += 0.25 * a * q_x;
    ml.row(2).setZero();

    // 4. Viscous hourglass control on the end-of-step geometry, coefficients a = kappa/2 m w
    //    (m the nodal mass or inertia, w the highest frequency of that kind): see the docs.
    if (kappa > 0.0) {
      const Quad3 vh = g.frame.transpose() * ve;
      const Quad3 wh = g.frame.transpose() * we;
      const double m_node = 0.25 * part.density * t * a;
      const double i_node = rotational_inertia_factor(a, t) * m_node;
      const double a_m = 0.5 * kappa * m_node * 2.0 * c / std::sqrt(a);
      const double a_w = 0.5 * kappa * m_node * 4.0 * c * t / (std::sqrt(12.0) * a);
      const double a_r = 0.5 * kappa * std::sqrt(2.0 * plate * t * t * t * i_node);
      const double qx = g.gamma.dot(vh.row(0));
      const double qy = g.gamma.dot(vh.row(1));
      const double qz = g.gamma.dot(vh.row(2));
      const double rx = g.gamma.dot(wh.row(0));
      const double ry = g.gamma.dot(wh.row(1));
      fl.row(0) += (a_m * qx) * g.gamma;
      fl.row(1) += (a_m * qy) * g.gamma;
      fl.row(2) += (a_w * qz) * g.gamma;
      ml.row(0) += (a_r * rx) * g.gamma;
      ml.row(1) += (a_r * ry) * g.gamma;
      result.hourglass_power +=
          a_m * (qx * qx + qy * qy) + a_w * qz * qz + a_r * (rx * rx + ry * ry);
    }

    const Quad3 fg = g.frame * fl;
    const Quad3 mg = g.frame * ml;
    for (int i = 0; i < 4; ++i) {
      f_int.col(part.quads(i, e)) += fg.col(i);
      m_int.col(part.quads(i, e)) += mg.col(i);
    }
  }
  return result;
}

}  // namespace

ShellForceResult compute_shell_internal_forces(const ShellPart& part, const Matrix3X& x,
                                               const Matrix3X& v, const Matrix3X& omega, double dt,
                                               ShellState& state, Matrix3X& f_int,
                                               Matrix3X& m_int) {
  const auto n_nodes = x.cols();
  const auto n_el = part.quads.cols();
  if (v.cols() != n_nodes || omega.cols() != n_nodes || f_int.cols() != n_nodes ||
      m_int.cols() != n_nodes || state.n_points != part.section.n_points ||
      state.n_elements != n_el ||
      state.sxx.size() != static_cast<std::size_t>(n_el * part.section.n_points) ||
      state.thickness.size() != static_cast<std::size_t>(n_el)) {
    throw std::invalid_argument("compute_shell_internal_forces: inconsistent array sizes");
  }
  return std::visit(
      [&](const auto& law) {
        return compute_forces(part, law, x, v, omega, dt, state, f_int, m_int);
      },
      part.material);
}

}  // namespace sf
