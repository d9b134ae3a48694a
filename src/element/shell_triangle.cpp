#include "element/shell_triangle.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <variant>

#include "core/errors.hpp"
#include "element/shell_nodal_access.hpp"
#include "element/shell_section_update.hpp"
#include "element/shell_triangle_geometry.hpp"

namespace sf {

namespace {

std::string name_of(int element, int triangle) {
  return "shell element " + std::to_string(element) + " (triangle " + std::to_string(triangle) +
         ")";
}

// The triangle loop, instantiated once per material type (the variant is visited outside it).
template <class Law>
ShellForceResult compute_forces(const ShellPart& part, const Law& law, const Matrix3X& x,
                                const Matrix3X& v, const Matrix3X& omega, double dt, ShellState& st,
                                Matrix3X& f_int, Matrix3X& m_int) {
  const int n_quads = static_cast<int>(part.quads.cols());
  const int n_tri = static_cast<int>(part.triangles.cols());
  const double* material_angle = part.material_angle.empty() ? nullptr : part.material_angle.data();
  const double ks_g = 5.0 / 6.0 * 0.5 * law.E / (1.0 + law.nu);  // shear correction factor 5/6
  const SectionConstants section = make_section_constants(part.section);
  const auto kernel = point_kernel(law);  // the material update's constants
  const int* conn = part.triangles.data();
  const double* xd = x.data();
  const double* vd = v.data();
  const double* wd = omega.data();
  double* fd = f_int.data();
  double* md = m_int.data();
  ShellForceResult result;

  for (int k = 0; k < n_tri; ++k) {
    const int e = n_quads + k;  // index in the state arrays
    const int* nodes = conn + 3 * static_cast<std::ptrdiff_t>(k);
    Tri3 xe;
    Tri3 ve;
    Tri3 we;
    gather_nodes(xd, nodes, xe);
    gather_nodes(vd, nodes, ve);
    gather_nodes(wd, nodes, we);
    if (!ve.allFinite() || !we.allFinite()) {
      throw InstabilityError(name_of(e, k) + ": non-finite nodal velocity or angular velocity");
    }

    // 1. Velocity strains on the mid-step configuration (exactly zero for a rigid rotation step:
    //    the central-difference velocity is skew there, and every operator below is exact for
    //    linear velocity fields and uniform angular velocity).
    TriangleGeometry gm;
    const Tri3 xm = xe - (0.5 * dt) * ve;
    compute_triangle_geometry_or_throw(xm, e, k, "mid-step", gm);
    const Tri3 vl = gm.frame.transpose() * ve;
    const Tri3 wl = gm.frame.transpose() * we;
    // Mindlin, v^ = v^m - z e3 x theta^: eps(z) = eps_m - z kappa (engineering shear), as the quad.
    Vec3 d_m;
    Vec3 d_k;
    compute_plate_strain_rates(gm.bx, gm.by, vl, wl, d_m, d_k);
    const Vec2 g_s = gm.sw * vl.row(2).transpose() + gm.sx * wl.row(0).transpose() +
                     gm.sy * wl.row(1).transpose();
    const Vec3 dt_d_m = dt * d_m;
    const Vec3 dt_d_k = dt * d_k;

    // 2. Material update through the thickness (shell_section_update.hpp).
    const double t = st.thickness[e];
    const SectionResult sr =
        update_section(kernel, section, e, t, dt_d_m, dt_d_k, material_angle, st);
    double work = sr.work;
    // Transverse shear: elastic, shear-corrected, constant through the thickness, with the
    // Lyly-Stenberg-Vihinen factor t^2 / (t^2 + alpha h^2) on the modulus.
    const double shear_modulus = ks_g * triangle_shear_factor(t, gm.longest_side2);
    const double sxz_old = st.sxz[e];
    const double syz_old = st.syz[e];
    const double sxz_new = sxz_old + shear_modulus * dt * g_s(0);
    const double syz_new = syz_old + shear_modulus * dt * g_s(1);
    st.sxz[e] = sxz_new;
    st.syz[e] = syz_new;
    const double q_x = t * sxz_new;
    const double q_y = t * syz_new;
    work += t * dt * 0.5 * ((sxz_old + sxz_new) * g_s(0) + (syz_old + syz_new) * g_s(1));
    result.internal_work += gm.area * work;
    result.plastic_work += gm.area * sr.plastic_work;
    if (!sr.n.allFinite() || !sr.m.allFinite() || !std::isfinite(q_x + q_y)) {
      throw InstabilityError(name_of(e, k) + ": non-finite stress");
    }
    st.thickness[e] = t * (1.0 + sr.d_ezz_mean);

    // 3. Nodal forces and moments on the end-of-step configuration (the transpose of step 1).
    TriangleGeometry g;
    compute_triangle_geometry_or_throw(xe, e, k, "end of step", g);
    if (!(g.frame.col(2).dot(gm.frame.col(2)) > 0.0)) {
      throw InstabilityError(name_of(e, k) + ": inverted (the normal flipped within the step)");
    }
    const double a = g.area;
    Tri3 fl;
    Tri3 ml;
    fl.row(0) = a * (sr.n(0) * g.bx + sr.n(2) * g.by);
    fl.row(1) = a * (sr.n(1) * g.by + sr.n(2) * g.bx);
    fl.row(2) = a * (q_x * g.sw.row(0) + q_y * g.sw.row(1));
    ml.row(0) = a * (sr.m(1) * g.by + sr.m(2) * g.bx + q_x * g.sx.row(0) + q_y * g.sx.row(1));
    ml.row(1) = a * (-sr.m(0) * g.bx - sr.m(2) * g.by + q_x * g.sy.row(0) + q_y * g.sy.row(1));
    ml.row(2).setZero();
    const Tri3 fg = g.frame * fl;
    const Tri3 mg = g.frame * ml;
    scatter_add_nodes(fg, mg, nodes, fd, md);
  }
  return result;
}

}  // namespace

ShellForceResult compute_triangle_internal_forces(const ShellPart& part, const Matrix3X& x,
                                                  const Matrix3X& v, const Matrix3X& omega,
                                                  double dt, ShellState& state, Matrix3X& f_int,
                                                  Matrix3X& m_int) {
  if (part.triangles.cols() == 0) {
    return {};
  }
  return std::visit(
      [&](const auto& law) {
        return compute_forces(part, law, x, v, omega, dt, state, f_int, m_int);
      },
      part.material);
}

}  // namespace sf
