#pragma once
// The element loop, written once for every block (issue 34, item 1): each element of a range of
// one block goes through the same pipeline, and a formulation policy supplies the stages that
// differ between formulations. The policies are the Belytschko-Lin-Tsay quad (shell_quad_bt.cpp),
// the assumed-strain quad (shell_quad_assumed_strain.cpp), the C0 triangle (shell_triangle.cpp)
// and the assumed-strain triangle (shell_triangle_assumed_strain.cpp).
//
// The pipeline of one element e:
//   1. gather its nodes' x (end of step, mm), v (mid-step, mm/s) and omega (mid-step, rad/s);
//   2. policy.strains: the mid-step geometry and frame, the section's strain increments;
//   3. the section update through the thickness (shell_section_update.hpp), the material law;
//   4. policy.transverse_shear: the shear stresses and their work;
//   5. the works summed, the stresses checked, the thickness stretched;
//   6. policy.end_geometry: the end-of-step geometry (the forces' configuration);
//   7. policy.time_step: the element's critical step at x, when the pass wants it;
//   8. policy.forces: stabilisation or hourglass control, the corner forces and moments.
// A failure at any stage is a code recorded in the share's outputs (element_failure.hpp); the
// loop stops there.
//
// A policy F provides: kNodes and Nodes (Eigen 3 x kNodes); a per-element struct F::Element
// carried from stage to stage; prepare(e, begin, end) before each element (the quads compute
// their geometries kBlockLanes elements at a time); and the stages
//   StageResult strains(e, nodes, xe, ve, we, Element&, SectionStrains&)
//   double mid_area(const Element&)                      mm^2, the work's area
//   ShearUpdate transverse_shear(e, t, Element&, ShellState&)
//   StageResult end_geometry(e, xe, Element&)
//   double time_step(xe, const Element&)                 s
//   void forces(e, t, xe, ve, we, strains, sr, shear, Element&, ShellState&, corners,
//               hourglass_work)
// with t the thickness at the start of the step (mm).
#include <cmath>
#include <variant>

#include "core/exact_sum.hpp"
#include "core/types.hpp"
#include "element/corner_forces.hpp"
#include "element/element_block.hpp"
#include "element/element_pass.hpp"
#include "element/shell_nodal_access.hpp"
#include "element/shell_section_update.hpp"

/// Marks a policy's stages: they are inlined into the loop, one function per policy and material
/// law as the separate kernels were. GCC keeps a large member function called from several
/// instantiations out of line, and the element's working data then goes through memory (the
/// assumed-strain quad ran 4-8 % slower so).
#define SF_ELEMENT_STAGE [[gnu::always_inline]] inline

namespace sf {

/// Whether every entry of m is finite: Eigen's allFinite, written as a loop the compiler inlines
/// (Eigen's unroller was kept out of line in the loop and cost the assumed-strain quad 5 %).
template <int R, int C>
SF_ELEMENT_STAGE bool all_finite(const Eigen::Matrix<double, R, C>& m) {
  bool finite = true;
  for (int i = 0; i < R * C; ++i) {
    finite = finite && std::isfinite(m.data()[i]);
  }
  return finite;
}

/// How a policy's stage ended: ok, or the failure the loop records.
struct StageResult {
  ElementFailure::Kind kind = ElementFailure::Kind::none;
  const char* when = "";  ///< "mid-step" or "end of step" for a geometry failure

