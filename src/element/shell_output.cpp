#include "element/shell_output.hpp"

#include <cmath>

#include "element/element_block.hpp"
#include "element/shell_geometry.hpp"
#include "element/shell_triangle_geometry.hpp"

namespace sf {

namespace {

Stress6 rotate_to_global(const Mat3& frame, double sxx, double syy, double sxy, double syz,
                         double sxz) {
  Mat3 s;
  s << sxx, sxy, sxz, sxy, syy, syz, sxz, syz, 0.0;
  const Mat3 g = frame * s * frame.transpose();
  Stress6 out;
  out << g(0, 0), g(1, 1), g(2, 2), g(0, 1), g(1, 2), g(0, 2);
  return out;
}

// The corotational frame of state element e at the coordinates x.
Mat3 element_frame(const ShellPart& part, const Matrix3X& x, int e) {
  const ElementBlock block = block_of(part, e);
  if (block.shape == ElementShape::quad) {
    ShellGeometry g;
    compute_shell_geometry_or_throw(gather_quad(x, part.quads, block.local(e)), e, "output", g);
    return g.frame;
  }
  TriangleGeometry tg;
  const int k = block.local(e);
  compute_triangle_geometry_or_throw(gather_triangle(x, part.triangles, k), e, k, "output", tg);
  return tg.frame;
}

}  // namespace

void compute_point_stresses(const ShellPart& part, const Matrix3X& x, const ShellState& state,
                            int e, std::span<Stress6> out) {
  const Mat3 frame = element_frame(part, x, e);
  const auto ue = static_cast<std::size_t>(e);
  for (std::size_t k = 0; k < out.size(); ++k) {
    const std::size_t i = ue * static_cast<std::size_t>(state.n_points) + k;
    out[k] = rotate_to_global(frame, state.sxx[i], state.syy[i], state.sxy[i], state.syz[ue],
                              state.sxz[ue]);
  }
}

void compute_element_stress_output(const ShellPart& part, const Matrix3X& x,
                                   const ShellState& state, ShellStressOutput& out) {
  compute_element_stress_output(part, x, state, out.mid, out.top, out.bottom, out.eps_p);
}

void compute_element_stress_output(const ShellPart& part, const Matrix3X& x,
                                   const ShellState& state, StressColumns& mid, StressColumns& top,
                                   StressColumns& bottom, VectorX& eps_p) {
  const int n_el = element_count(part);
  const int np = state.n_points;
  mid.resize(6, n_el);
  top.resize(6, n_el);
  bottom.resize(6, n_el);
  eps_p.resize(n_el);
  for (int e = 0; e < n_el; ++e) {
    const Mat3 frame = element_frame(part, x, e);
    const std::size_t base = static_cast<std::size_t>(e) * np;
    const std::size_t lo = base + (np - 1) / 2;  // central point(s)
    const std::size_t hi = base + np / 2;
    mid.col(e) = rotate_to_global(
        frame, 0.5 * (state.sxx[lo] + state.sxx[hi]), 0.5 * (state.syy[lo] + state.syy[hi]),
        0.5 * (state.sxy[lo] + state.sxy[hi]), state.syz[e], state.sxz[e]);
    const std::size_t k_top = base + np - 1;
    top.col(e) =
        rotate_to_global(frame, state.sxx[k_top], state.syy[k_top], state.sxy[k_top], 0.0, 0.0);
    bottom.col(e) =
        rotate_to_global(frame, state.sxx[base], state.syy[base], state.sxy[base], 0.0, 0.0);
    double ep = 0.0;
    for (int k = 0; k < np; ++k) {
      ep += 0.5 * part.section.weight[k] * state.eps_p[base + k];
    }
    eps_p(e) = ep;
  }
}

void compute_element_back_stress_output(const ShellPart& part, const Matrix3X& x,
                                        const ShellState& state, StressColumns& top,
                                        StressColumns& bottom) {
  const int n_el = element_count(part);
  const int np = state.n_points;
  const std::size_t per_point =
      state.back_stress.size() / (static_cast<std::size_t>(n_el) * static_cast<std::size_t>(np));
  top.resize(6, n_el);
  bottom.resize(6, n_el);
  // The sum of a point's back stresses (xx, yy, xy in the element frame).
  const auto total = [&](std::size_t point) {
    Vec3 sum = Vec3::Zero();
    for (std::size_t j = 0; j < per_point; j += 3) {
      const double* a = state.back_stress.data() + per_point * point + j;
      sum += Vec3(a[0], a[1], a[2]);
    }
    return sum;
  };
  for (int e = 0; e < n_el; ++e) {
    const Mat3 frame = element_frame(part, x, e);
    const std::size_t base = static_cast<std::size_t>(e) * np;
    const Vec3 t = total(base + np - 1);
    const Vec3 b = total(base);
    top.col(e) = rotate_to_global(frame, t(0), t(1), t(2), 0.0, 0.0);
    bottom.col(e) = rotate_to_global(frame, b(0), b(1), b(2), 0.0, 0.0);
  }
}

double von_mises(const Stress6& s) {
  const double a = s(0) - s(1);
  const double b = s(1) - s(2);
  const double c = s(2) - s(0);
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s(3) * s(3) + s(4) * s(4) + s(5) * s(5)));
}

}  // namespace sf
