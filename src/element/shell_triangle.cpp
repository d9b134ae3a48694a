#include "element/shell_triangle.hpp"

#include <cstddef>

#include "element/element_loop.hpp"
#include "element/element_stages.hpp"
#include "element/shell_mass.hpp"
#include "element/shell_triangle_geometry.hpp"

namespace sf {

namespace {

// The C0 triangle as a formulation policy of the element loop (element_loop.hpp).
class C0Triangle {
 public:
  static constexpr int kNodes = 3;
  using Nodes = Tri3;

  struct Element {
    TriangleGeometry mid;  // at x - dt/2 v
    TriangleGeometry end;  // at x
    Vec2 g_s;              // 1/s, transverse shear strain rates
  };

  C0Triangle(const ShellPart& /*part*/, const ShellMaterial& material, double E, double nu,
             const ElementInputs& in, ShellState& /*st*/)
      : in_(in),
        ks_g_(5.0 / 6.0 * 0.5 * E / (1.0 + nu)),  // shear correction factor 5/6
        wave_speed_(material_wave_speed(material)) {}

  SF_ELEMENT_STAGE void prepare(int /*e*/, int /*begin*/, int /*end*/) {}

  // Velocity strains on the mid-step configuration (exactly zero for a rigid rotation step: the
  // central-difference velocity is skew there, and every operator below is exact for linear
  // velocity fields and uniform angular velocity).
  SF_ELEMENT_STAGE StageResult strains(int /*e*/, const int* /*nodes*/, const Tri3& xe,
                                       const Tri3& ve, const Tri3& we, Element& el,
                                       SectionStrains& s) const {
    const double dt = in_.dt;
    const Tri3 xm = xe - (0.5 * dt) * ve;
    if (!compute_triangle_geometry(xm, el.mid)) {
      return {ElementFailure::Kind::invalid_geometry, "mid-step"};
    }
    const TriangleGeometry& gm = el.mid;
    const Tri3 vl = gm.frame.transpose() * ve;
    const Tri3 wl = gm.frame.transpose() * we;
    // Mindlin, v^ = v^m - z e3 x theta^: eps(z) = eps_m - z kappa (engineering shear), as the
    // quad.
    Vec3 d_m;
    Vec3 d_k;
    compute_plate_strain_rates(gm.bx, gm.by, vl, wl, d_m, d_k);
    el.g_s = gm.sw * vl.row(2).transpose() + gm.sx * wl.row(0).transpose() +
             gm.sy * wl.row(1).transpose();
    s.membrane = dt * d_m;
    s.curvature = dt * d_k;
    return {};
  }

  SF_ELEMENT_STAGE double mid_area(const Element& el) const { return el.mid.area; }

  // Elastic, with the Lyly-Stenberg-Vihinen factor t^2 / (t^2 + alpha h^2) on the modulus.
  SF_ELEMENT_STAGE ShearUpdate transverse_shear(int e, double t, const Element& el,
                                                ShellState& st) const {
    const double dt = in_.dt;
    const double shear_modulus = ks_g_ * triangle_shear_factor(t, el.mid.longest_side2);
    const double sxz_old = st.sxz[e];
    const double syz_old = st.syz[e];
    const double sxz_new = sxz_old + shear_modulus * dt * el.g_s(0);
    const double syz_new = syz_old + shear_modulus * dt * el.g_s(1);
    st.sxz[e] = sxz_new;
    st.syz[e] = syz_new;
    return {Vec2(sxz_new, syz_new),
            t * dt * 0.5 * ((sxz_old + sxz_new) * el.g_s(0) + (syz_old + syz_new) * el.g_s(1))};
  }

  SF_ELEMENT_STAGE StageResult end_geometry(int /*e*/, const Tri3& xe, Element& el) const {
    return triangle_end_geometry(xe, el.mid, el.end);
  }

  SF_ELEMENT_STAGE double time_step(const Tri3& /*xe*/, const Element& el) const {
    return triangle_characteristic_length(el.end) / wave_speed_;
  }

  // Nodal forces and moments on the end-of-step configuration (the transpose of the strains).
  SF_ELEMENT_STAGE void forces(int /*e*/, double t, const Tri3& /*xe*/, const Tri3& /*ve*/,
                               const Tri3& /*we*/, const SectionStrains& /*strains*/,
                               const SectionResult& sr, const ShearUpdate& shear, const Element& el,
                               ShellState& /*st*/, double* corners,
                               ExactSum& /*hourglass_work*/) const {
    const TriangleGeometry& g = el.end;
    const double q_x = t * shear.stress(0);
    const double q_y = t * shear.stress(1);
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
    store_corners(fg, mg, corners);
  }

 private:
  const ElementInputs& in_;
  double ks_g_;        // MPa, shear-corrected shear modulus
  double wave_speed_;  // mm/s, for the time step
};

}  // namespace

void run_c0_triangles(const ElementBlock& block, const ShellPart& part,
                      const ShellMaterial& material, const ElementInputs& in, ShellState& state,
                      int begin, int end, ElementOutputs& out) {
  run_block_elements<C0Triangle>(block, part, material, in, state, begin, end, out);
}

}  // namespace sf
