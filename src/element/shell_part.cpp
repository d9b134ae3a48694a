#include "element/shell_part.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"

namespace sf {

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
      double p0 = 1.0;
      double p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      const double pn = n == 1 ? x : p1;
      const double pnm1 = n == 1 ? 1.0 : p0;
      dp = n * (x * pn - pnm1) / (x * x - 1.0);
      const double dx = pn / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) {
        break;
      }
    }
    // Re-evaluate the derivative at the converged root.
    double p0 = 1.0;
    double p1 = x;
    for (int k = 2; k <= n; ++k) {
      const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    dp = n == 1 ? 1.0 : n * (x * p1 - p0) / (x * x - 1.0);
    // i = 0 is the largest root: store ascending (bottom first).
    s.zeta[n - 1 - i] = std::abs(x) < 1e-15 ? 0.0 : x;
    s.weight[n - 1 - i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
  return s;
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
  st.sxz.assign(n_elements, 0.0);
  st.syz.assign(n_elements, 0.0);
  st.thickness.assign(n_elements, thickness);
  return st;
}

}  // namespace sf
