#include "element/shell_part.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/errors.hpp"

namespace sf {

namespace {

// Legendre polynomials P_m(x) and P_{m-1}(x) by the three-term recurrence (m >= 1).
void evaluate_legendre(int m, double x, double& p_m, double& p_m_minus_1) {
  double p0 = 1.0;
  double p1 = x;
  for (int k = 2; k <= m; ++k) {
    const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
    p0 = p1;
    p1 = p2;
  }
  p_m = p1;
  p_m_minus_1 = p0;
}

// Gauss-Lobatto rule with n >= 2 points (Abramowitz & Stegun 25.4.32): x = -1, +1 and the n - 2
// roots of P'_{n-1}; weights 2 / (n (n - 1) P_{n-1}(x)^2).
ShellSection make_lobatto_section(int n) {
  ShellSection s;
  s.n_points = n;
  s.rule = ThroughThicknessRule::lobatto;
  const int m = n - 1;
  const double end_weight = 2.0 / (n * (n - 1.0));
  s.zeta[0] = -1.0;
  s.zeta[n - 1] = 1.0;
  s.weight[0] = end_weight;
  s.weight[n - 1] = end_weight;
  for (int i = 1; i < n - 1; ++i) {
    // Interior roots of P'_m, Newton from the Chebyshev-Lobatto guess -cos(pi i / m) (ascending).
    // P'_m = m (P_{m-1} - x P_m) / (1 - x^2), P''_m = (2 x P'_m - m (m + 1) P_m) / (1 - x^2).
    double x = -std::cos(std::numbers::pi * i / m);
    for (int it = 0; it < 100; ++it) {
      double pm = 0.0;
      double pm1 = 0.0;
      evaluate_legendre(m, x, pm, pm1);
      const double one_minus_x2 = 1.0 - x * x;
      const double dp = m * (pm1 - x * pm) / one_minus_x2;
      const double d2p = (2.0 * x * dp - m * (m + 1.0) * pm) / one_minus_x2;
      const double dx = dp / d2p;
      x -= dx;
      if (std::abs(dx) < 1e-16) {
        break;
      }
    }
    double pm = 0.0;
    double pm1 = 0.0;
    evaluate_legendre(m, x, pm, pm1);
    s.zeta[i] = std::abs(x) < 1e-15 ? 0.0 : x;
    s.weight[i] = end_weight / (pm * pm);
  }
  return s;
}

}  // namespace

ShellSection make_gauss_section(int n_points) {
  if (n_points < 1 || n_points > 9) {
    throw InputError(
        "shell section: the number of integration points through the thickness must "
        "be 1..9 (got " +
        std::to_string(n_points) + ")");
  }
  ShellSection s;
  s.n_points = n_points;
  const int n = n_points;
  // Roots of the Legendre polynomial P_n by Newton's method from the classical initial guess
  // cos(pi (i + 3/4) / (n + 1/2)); weights 2 / ((1 - x^2) P_n'(x)^2) (Abramowitz & Stegun 25.4.29).
  for (int i = 0; i < n; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double pn = 1.0;
      double pnm1 = 1.0;
      evaluate_legendre(n, x, pn, pnm1);
      dp = n == 1 ? 1.0 : n * (x * pn - pnm1) / (x * x - 1.0);
      const double dx = pn / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) {
        break;
      }
    }
    // Re-evaluate the derivative at the converged root.
    double pn = 1.0;
    double pnm1 = 1.0;
    evaluate_legendre(n, x, pn, pnm1);
    dp = n == 1 ? 1.0 : n * (x * pn - pnm1) / (x * x - 1.0);
    // i = 0 is the largest root: store ascending (bottom first).
    s.zeta[n - 1 - i] = std::abs(x) < 1e-15 ? 0.0 : x;
    s.weight[n - 1 - i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
  return s;
}

ShellSection make_section(int n_points, ThroughThicknessRule rule) {
  if (rule == ThroughThicknessRule::gauss) {
    return make_gauss_section(n_points);
  }
  if (n_points < 2 || n_points > 9) {
    throw InputError(
        "shell section: the number of Lobatto integration points through the thickness must be "
        "2..9 (got " +
        std::to_string(n_points) + ")");
  }
  return make_lobatto_section(n_points);
}

ShellState make_shell_state(int n_elements, int n_points, double thickness) {
  ShellState st;
  st.n_elements = n_elements;
  st.n_points = n_points;
  const std::size_t n = static_cast<std::size_t>(n_elements) * static_cast<std::size_t>(n_points);
  st.sxx.assign(n, 0.0);
  st.syy.assign(n, 0.0);
  st.sxy.assign(n, 0.0);
  st.eps_p.assign(n, 0.0);
  // Not yet evaluated: no plastic strain equals NaN.
  st.flow_stress.assign(n, 0.0);
  st.flow_stress_at.assign(n, std::numeric_limits<double>::quiet_NaN());
  st.sxz.assign(n_elements, 0.0);
  st.syz.assign(n_elements, 0.0);
  st.thickness.assign(n_elements, thickness);
  st.hourglass.assign(static_cast<std::size_t>(n_elements) * kHourglassModes, 0.0);
  st.director.assign(static_cast<std::size_t>(n_elements) * 3 * kDirectorNodes, 0.0);
  return st;
}

void size_shell_state_for_material(ShellState& state, const Material& material) {
  const auto* law = std::get_if<GeneralPlasticity>(&material);
  const int n_back = law ? law->kinematic.count : 0;
  state.back_stress.assign(static_cast<std::size_t>(state.n_elements) *
                               static_cast<std::size_t>(state.n_points) * 3 *
                               static_cast<std::size_t>(n_back),
                           0.0);
}

int back_stress_count(const Material& material) {
  const auto* law = std::get_if<GeneralPlasticity>(&material);
  return law ? law->kinematic.count : 0;
}

int material_run_end(const ShellPart& part, int begin, int end) {
  if (part.element_material.empty()) {
    return end;
  }
  const int m = part.element_material[static_cast<std::size_t>(begin)];
  int e = begin + 1;
  while (e < end && part.element_material[static_cast<std::size_t>(e)] == m) {
    ++e;
  }
  return e;
}

void set_element_materials(ShellPart& part, std::vector<ShellMaterial> materials,
                           std::vector<int> element_material) {
  if (materials.empty() ||
      element_material.size() != static_cast<std::size_t>(element_count(part))) {
    throw std::invalid_argument("set_element_materials: one material index per element expected");
  }
  for (const int m : element_material) {
    if (m < 0 || static_cast<std::size_t>(m) >= materials.size()) {
      throw std::invalid_argument("set_element_materials: material index out of range");
    }
  }
  part.materials = std::move(materials);
  part.element_material = std::move(element_material);
}

void size_shell_state_for_part(ShellState& state, const ShellPart& part) {
  const int n_back = back_stress_count(part.materials.front().law);
  for (const ShellMaterial& m : part.materials) {
    if (back_stress_count(m.law) != n_back) {
      throw std::invalid_argument(
          "size_shell_state_for_part: the materials keep different numbers of back stresses");
    }
  }
  size_shell_state_for_material(state, part.materials.front().law);
}

}  // namespace sf
