#include "element/shell_triangle.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <variant>

#include "element/corner_forces.hpp"
#include "element/shell_nodal_access.hpp"
#include "element/shell_section_update.hpp"
#include "element/shell_triangle_geometry.hpp"

namespace sf {

namespace {

// The triangle loop, instantiated once per material type (the variant is visited outside it).
template <class Law>
void compute_forces(const ShellPart& part, const ShellMaterial& material, const Law& law,
                    const ElementInputs& in, ShellState& st, int begin, int end,
                    ElementOutputs& out) {
  const Matrix3X& x = in.x;
  const double dt = in.dt;
  const int n_quads = static_cast<int>(part.quads.cols());
  const double* material_angle = part.material_angle.empty() ? nullptr : part.material_angle.data();
  const double ks_g = 5.0 / 6.0 * 0.5 * law.E / (1.0 + law.nu);  // shear correction factor 5/6
  const SectionConstants section = make_section_constants(part.section);
  const auto kernel = point_kernel(law, in.rate_dt());  // the material update's constants
  const int* conn = part.triangles.data();
  const double* xd = x.data();
  const double* vd = in.v.data();
  const double* wd = in.omega.data();

  for (int k = begin; k < end; ++k) {
    const int e = n_quads + k;  // index in the state arrays
    out.current = e;
    const int* nodes = conn + 3 * static_cast<std::ptrdiff_t>(k);
    Tri3 xe;
    Tri3 ve;
    Tri3 we;
    gather_nodes(xd, nodes, xe);
    gather_nodes(vd, nodes, ve);
    gather_nodes(wd, nodes, we);
    if (!ve.allFinite() || !we.allFinite()) {
      return out.fail(e, ElementFailure::Kind::non_finite_velocity, "", k);
    }

    // 1. Velocity strains on the mid-step configuration (exactly zero for a rigid rotation step:
    //    the central-difference velocity is skew there, and every operator below is exact for
    //    linear velocity fields and uniform angular velocity).
    TriangleGeometry gm;
    const Tri3 xm = xe - (0.5 * dt) * ve;
    if (!compute_triangle_geometry(xm, gm)) {
      return out.fail(e, ElementFailure::Kind::invalid_geometry, "mid-step", k);
    }
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
    out.internal_work.add(gm.area * work);
    out.plastic_work.add(gm.area * sr.plastic_work);
    if (!sr.n.allFinite() || !sr.m.allFinite() || !std::isfinite(q_x + q_y)) {
      return out.fail(e, ElementFailure::Kind::non_finite_stress, "", k);
    }
    st.thickness[e] = t * (1.0 + sr.d_ezz_mean);

    // 3. Nodal forces and moments on the end-of-step configuration (the transpose of step 1).
    TriangleGeometry g;
    if (!compute_triangle_geometry(xe, g)) {
      return out.fail(e, ElementFailure::Kind::invalid_geometry, "end of step", k);
    }
    if (!(g.frame.col(2).dot(gm.frame.col(2)) > 0.0)) {
      return out.fail(e, ElementFailure::Kind::inverted, "", k);
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
    store_corners(fg, mg,
                  out.corners + kCornerWidth * static_cast<std::ptrdiff_t>(
                                                   triangle_corner_slot(n_quads, k, 0)));
  }
}

}  // namespace

void compute_triangle_forces(const ShellPart& part, const ShellMaterial& material,
                             const ElementInputs& in, ShellState& state, int begin, int end,
                             ElementOutputs& out) {
  std::visit(
      [&](const auto& law) { compute_forces(part, material, law, in, state, begin, end, out); },
      material.law);
}

}  // namespace sf
