#include <cstddef>
#include <string>
#include <variant>

#include "element/corner_forces.hpp"
#include "element/shell_directors.hpp"
#include "element/shell_nodal_access.hpp"
#include "element/shell_section_update.hpp"
#include "element/shell_triangle.hpp"
#include "element/shell_triangle_directors.hpp"
#include "element/shell_triangle_geometry.hpp"

namespace sf {

namespace {

// The Cartesian map of the triangle's natural basis (x_1 - x_0, x_2 - x_0) in `frame`.
CartesianMap make_triangle_map(const Tri3& x, const Mat3& frame) {
  const EdgeDual dual = compute_edge_dual(x.col(1) - x.col(0), x.col(2) - x.col(0));
  return {Vec2(dual.grad1.dot(frame.col(0)), dual.grad1.dot(frame.col(1))),
          Vec2(dual.grad2.dot(frame.col(0)), dual.grad2.dot(frame.col(1)))};
}

template <class Law>
void compute_forces(const ShellPart& part, const ShellMaterial& material, const Law& law,
                    const ElementInputs& in, ShellState& st, int first, int last,
                    ElementOutputs& out) {
  const Matrix3X& x = in.x;
  const double dt = in.dt;
  const int n_quads = static_cast<int>(part.quads.cols());
  const double* material_angle = part.material_angle.empty() ? nullptr : part.material_angle.data();
  const double ks_g = 5.0 / 6.0 * 0.5 * law.E / (1.0 + law.nu);  // shear correction factor 5/6
  const SectionConstants section = make_section_constants(part.section);
  const auto kernel = point_kernel(law, in.rate_dt());  // the material update's constants

  for (int k = first; k < last; ++k) {
    const int e = n_quads + k;  // index in the state arrays
    out.current = e;
    const int* nodes = part.triangles.data() + 3 * static_cast<std::ptrdiff_t>(k);
    Tri3 xe;
    Tri3 ve;
    Tri3 we;
    gather_nodes(x.data(), nodes, xe);
    gather_nodes(in.v.data(), nodes, ve);
    gather_nodes(in.omega.data(), nodes, we);
    if (!ve.allFinite() || !we.allFinite()) {
      return out.fail(e, ElementFailure::Kind::non_finite_velocity, "", k);
    }

    // 1. Membrane strain from the velocities on the mid-step geometry; curvature and shear from
    //    the change of the director measures over the step, in the mid-step frame.
    TriangleGeometry gm;
    const Tri3 xm = xe - (0.5 * dt) * ve;
    const Tri3 xs = xe - dt * ve;
    if (!compute_triangle_geometry(xm, gm)) {
      return out.fail(e, ElementFailure::Kind::invalid_geometry, "mid-step", k);
    }
    const Tri3 vl = gm.frame.transpose() * ve;
    const Vec3 d_membrane(gm.bx.dot(vl.row(0)), gm.by.dot(vl.row(1)),
                          gm.by.dot(vl.row(0)) + gm.bx.dot(vl.row(1)));
    Tri3 d_start;
    Tri3 d_end;
    advance_element_directors(
        st.director.data() + 3 * kDirectorNodes * static_cast<std::ptrdiff_t>(e), we, dt, e,
        d_start, d_end);
    const TriangleDirectorMeasures start = compute_triangle_director_measures(xs, d_start);
    const TriangleDirectorMeasures end = compute_triangle_director_measures(xe, d_end);
    const Vec3 d_curvature =
        to_cartesian_curvature(make_triangle_map(xm, gm.frame), end.curvature - start.curvature);
    const Eigen::Matrix<double, 2, 3> shear_mid = compute_dsg3_weights(xm, gm.frame).weight;
    const Vec2 d_shear =
        shear_mid * Eigen::Vector3d(end.gap[0] - start.gap[0], end.gap[1] - start.gap[1],
                                    end.gap[2] - start.gap[2]);

    // 2. Material update; transverse shear elastic with the Lyly-Stenberg-Vihinen factor.
    const double t = st.thickness[e];
    const SectionResult sr =
        update_section(kernel, section, e, t, dt * d_membrane, d_curvature, material_angle, st);
    const double shear_modulus = ks_g * triangle_shear_factor(t, gm.longest_side2);
    const Vec2 s_old(st.sxz[e], st.syz[e]);
    const Vec2 s_new = s_old + shear_modulus * d_shear;
    st.sxz[e] = s_new(0);
    st.syz[e] = s_new(1);
    out.internal_work.add(gm.area * (sr.work + t * 0.5 * (s_old + s_new).dot(d_shear)));
    out.plastic_work.add(gm.area * sr.plastic_work);
    if (!sr.n.allFinite() || !sr.m.allFinite() || !s_new.allFinite()) {
      return out.fail(e, ElementFailure::Kind::non_finite_stress, "", k);
    }
    st.thickness[e] = t * (1.0 + sr.d_ezz_mean);

    // 3. Nodal forces and moments on the end-of-step configuration (conjugate to step 1).
    TriangleGeometry g;
    if (!compute_triangle_geometry(xe, g)) {
      return out.fail(e, ElementFailure::Kind::invalid_geometry, "end of step", k);
    }
    if (!(g.frame.col(2).dot(gm.frame.col(2)) > 0.0)) {
      return out.fail(e, ElementFailure::Kind::inverted, "", k);
    }
    const double a = g.area;
    Tri3 fl;
    fl.row(0) = a * (sr.n(0) * g.bx + sr.n(2) * g.by);
    fl.row(1) = a * (sr.n(1) * g.by + sr.n(2) * g.bx);
    fl.row(2).setZero();
    Tri3 fg = g.frame * fl;
    Tri3 mg = Tri3::Zero();
    const Vec3 moment = to_covariant_moment(make_triangle_map(xe, g.frame), sr.m, a);
    const Vec2 shear_force = (a * t) * s_new;
    const Eigen::Matrix<double, 2, 3> shear_end = compute_dsg3_weights(xe, g.frame).weight;
    const Eigen::Vector3d gap_force = shear_end.transpose() * shear_force;
    const double gap[3] = {gap_force(0), gap_force(1), gap_force(2)};
    add_triangle_director_forces(xe, d_end, moment, gap, fg, mg);
    store_corners(fg, mg,
                  out.corners + kCornerWidth * static_cast<std::ptrdiff_t>(
                                                   triangle_corner_slot(n_quads, k, 0)));
  }
}

}  // namespace

void compute_assumed_strain_triangle_forces(const ShellPart& part, const ShellMaterial& material,
                                            const ElementInputs& in, ShellState& state, int begin,
                                            int end, ElementOutputs& out) {
  std::visit(
      [&](const auto& law) { compute_forces(part, material, law, in, state, begin, end, out); },
      material.law);
}

}  // namespace sf
