#include <cstddef>

#include "element/element_loop.hpp"
#include "element/element_stages.hpp"
#include "element/shell_directors.hpp"
#include "element/shell_mass.hpp"
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

// The assumed-strain triangle as a formulation policy of the element loop (element_loop.hpp).
class AssumedStrainTriangle {
 public:
  static constexpr int kNodes = 3;
  using Nodes = Tri3;

  struct Element {
    TriangleGeometry mid;  // at x - dt/2 v
    TriangleGeometry end;  // at x
    Tri3 d_end;            // -, the directors at the end of the step
    Vec2 d_shear;          // -, the transverse shear strain increment
  };

  AssumedStrainTriangle(const ShellPart& /*part*/, const ShellMaterial& material, double E,
                        double nu, const ElementInputs& in, ShellState& st)
      : in_(in),
        directors_(st.director.data()),
        ks_g_(5.0 / 6.0 * 0.5 * E / (1.0 + nu)),  // shear correction factor 5/6
        wave_speed_(material_wave_speed(material)) {}

  SF_ELEMENT_STAGE void prepare(int /*e*/, int /*begin*/, int /*end*/) {}

  // Membrane strain from the velocities on the mid-step geometry; curvature and shear from the
  // change of the director measures over the step, in the mid-step frame. Turns the element's
  // directors by its nodes' turns (dt omega, found once per node: ElementInputs::turns).
  SF_ELEMENT_STAGE StageResult strains(int e, const int* nodes, const Tri3& xe, const Tri3& ve,
                                       const Tri3& /*we*/, Element& el, SectionStrains& s) const {
    const double dt = in_.dt;
    const Tri3 xm = xe - (0.5 * dt) * ve;
    const Tri3 xs = xe - dt * ve;
    if (!compute_triangle_geometry(xm, el.mid)) {
      return {ElementFailure::Kind::invalid_geometry, "mid-step"};
    }
    const TriangleGeometry& gm = el.mid;
    const Tri3 vl = gm.frame.transpose() * ve;
    const Vec3 d_membrane(gm.bx.dot(vl.row(0)), gm.by.dot(vl.row(1)),
                          gm.by.dot(vl.row(0)) + gm.bx.dot(vl.row(1)));
    Tri3 d_start;
    if (!advance_element_directors(directors_ + 3 * kDirectorNodes * static_cast<std::ptrdiff_t>(e),
                                   nodes, *in_.turns, d_start, el.d_end)) {
      return {ElementFailure::Kind::directors_not_set};
    }
    const TriangleDirectorMeasures start = compute_triangle_director_measures(xs, d_start);
    const TriangleDirectorMeasures end = compute_triangle_director_measures(xe, el.d_end);
    const Eigen::Matrix<double, 2, 3> shear_mid = compute_dsg3_weights(xm, gm.frame).weight;
    el.d_shear = shear_mid * Eigen::Vector3d(end.gap[0] - start.gap[0], end.gap[1] - start.gap[1],
                                             end.gap[2] - start.gap[2]);
    s.membrane = dt * d_membrane;
    s.curvature =
        to_cartesian_curvature(make_triangle_map(xm, gm.frame), end.curvature - start.curvature);
    return {};
  }

  SF_ELEMENT_STAGE double mid_area(const Element& el) const { return el.mid.area; }

  // Elastic, with the Lyly-Stenberg-Vihinen factor on the modulus.
  SF_ELEMENT_STAGE ShearUpdate transverse_shear(int e, double t, const Element& el,
                                                ShellState& st) const {
    const double shear_modulus = ks_g_ * triangle_shear_factor(t, el.mid.longest_side2);
    const Vec2 s_old(st.sxz[e], st.syz[e]);
    const Vec2 s_new = s_old + shear_modulus * el.d_shear;
    st.sxz[e] = s_new(0);
    st.syz[e] = s_new(1);
    return {s_new, t * 0.5 * (s_old + s_new).dot(el.d_shear)};
  }

  SF_ELEMENT_STAGE StageResult end_geometry(int /*e*/, const Tri3& xe, Element& el) const {
    return triangle_end_geometry(xe, el.mid, el.end);
  }

  SF_ELEMENT_STAGE double time_step(const Tri3& /*xe*/, const Element& el) const {
    return triangle_characteristic_length(el.end) / wave_speed_;
  }

  // Nodal forces and moments on the end-of-step configuration (conjugate to the strains).
  SF_ELEMENT_STAGE void forces(int /*e*/, double t, const Tri3& xe, const Tri3& /*ve*/,
                               const Tri3& /*we*/, const SectionStrains& /*strains*/,
                               const SectionResult& sr, const ShearUpdate& shear, const Element& el,
                               ShellState& /*st*/, double* corners,
                               ExactSum& /*hourglass_work*/) const {
    const TriangleGeometry& g = el.end;
    const double a = g.area;
    Tri3 fl;
    fl.row(0) = a * (sr.n(0) * g.bx + sr.n(2) * g.by);
    fl.row(1) = a * (sr.n(1) * g.by + sr.n(2) * g.bx);
    fl.row(2).setZero();
    Tri3 fg = g.frame * fl;
    Tri3 mg = Tri3::Zero();
    const Vec3 moment = to_covariant_moment(make_triangle_map(xe, g.frame), sr.m, a);
    const Vec2 shear_force = (a * t) * shear.stress;
    const Eigen::Matrix<double, 2, 3> shear_end = compute_dsg3_weights(xe, g.frame).weight;
    const Eigen::Vector3d gap_force = shear_end.transpose() * shear_force;
    const double gap[3] = {gap_force(0), gap_force(1), gap_force(2)};
    add_triangle_director_forces(xe, el.d_end, moment, gap, fg, mg);
    store_corners(fg, mg, corners);
  }

 private:
  const ElementInputs& in_;
  double* directors_;  // -, ShellState::director
  double ks_g_;        // MPa, shear-corrected shear modulus
  double wave_speed_;  // mm/s, for the time step
};

}  // namespace

void run_assumed_strain_triangles(const ElementBlock& block, const ShellPart& part,
                                  const ShellMaterial& material, const ElementInputs& in,
                                  ShellState& state, int begin, int end, ElementOutputs& out) {
  run_block_elements<AssumedStrainTriangle>(block, part, material, in, state, begin, end, out);
}

}  // namespace sf
