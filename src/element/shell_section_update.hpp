#pragma once
// The through-thickness material update of one shell element, shared by the quad and the triangle
// loops: strain increment at each thickness point, the material law, the stress resultants, the
// thickness strain and the work of the step. Inline: it runs once per element and cycle.
#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "core/types.hpp"
#include "element/shell_material_axes.hpp"
#include "element/shell_part.hpp"
#include "material/plane_stress_batch.hpp"

namespace sf {

/// Per-section constants, hoisted out of the element loop: zeta_k / 2 and w_k / 2.
struct SectionConstants {
  int n_points = 0;
  std::array<double, 9> half_zeta{};
  std::array<double, 9> half_weight{};
};

inline SectionConstants make_section_constants(const ShellSection& section) {
  SectionConstants c;
  c.n_points = section.n_points;
  for (int k = 0; k < section.n_points; ++k) {
    c.half_zeta[k] = 0.5 * section.zeta[k];
    c.half_weight[k] = 0.5 * section.weight[k];
  }
  return c;
}

/// Membrane strain rate d_m = (d_xx, d_yy, g_xy) and curvature rate d_k of a Mindlin shell with
/// constant gradients (bx, by: dN_I/dx^, dN_I/dy^ in the element frame, 1/mm) from the nodal
/// velocities vl (mm/s) and angular velocities wl (rad/s) in that frame: v^ = v^m - z e3 x theta^,
/// eps(z) = eps_m - z kappa, engineering shear. The same for the quad (one point) and the
/// triangle.
template <int N>
inline void compute_plate_strain_rates(const Eigen::Matrix<double, 1, N>& bx,
                                       const Eigen::Matrix<double, 1, N>& by,
                                       const Eigen::Matrix<double, 3, N>& vl,
                                       const Eigen::Matrix<double, 3, N>& wl, Vec3& d_m,
                                       Vec3& d_k) {
  d_m = Vec3(bx.dot(vl.row(0)), by.dot(vl.row(1)), by.dot(vl.row(0)) + bx.dot(vl.row(1)));
  d_k = Vec3(-bx.dot(wl.row(1)), by.dot(wl.row(0)), bx.dot(wl.row(0)) - by.dot(wl.row(1)));
}

/// What one element's section update returns (per unit mid-surface area).
struct SectionResult {
  Vec3 n = Vec3::Zero();      ///< N/mm, membrane resultant N = int s dz
  Vec3 m = Vec3::Zero();      ///< N, bending resultant M = -int z s dz
  double d_ezz_mean = 0.0;    ///< -, thickness strain increment averaged over the thickness
  double work = 0.0;          ///< N/mm, stress work of the step (trapezoidal in the stress)
  double plastic_work = 0.0;  ///< N/mm, its plastic part
  /// N/mm, int (s_new - s_old) . d_eps dz: the stress change's work on the strain increment, the
  /// step's incremental stiffness seen along its own strain increment (elastic: d_eps . C d_eps).
  double stress_change_work = 0.0;
};

/// The flow-stress store of the points from `base` on (none if the state has none).
inline FlowStressCache flow_stress_cache(ShellState& st, std::size_t base) {
  if (st.flow_stress.size() != st.eps_p.size() || st.flow_stress_at.size() != st.eps_p.size()) {
    return {};
  }
  return {st.flow_stress.data() + base, st.flow_stress_at.data() + base};
}

/// update_section (below) for a GeneralPlasticity law (Barlat's criteria, kinematic hardening):
/// the points are returned one at a time with their back stresses, which are stored like the
/// stress, in the element frame (ShellState::back_stress). A plain overload: the element loops'
/// update_section(kernel, ...) picks it for a GeneralKernel.
inline SectionResult update_section(const GeneralKernel& kernel, const SectionConstants& sc, int e,
                                    double t, const Vec3& dt_d_m, const Vec3& dt_d_k,
                                    const double* material_angle, ShellState& st,
                                    MaterialFailure& failure) {
  const GeneralPlasticity& law = *kernel.law;
  const MaterialFrame axes = make_material_frame(dt_d_m, dt_d_k, material_angle, e);
  const int n_back = law.kinematic.count;
  const std::size_t base = static_cast<std::size_t>(e) * static_cast<std::size_t>(sc.n_points);
  const FlowStressCache cache = flow_stress_cache(st, base);
  SectionResult r;
  for (int k = 0; k < sc.n_points; ++k) {
    const std::size_t i = base + static_cast<std::size_t>(k);
    const double z = t * sc.half_zeta[k];
    const double hw = t * sc.half_weight[k];
    const Vec3 d_eps = dt_d_m - z * dt_d_k;
    const Vec3 old_stress(st.sxx[i], st.syy[i], st.sxy[i]);
    GeneralPlasticityState old;
    old.stress = rotate_stress(old_stress, axes.c, axes.s);
    old.eps_p = st.eps_p[i];
    double* back = n_back > 0 ? st.back_stress.data() + 3 * n_back * i : nullptr;
    for (int b = 0; b < n_back; ++b) {
      old.back[b] =
          rotate_stress(Vec3(back[3 * b], back[3 * b + 1], back[3 * b + 2]), axes.c, axes.s);
    }
    // The flow stress store (ShellState::flow_stress) spares a hardening evaluation per point.
    const bool stored = cache.stress && cache.at[k] == old.eps_p;
    const GeneralPlasticityUpdate up = law.update_or_fail(
        old, axes.d_m - z * axes.d_k, failure, nullptr,
        stored ? cache.stress[k] : std::numeric_limits<double>::quiet_NaN(), kernel.dt);
    if (failure.failed()) {
      return r;
    }
    if (cache.stress) {
      cache.stress[k] = up.flow_stress;
      cache.at[k] = up.state.eps_p;
    }
    const Vec3 stress = rotate_stress(up.state.stress, axes.c, -axes.s);
    st.sxx[i] = stress(0);
    st.syy[i] = stress(1);
    st.sxy[i] = stress(2);
    st.eps_p[i] = up.state.eps_p;
    for (int b = 0; b < n_back; ++b) {
      const Vec3 alpha = rotate_stress(up.state.back[b], axes.c, -axes.s);
      back[3 * b] = alpha(0);
      back[3 * b + 1] = alpha(1);
      back[3 * b + 2] = alpha(2);
    }
    r.n += hw * stress;
    r.m -= (hw * z) * stress;
    r.d_ezz_mean += sc.half_weight[k] * up.d_ezz;
    r.work += hw * 0.5 * (old_stress + stress).dot(d_eps);
    r.plastic_work += hw * up.d_plastic_work;
    r.stress_change_work += hw * (stress - old_stress).dot(d_eps);
  }
  return r;
}

/// Updates the points of element e (state indices e * n_points + k) for the strain increments
/// dt d_m (membrane) and dt d_k (curvature): d_eps(z) = dt d_m - z dt d_k, z = zeta t / 2, t the
/// element's thickness (mm), with the law's kernel (point_kernel, formed once per loop). Laws with
/// material axes (Hill48) work in the element's material frame (material_angle[e], rad, or 0 when
/// material_angle is null); the stored stress stays in the element frame. The points are updated
/// as one batch (material/plane_stress_batch.hpp); the resultants are summed bottom to top. A
/// point update that fails is written to `failure` (nothing else is then to be used), which is
/// left as it is otherwise.
template <class Kernel>
inline SectionResult update_section(const Kernel& kernel, const SectionConstants& sc, int e,
                                    double t, const Vec3& dt_d_m, const Vec3& dt_d_k,
                                    const double* material_angle, ShellState& st,
                                    MaterialFailure& failure) {
  constexpr bool material_axes = Kernel::kMaterialAxes;
  // Laws with material axes: components in the material axes (the element frame turned by the
  // element's material angle theta); strains are linear in z, so dt d_m and dt d_k are turned
  // once per element. Isotropic laws get an empty struct: their loop is the plain one.
  [[maybe_unused]] std::conditional_t<material_axes, MaterialFrame, NoMaterialFrame> axes;
  if constexpr (material_axes) {
    axes = make_material_frame(dt_d_m, dt_d_k, material_angle, e);
  }
  double* sxx = st.sxx.data();
  double* syy = st.syy.data();
  double* sxy = st.sxy.data();
  double* eps = st.eps_p.data();
  const int n = sc.n_points;
  const std::size_t base = static_cast<std::size_t>(e) * static_cast<std::size_t>(n);
  constexpr int kMax = kMaxReturnLanes;
  Vec3 old_stress[kMax];
  Vec3 d_eps[kMax];
  double eps_n[kMax];
  [[maybe_unused]] Vec3 law_stress[material_axes ? kMax : 1];  // material axes
  [[maybe_unused]] Vec3 law_d_eps[material_axes ? kMax : 1];
  for (int k = 0; k < n; ++k) {
    const std::size_t i = base + static_cast<std::size_t>(k);
    const double z = t * sc.half_zeta[k];
    // dt (d_m - z d_k), as dt d_m - z (dt d_k): equal to round-off.
    d_eps[k] = dt_d_m - z * dt_d_k;
    old_stress[k] = Vec3(sxx[i], syy[i], sxy[i]);
    eps_n[k] = eps[i];
    if constexpr (material_axes) {
      law_stress[k] = rotate_stress(old_stress[k], axes.c, axes.s);
      law_d_eps[k] = axes.d_m - z * axes.d_k;
    }
  }
  PlaneStressUpdate up[kMax];
  bool updated;
  if constexpr (material_axes) {
    updated = update_points(kernel, n, law_stress, eps_n, law_d_eps, flow_stress_cache(st, base),
                            up, failure);
  } else {
    updated = update_points(kernel, n, old_stress, eps_n, d_eps, flow_stress_cache(st, base), up,
                            failure);
  }
  SectionResult r;
  if (!updated) {
    return r;
  }
  for (int k = 0; k < n; ++k) {
    const std::size_t i = base + static_cast<std::size_t>(k);
    if constexpr (material_axes) {
      up[k].stress = rotate_stress(up[k].stress, axes.c, -axes.s);  // back to the element frame
    }
    const double z = t * sc.half_zeta[k];
    const double hw = t * sc.half_weight[k];
    sxx[i] = up[k].stress(0);
    syy[i] = up[k].stress(1);
    sxy[i] = up[k].stress(2);
    eps[i] = up[k].eps_p;
    r.n += hw * up[k].stress;
    r.m -= (hw * z) * up[k].stress;
    r.d_ezz_mean += sc.half_weight[k] * up[k].d_ezz;
    r.work += hw * 0.5 * (old_stress[k] + up[k].stress).dot(d_eps[k]);
    r.plastic_work += hw * up[k].d_plastic_work;
    r.stress_change_work += hw * (up[k].stress - old_stress[k]).dot(d_eps[k]);
  }
  return r;
}

}  // namespace sf
