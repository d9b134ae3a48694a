#include "element/shell_quad_assumed_strain.hpp"

#include <algorithm>
#include <cstddef>

#include "element/element_loop.hpp"
#include "element/element_stages.hpp"
#include "element/shell_directors.hpp"
#include "element/shell_geometry.hpp"
#include "element/shell_mass.hpp"
#include "element/shell_quad_directors.hpp"
#include "element/shell_quad_hourglass.hpp"
#include "element/shell_quad_stabilization.hpp"
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

// end_gradients: the gradients of the end-of-step directors, which the forces use again.
BendingShearIncrements compute_increments(const Quad3& x_start, const Quad3& x_end,
                                          const StepDirectors& d, const QuadBasis& mid,
                                          const CartesianMap& map,
                                          QuadDirectorGradients& end_gradients) {
  end_gradients = compute_director_gradients(d.new_d);
  const DirectorMeasures start =
      compute_director_measures(x_start, d.old_d, compute_director_gradients(d.old_d), mid);
  const DirectorMeasures end = compute_director_measures(x_end, d.new_d, end_gradients, mid);
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

// The assumed-strain quad as a formulation policy of the element loop (element_loop.hpp).
class AssumedStrainQuad {
 public:
  static constexpr int kNodes = 4;
  using Nodes = Quad3;

  struct Element {
    const ShellGeometry* mid = nullptr;  // at x - dt/2 v
    const ShellGeometry* end = nullptr;  // at x
    Quad3 xm;                            // mm, mid-step nodes
    Quad3 vl;                            // mm/s, velocities in the mid-step frame
    StepDirectors d;
    QuadDirectorGradients end_gradients;  // of d.new_d
    QuadBasis basis_mid;
    CartesianMap map_mid;
    BendingShearIncrements inc;
  };

  AssumedStrainQuad(const ShellPart& part, const ShellMaterial& material, double E, double nu,
                    const ElementInputs& in, ShellState& st)
      : in_(in),
        geometry_(in, part.quads.data()),
        directors_(st.director.data()),
        unloading_(part.stabilization_unloading),
        wave_speed_(material_wave_speed(material)),
        c_{E, nu, 5.0 / 6.0 * 0.5 * E / (1.0 + nu), plane_stress_stiffness(E, nu)} {}

  SF_ELEMENT_STAGE void prepare(int e, int begin, int end) { geometry_.prepare(e, begin, end); }

  // Membrane: the one-point velocity strain on the mid-step geometry (exact zero for a rigid
  // rotation step); curvature and transverse shear: the change of the director measures from the
  // start to the end of the step, in the mid-step frame. Turns the element's directors by its
  // nodes' turns (dt omega, found once per node: ElementInputs::turns).
  SF_ELEMENT_STAGE StageResult strains(int e, const int* nodes, const Quad3& xe, const Quad3& ve,
                                       const Quad3& /*we*/, Element& el, SectionStrains& s) {
    const double dt = in_.dt;
    el.xm = xe - (0.5 * dt) * ve;
    const Quad3 xs = xe - dt * ve;
    if (const StageResult r = geometry_.mid(el.mid); !r.ok()) {
      return r;
    }
    const ShellGeometry& gm = *el.mid;
    el.vl = gm.frame.transpose() * ve;
    const Vec3 d_membrane(gm.b.row(0).dot(el.vl.row(0)), gm.b.row(1).dot(el.vl.row(1)),
                          gm.b.row(1).dot(el.vl.row(0)) + gm.b.row(0).dot(el.vl.row(1)));
    if (!advance_element_directors(directors_ + 3 * kDirectorNodes * static_cast<std::ptrdiff_t>(e),
                                   nodes, *in_.turns, el.d.old_d, el.d.new_d)) {
      return {ElementFailure::Kind::directors_not_set};
    }
    el.basis_mid = compute_quad_basis(el.xm);
    el.map_mid = make_cartesian_map(el.basis_mid, gm.frame);
    el.inc = compute_increments(xs, xe, el.d, el.basis_mid, el.map_mid, el.end_gradients);
    s.membrane = dt * d_membrane;
    s.curvature = el.inc.curvature;
    return {};
  }

  SF_ELEMENT_STAGE double mid_area(const Element& el) const { return el.mid->area; }

  SF_ELEMENT_STAGE ShearUpdate transverse_shear(int e, double t, const Element& el,
                                                ShellState& st) const {
    const Vec2 s_old(st.sxz[e], st.syz[e]);
    const Vec2 s_new = s_old + c_.ks_g * el.inc.shear;
    st.sxz[e] = s_new(0);
    st.syz[e] = s_new(1);
    return {s_new, t * 0.5 * (s_old + s_new).dot(el.inc.shear)};
  }

  SF_ELEMENT_STAGE StageResult end_geometry(int /*e*/, const Quad3& /*xe*/, Element& el) const {
    return geometry_.end(el.end);
  }

  SF_ELEMENT_STAGE double time_step(const Quad3& xe, const Element& el) const {
    return quad_time_step(xe, el.end->area, wave_speed_);
  }

  // The stabilisation (shell_quad_stabilization.hpp): membrane from the warping-corrected
  // hourglass rates on the mid-step geometry, bending and shear from the director measures. Then
  // the nodal forces and moments on the end-of-step configuration (conjugate to the strains).
  SF_ELEMENT_STAGE void forces(int e, double t, const Quad3& xe, const Quad3& /*ve*/,
                               const Quad3& /*we*/, const SectionStrains& strains,
                               const SectionResult& sr, const ShearUpdate& shear, const Element& el,
                               ShellState& st, double* corners, ExactSum& hourglass_work) const {
    const ShellGeometry& gm = *el.mid;
    const double gz_mid = compute_warp(gm, el.xm);
    const Vec2 membrane_hg = in_.dt * compute_membrane_hourglass_rates(gm, gz_mid, el.vl);
    const StabilizationStiffness k = compute_stabilization_stiffness(
        el.basis_mid, el.map_mid, gm.frame, c_.young, c_.poisson, t, c_.ks_g);
    double* hs = st.hourglass.data() + kHourglassModes * static_cast<std::ptrdiff_t>(e);
    const double ratio =
        incremental_stiffness_ratio(c_, t, strains.membrane, strains.curvature, sr);
    hourglass_work.add(update_stabilization(k, unloading_, ratio, membrane_hg, el.inc.hourglass,
                                            el.inc.shear_linear, hs));

    const ShellGeometry& g = *el.end;
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
    const DirectorResultants r = make_director_resultants(map_end, a, sr.m, t * shear.stress, hs);
    add_director_forces(xe, el.d.new_d, el.end_gradients, el.basis_mid, r, fg, mg);
    store_corners(fg, mg, corners);
  }

 private:
  const ElementInputs& in_;
  QuadGeometryStage geometry_;
  double* directors_;  // -, ShellState::director
  StabilizationUnloading unloading_;
  double wave_speed_;  // mm/s, for the time step
  Constants c_;
};

}  // namespace

void run_assumed_strain_quads(const ElementBlock& block, const ShellPart& part,
                              const ShellMaterial& material, const ElementInputs& in,
                              ShellState& state, int begin, int end, ElementOutputs& out) {
  run_block_elements<AssumedStrainQuad>(block, part, material, in, state, begin, end, out);
}

}  // namespace sf