  bool ok() const { return kind == ElementFailure::Kind::none; }
};

/// The section's strain increments of the step, in the element frame.
struct SectionStrains {
  Vec3 membrane;   ///< -, dt d_m: xx, yy, engineering xy
  Vec3 curvature;  ///< 1/mm, dt d_k: the curvature increment, engineering twist
};

/// The transverse shear update of one element (shear-corrected, constant through the thickness).
struct ShearUpdate {
  Vec2 stress = Vec2::Zero();  ///< MPa, the new sxz, syz
  double work = 0.0;           ///< N/mm, the step's shear stress work per unit mid-surface area
};

/// What every element of one loop shares.
struct LoopContext {
  const ElementBlock& block;
  const ElementInputs& in;
  ShellState& st;
  SectionConstants section;
  const double* material_angle;  ///< rad per element, or null (see update_section)
};

/// Runs elements [begin, end) (state indices, within c.block) through the pipeline above with the
/// policy f and the material kernel (point_kernel). Stops at the first failure, recorded in out.
template <class Formulation, class Kernel>
void run_element_loop(Formulation& f, const Kernel& kernel, const LoopContext& c, int begin,
                      int end, ElementOutputs& out) {
  using Nodes = typename Formulation::Nodes;
  static_assert(Nodes::ColsAtCompileTime == Formulation::kNodes, "a column per element node");
  const bool triangles = c.block.shape == ElementShape::triangle;
  ShellState& st = c.st;
  for (int e = begin; e < end; ++e) {
    const int triangle = triangles ? c.block.local(e) : -1;  // names a triangle in a message
    f.prepare(e, begin, end);
    const int* nodes = c.block.element_nodes(e);
    Nodes xe;
    Nodes ve;
    Nodes we;
    gather_nodes(c.in.x.data(), nodes, xe);
    gather_nodes(c.in.v.data(), nodes, ve);
    gather_nodes(c.in.omega.data(), nodes, we);
    if (!all_finite(ve) || !all_finite(we)) {
      return out.fail(e, ElementFailure::Kind::non_finite_velocity, "", triangle);
    }
    typename Formulation::Element el;
    SectionStrains strains;
    if (const StageResult r = f.strains(e, nodes, xe, ve, we, el, strains); !r.ok()) {
      return out.fail(e, r.kind, r.when, triangle);
    }

    const double t = st.thickness[e];
    const SectionResult sr =
        update_section(kernel, c.section, e, t, strains.membrane, strains.curvature,
                       c.material_angle, st, out.failure.material);
    if (out.failure.material.failed()) {
      return out.fail(e, ElementFailure::Kind::material, "", triangle);
    }
    const ShearUpdate shear = f.transverse_shear(e, t, el, st);
    const double area = f.mid_area(el);
    out.internal_work.add(area * (sr.work + shear.work));
    out.plastic_work.add(area * sr.plastic_work);
    if (!all_finite(sr.n) || !all_finite(sr.m) || !all_finite(shear.stress)) {
      return out.fail(e, ElementFailure::Kind::non_finite_stress, "", triangle);
    }
    // Plane stress gives d_ezz at each point; the mean over the thickness stretches it.
    st.thickness[e] = t * (1.0 + sr.d_ezz_mean);

    if (const StageResult r = f.end_geometry(e, xe, el); !r.ok()) {
      return out.fail(e, r.kind, r.when, triangle);
    }
    if (out.element_dt) {
      out.element_dt[e] = f.time_step(xe, el);  // the next step's bound, at x
    }
    f.forces(e, t, xe, ve, we, strains, sr, shear, el, st,
             out.corners + kCornerWidth * static_cast<std::ptrdiff_t>(c.block.corner_slot(e, 0)),
             out.hourglass_work);
  }
}

/// Runs elements [begin, end) of `block` (of one material) with the formulation F, made for the
/// material's law: F(part, material, E (MPa), nu, in, st).
template <class Formulation>
void run_block_elements(const ElementBlock& block, const ShellPart& part,
                        const ShellMaterial& material, const ElementInputs& in, ShellState& st,
                        int begin, int end, ElementOutputs& out) {
  std::visit(
      [&](const auto& law) {
        Formulation f(part, material, law.E, law.nu, in, st);
        const LoopContext c{block, in, st, make_section_constants(part.section),
                            part.material_angle.empty() ? nullptr : part.material_angle.data()};
        run_element_loop(f, point_kernel(law, in.rate_dt()), c, begin, end, out);
      },
      material.law);
}

}  // namespace sf
