#pragma once
// Static description and integration-point state of a shell part: Belytschko-Lin-Tsay quads and
// C0 triangles.
#include <array>
#include <vector>

#include "core/types.hpp"
#include "element/shell_choices.hpp"
#include "material/plane_stress.hpp"

namespace sf {

/// Through-thickness integration rule: n_points points, ordered from the bottom (zeta = -1 side)
/// to the top (zeta = +1 side, the side the normal e3 points to).
struct ShellSection {
  int n_points = 5;
  ThroughThicknessRule rule = ThroughThicknessRule::gauss;
  std::array<double, 9> zeta{};    ///< positions in [-1, 1]; z = zeta t / 2
  std::array<double, 9> weight{};  ///< quadrature weights, summing to 2
};

/// The Gauss-Legendre rule with n_points (1..9) points; exact for polynomials of degree
/// 2 n_points - 1 in zeta. Throws InputError outside 1..9.
ShellSection make_gauss_section(int n_points);

/// The rule of the given family: Gauss-Legendre (1..9 points) or Gauss-Lobatto (2..9 points; the
/// end points zeta = -1, +1 are the bottom and top surfaces; exact to degree 2 n_points - 3).
/// Throws InputError for a point count outside the family's range.
ShellSection make_section(int n_points, ThroughThicknessRule rule);

/// Integration-point state of a shell part, structure of arrays. Elements are numbered by the
/// part's element blocks (element/element_block.hpp; see ShellPart). In-plane quantities are
/// indexed e * n_points + k (k = 0 bottom .. n_points - 1 top); stresses are components in the
/// element's corotational frame (e1, e2, e3).
struct ShellState {
  int n_elements = 0;
  int n_points = 0;
  std::vector<double> sxx, syy, sxy;  ///< MPa, in-plane stress per point
  std::vector<double> eps_p;          ///< -, equivalent plastic strain per point
  /// MPa, per point: the flow stress at the plastic strain flow_stress_at (set by the element
  /// loops' material update, FlowStressCache in material/plane_stress_batch.hpp: the value the
  /// return converged on, a Swift law's within 1e-13 relative of its pow), so that a yield
  /// check needs no hardening evaluation. Where flow_stress_at differs from eps_p (at the start,
  /// or after eps_p was set from outside) the flow stress is evaluated again. Belongs to the
  /// part's hardening law: a state moved to another law must be made again. Empty: not stored.
  std::vector<double> flow_stress;
  std::vector<double> flow_stress_at;  ///< -, per point, see flow_stress
  /// MPa, the back stresses of a law with kinematic hardening (GeneralPlasticity), in the
  /// element frame like the stress: index 3 (n_back i + b) + c for point i, back stress b of
  /// n_back, component c (xx, yy, xy). Empty for other laws (size_shell_state_for_material).
  std::vector<double> back_stress;
  std::vector<double> sxz, syz;   ///< MPa, per element: transverse shear stress averaged over
                                  ///< the thickness (Q / t, shear-corrected)
  std::vector<double> thickness;  ///< mm, per element, current
  /// Hourglass (stabilisation) resultants per element, kHourglassModes per element (index
  /// kHourglassModes e + j). Belytschko-Tsay, stiffness form, in the element's corotational
  /// frame: j = 0, 1 in-plane (N), 2 out-of-plane (N), 3, 4 rotational (N mm), 5 unused. Assumed
  /// strain: j = 0, 1 membrane (N, frame), 2, 3 bending (N mm, frame), 4, 5 transverse shear (N,
  /// of the edge differences) (shell_quad_stabilization.hpp). Unused (stays 0) with the viscous
  /// form and for triangles.
  std::vector<double> hourglass;
  /// -, per element and node, the unit director (the shell's fibre) in global components: index
  /// 3 (kDirectorNodes e + I) + c, node I of the element, component c. Used by the
  /// assumed-strain quads (their curvature and transverse shear are functions of the nodes'
  /// positions and directors, shell_quad_directors.hpp); set by initialize_directors and rotated
  /// with the nodes.
  std::vector<double> director;
};

/// Number of hourglass resultants stored per element in ShellState::hourglass.
inline constexpr int kHourglassModes = 6;
/// Directors stored per element in ShellState::director (4: a quad's nodes).
inline constexpr int kDirectorNodes = 4;

/// A stress-free state with uniform thickness (mm).
ShellState make_shell_state(int n_elements, int n_points, double thickness);
/// Sizes the material's own per-point arrays of `state` (zero): the back stresses of a law with
/// kinematic hardening; clears them for other laws.
void size_shell_state_for_material(ShellState& state, const Material& material);

/// How the assumed strain's membrane and bending stabilisation unloads in an element that yields
/// during the step (docs/element-and-material.md, section 3c).
enum class StabilizationUnloading {
  /// Elastically: a mode follows the incremental stiffness only while it loads, so it never gives
  /// back more than it stored (the explicit loop).
  elastic,
  /// Along the incremental stiffness, as it loads: the force is then continuous in the increment,
  /// which the static step's Newton iteration needs (the switch between loading and unloading
  /// made its differenced tangent jump; the work is still counted, so the energy balance holds).
  as_loading,
};

/// The material of some of a part's elements: its law and its density.
struct ShellMaterial {
  Material law = ElasticPlaneStress{};
  double density = 0.0;  ///< tonne/mm^3
};

/// A shell part: connectivity (node indices, counter-clockwise seen from the +normal side) of its
/// quads and triangles, section, materials and the hourglass control (quads only). A part may
/// hold quads, triangles or both; its elements are numbered block by block, its quads and then
/// its triangles, and only element/element_block.hpp turns that numbering into a shape and a
/// column. State arrays, stable-step elements and output cells use this numbering. A part of
/// several materials (a tailor-welded blank) names each element's material; elements of one
/// material are best kept consecutive (the element loops take a run of one material at a time).
struct ShellPart {
  QuadConn quads;
  TriConn triangles;  ///< 3-node C0 shell triangles (DSG3 transverse shear)
  ShellSection section = make_gauss_section(5);
  std::vector<ShellMaterial> materials{ShellMaterial{}};  ///< at least one
  /// Per element, its index into `materials`; empty: every element has materials[0].
  std::vector<int> element_material;
  ShellFormulation formulation = ShellFormulation::assumed_strain;  ///< of the quads
  /// -, viscous: fraction (x 4) of critical damping; stiffness: hourglass mode stiffness as a
  /// fraction of the element's membrane / bending stiffness. See docs/element-and-material.md.
  double hourglass_coefficient = 0.1;
  HourglassForm hourglass_form = HourglassForm::viscous;
  StabilizationUnloading stabilization_unloading =
      StabilizationUnloading::elastic;  ///< assumed strain
  /// rad, one per element: the angle from the element's corotational e1 axis to the rolling
  /// direction (counter-clockwise about e3), fixed at the start (compute_material_angles). Read
  /// only by laws with material axes (Hill48): the material axes turn with e1. Empty = 0 for
  /// every element (the element frame is the material frame).
  std::vector<double> material_angle;
};

/// Number of elements of a part: quads plus triangles.
inline int element_count(const ShellPart& part) {
  return static_cast<int>(part.quads.cols() + part.triangles.cols());
}

/// The index into part.materials of element e's material.
inline int material_index(const ShellPart& part, int e) {
  return part.element_material.empty() ? 0 : part.element_material[static_cast<std::size_t>(e)];
}

/// Element e's material.
inline const ShellMaterial& material_of(const ShellPart& part, int e) {
  return part.materials[static_cast<std::size_t>(material_index(part, e))];
}

/// The end of the run of elements from `begin` (up to `end`) that share element begin's material.
int material_run_end(const ShellPart& part, int begin, int end);

/// Calls piece(b, e, material) for the runs of one material that make up elements [begin, end),
/// in order.
template <class Piece>
void for_each_material_run(const ShellPart& part, int begin, int end, const Piece& piece) {
  for (int b = begin; b < end;) {
    const int e = material_run_end(part, b, end);
    piece(b, e, material_of(part, b));
    b = e;
  }
}

/// Sets the part's materials and each element's (an index into `materials`, one per element).
/// Throws std::invalid_argument on an index out of range or a count that is not the part's.
void set_element_materials(ShellPart& part, std::vector<ShellMaterial> materials,
                           std::vector<int> element_material);

/// The number of back stresses (kinematic hardening terms) the law keeps per point.
int back_stress_count(const Material& material);

/// Sizes the materials' own per-point arrays of `state` (see size_shell_state_for_material) for
/// a part of several materials, which must keep the same number of back stresses
/// (std::invalid_argument otherwise; build_model refuses such parts first).
void size_shell_state_for_part(ShellState& state, const ShellPart& part);

}  // namespace sf
