#include "element/shell_quad_assumed_strain.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <variant>

#include "core/errors.hpp"
#include "element/corner_forces.hpp"
#include "element/shell_directors.hpp"
#include "element/shell_geometry.hpp"
#include "element/shell_geometry_batch.hpp"
#include "element/shell_mass.hpp"
#include "element/shell_nodal_access.hpp"
#include "element/shell_quad_directors.hpp"
#include "element/shell_quad_hourglass.hpp"
#include "element/shell_quad_stabilization.hpp"
#include "element/shell_section_update.hpp"
#include "material/plane_stress.hpp"

namespace sf {

namespace {

// Per-part constants of the loop.
struct Constants {
  double young = 0.0;    ///< MPa
  double poisson = 0.0;  ///< -
  double ks_g = 0.0;     ///< MPa, shear-corrected shear modulus (factor 5/6)
  Mat3 hooke;            ///< MPa, plane-stress stiffness (engineering shear)
};

// The element's directors at the start and end of the step.
struct StepDirectors {
  Quad3 old_d;
  Quad3 new_d;
};

// The increments of the step (end minus start) of the director measures, in the mid-step frame.
struct BendingShearIncrements {
  Vec3 curvature;     ///< -, dt x curvature rate (1/mm), Cartesian: xx, yy, xy (engineering)
  Vec2 shear;         ///< -, transverse shear strain increment at the centre (xz, yz)
  Vec2 shear_linear;  ///< mm, of (e_A - e_C, e_B - e_D)
  Vec2 hourglass;     ///< rad, of the director hourglass amplitudes (frame components)
};

BendingShearIncrements compute_increments(const Quad3& x_start, const Quad3& x_end,
                                          const StepDirectors& d, const QuadBasis& mid,
                                          const CartesianMap& map) {
  const DirectorMeasures start = compute_director_measures(x_start, d.old_d, mid);
  const DirectorMeasures end = compute_director_measures(x_end, d.new_d, mid);
  double de[4];
  for (int k = 0; k < 4; ++k) {
    de[k] = end.edge[k] - start.edge[k];
  }
  BendingShearIncrements inc;
  inc.curvature = to_cartesian_curvature(map, end.curvature - start.curvature);
  inc.shear = map.p * (0.5 * (de[0] + de[1])) + map.r * (0.5 * (de[2] + de[3]));
  inc.shear_linear = Vec2(de[1] - de[0], de[3] - de[2]);
  const Vec2 dq = end.hourglass - start.hourglass;
  inc.hourglass = map.p * dq(0) + map.r * dq(1);
  return inc;
}

// The ratio (0..1] of the section's incremental stiffness to its elastic stiffness along the
// step's own strain increment: int ds . de dz / int de . C de dz, C the plane-stress Hooke
// matrix (de = dm - z dk: t dm.C dm + t^3/12 dk.C dk for a rule exact on quadratics; the
// 1-point rule's bending part is 0 and so is its sum). 1 in a step without plastic flow, so
// that elastic runs are unchanged to the bit.
double incremental_stiffness_ratio(const Constants& c, double t, const Vec3& dm, const Vec3& dk,
                                   const SectionResult& sr) {
  if (sr.plastic_work <= 0.0) {
    return 1.0;
  }
  const double elastic = t * dm.dot(c.hooke * dm) + t * t * t / 12.0 * dk.dot(c.hooke * dk);
  if (!(elastic > 0.0)) {
    return 1.0;
  }
  return std::clamp(sr.stress_change_work / elastic, 0.0, 1.0);
}

// The factor of a stabilisation part's elastic increment: `ratio` while the step loads it (its
// resultant does positive work on the increment), 1 while it unloads. So the part's stored
// energy 1/2 R.K^-1.R rises by at most the work done on it and falls by exactly that work: the
// stabilisation never gives back more than it stored (with the ratio on unloading too, a mode
// loaded elastically and unloaded while its element yields would release energy it never held).
// With StabilizationUnloading::as_loading the factor is `ratio` either way.
double loading_factor(StabilizationUnloading unloading, double ratio, double r0, double r1,
                      const Vec2& increment) {
  if (unloading == StabilizationUnloading::as_loading) {
    return ratio;
  }
  return r0 * increment(0) + r1 * increment(1) > 0.0 ? ratio : 1.0;
}

// Advances the stabilisation resultants hs (membrane 0, 1; bending 2, 3; shear 4, 5) by their
// stiffnesses times the step's increments; returns the work of the step (trapezoidal, N mm).
// The membrane and bending parts follow the section's incremental stiffness (`ratio`) as they
// load: in a yielding element they stiffen the hourglass modes as the material does.
double update_stabilization(const StabilizationStiffness& k, StabilizationUnloading unloading,
                            double ratio, const Vec2& membrane, const Vec2& bending,
                            const Vec2& shear, double* hs) {
  const Vec2 d_m =
      loading_factor(unloading, ratio, hs[0], hs[1], membrane) * (k.membrane * membrane);
  const Vec2 d_b = loading_factor(unloading, ratio, hs[2], hs[3], bending) * (k.bending * bending);
  const Vec2 d_s = k.shear.cwiseProduct(shear);
  const double increment[kHourglassModes] = {d_m(0), d_m(1), d_b(0), d_b(1), d_s(0), d_s(1)};
  const double strain[kHourglassModes] = {membrane(0), membrane(1), bending(0),
                                          bending(1),  shear(0),    shear(1)};
  double work = 0.0;
  for (int j = 0; j < kHourglassModes; ++j) {
    const double old_res = hs[j];
    hs[j] = old_res + increment[j];
    work += 0.5 * (old_res + hs[j]) * strain[j];
  }
  return work;
}

// The generalised resultants of the director measures on the end-of-step geometry: the bending
// moment and transverse shear resultants of the section and the stabilisation's.
DirectorResultants make_director_resultants(const CartesianMap& map, double area,
                                            const Vec3& moment, const Vec2& shear_force,
                                            const double* hs) {
  DirectorResultants r;
  r.curvature = to_covariant_moment(map, moment, area);
  const double along_xi = 0.5 * area * shear_force.dot(map.p);
  const double along_eta = 0.5 * area * shear_force.dot(map.r);
  r.edge[0] = along_xi - hs[4];
  r.edge[1] = along_xi + hs[4];
  r.edge[2] = along_eta - hs[5];
  r.edge[3] = along_eta + hs[5];
  const Vec2 q(hs[2], hs[3]);
  r.hourglass = Vec2(q.dot(map.p), q.dot(map.r));
  return r;
}

template <class Law>
void compute_forces(const ShellPart& part, const ShellMaterial& material, const Law& law,
                    const ElementInputs& in, ShellState& st, int begin, int end,
                    ElementOutputs& out) {
  const Matrix3X& x = in.x;
  const double dt = in.dt;
  const double wave_speed = material_wave_speed(material);  // mm/s, for the elements' time steps
  const Constants c{law.E, law.nu, 5.0 / 6.0 * 0.5 * law.E / (1.0 + law.nu),
                    plane_stress_stiffness(law.E, law.nu)};
  const SectionConstants section = make_section_constants(part.section);
  const auto kernel = point_kernel(law, in.rate_dt());  // the material update's constants
  const int* conn = part.quads.data();
  const double* material_angle = part.material_angle.empty() ? nullptr : part.material_angle.data();

  QuadGeometryBlock geometry;  // of the block of elements holding e
  for (int e = begin; e < end; ++e) {
    out.current = e;
    const int lane = (e - begin) % kBlockLanes;  // begin is a multiple of kBlockLanes
    if (lane == 0) {
      compute_quad_geometry_block(x.data(), in.v.data(), conn, e, std::min(kBlockLanes, end - e),
                                  dt, geometry);
    }
    const int* nodes = conn + 4 * static_cast<std::ptrdiff_t>(e);
    Quad3 xe;
    Quad3 ve;
    Quad3 we;
    gather_nodes(x.data(), nodes, xe);
    gather_nodes(in.v.data(), nodes, ve);
    gather_nodes(in.omega.data(), nodes, we);
    if (!ve.allFinite() || !we.allFinite()) {
      return out.fail(e, ElementFailure::Kind::non_finite_velocity);
    }

    // 1. Strain increments. Membrane: the one-point velocity strain on the mid-step geometry
    //    (exact zero for a rigid rotation step); curvature and transverse shear: the change of the
    //    director measures from the start to the end of the step, in the mid-step frame.
    const Quad3 xm = xe - (0.5 * dt) * ve;
    const Quad3 xs = xe - dt * ve;
    const ShellGeometry& gm = geometry.mid[lane];
    if (!geometry.mid_ok[lane]) {
      return out.fail(e, ElementFailure::Kind::invalid_geometry, "mid-step");
    }
    const Quad3 vl = gm.frame.transpose() * ve;
    const Vec3 d_membrane(gm.b.row(0).dot(vl.row(0)), gm.b.row(1).dot(vl.row(1)),
                          gm.b.row(1).dot(vl.row(0)) + gm.b.row(0).dot(vl.row(1)));
    StepDirectors d;
    advance_element_directors(
        st.director.data() + 3 * kDirectorNodes * static_cast<std::ptrdiff_t>(e), we, dt, e,
        d.old_d, d.new_d);
    const QuadBasis basis_mid = compute_quad_basis(xm);
    const CartesianMap map_mid = make_cartesian_map(basis_mid, gm.frame);
    const BendingShearIncrements inc = compute_increments(xs, xe, d, basis_mid, map_mid);

    // 2. Material update through the thickness; transverse shear elastic, shear-corrected,
    //    constant through the thickness.
    const double t = st.thickness[e];
    const SectionResult sr =
        update_section(kernel, section, e, t, dt * d_membrane, inc.curvature, material_angle, st);
    const Vec2 s_old(st.sxz[e], st.syz[e]);
    const Vec2 s_new = s_old + c.ks_g * inc.shear;
    st.sxz[e] = s_new(0);
    st.syz[e] = s_new(1);
    const double work = sr.work + t * 0.5 * (s_old + s_new).dot(inc.shear);
    out.internal_work.add(gm.area * work);
    out.plastic_work.add(gm.area * sr.plastic_work);
    if (!sr.n.allFinite() || !sr.m.allFinite() || !s_new.allFinite()) {
      return out.fail(e, ElementFailure::Kind::non_finite_stress);
    }
    st.thickness[e] = t * (1.0 + sr.d_ezz_mean);

    // 3. Stabilisation (shell_quad_stabilization.hpp): membrane from the warping-corrected
    //    hourglass rates on the mid-step geometry, bending and shear from the director measures.
    const double gz_mid = compute_warp(gm, xm);
    const Vec2 membrane_hg = dt * compute_membrane_hourglass_rates(gm, gz_mid, vl);
    const StabilizationStiffness k = compute_stabilization_stiffness(basis_mid, map_mid, gm.frame,
                                                                     c.young, c.poisson, t, c.ks_g);
    double* hs = st.hourglass.data() + kHourglassModes * static_cast<std::ptrdiff_t>(e);
    const double ratio = incremental_stiffness_ratio(c, t, dt * d_membrane, inc.curvature, sr);
    out.hourglass_work.add(update_stabilization(k, part.stabilization_unloading, ratio, membrane_hg,
                                                inc.hourglass, inc.shear_linear, hs));

    // 4. Nodal forces and moments on the end-of-step configuration (conjugate to step 1).
    const ShellGeometry& g = geometry.end[lane];
    if (!geometry.end_ok[lane]) {
      return out.fail(e, ElementFailure::Kind::invalid_geometry, "end of step");
    }
    if (out.element_dt) {
      out.element_dt[e] = quad_time_step(xe, g.area, wave_speed);  // the next step's bound, at x
    }
    const double a = g.area;
    Quad3 fl;
    fl.row(0) = a * (sr.n(0) * g.b.row(0) + sr.n(2) * g.b.row(1));
    fl.row(1) = a * (sr.n(1) * g.b.row(1) + sr.n(2) * g.b.row(0));
    fl.row(2).setZero();
    add_membrane_hourglass_forces(g, compute_warp(g, xe), Vec2(hs[0], hs[1]), fl);
    Quad3 fg = g.frame * fl;
    Quad3 mg = Quad3::Zero();
    const QuadBasis basis_end = compute_quad_basis(xe);
    const CartesianMap map_end = make_cartesian_map(basis_end, g.frame);
    const DirectorResultants r = make_director_resultants(map_end, a, sr.m, t * s_new, hs);
    add_director_forces(xe, d.new_d, basis_mid, r, fg, mg);
    store_corners(fg, mg, out.corners + kCornerWidth * 4 * static_cast<std::ptrdiff_t>(e));
  }
}

}  // namespace

void compute_assumed_strain_quad_forces(const ShellPart& part, const ShellMaterial& material,
                                        const ElementInputs& in, ShellState& state, int begin,
                                        int end, ElementOutputs& out) {
  std::visit(
      [&](const auto& law) { compute_forces(part, material, law, in, state, begin, end, out); },
      material.law);
}

}  // namespace sf
