#pragma once
// Barlat et al. (2003)'s AA2090-T3 sheet, the Yld2000-2d tests' material (docs/references.md):
// F. Barlat et al., Int. J. Plasticity 19 (2003) 1297-1319, Table 2 (yield stresses normalised by
// sigma0, r-values, experimental r_b) and Table 3 (coefficients fitted with that r_b, a = 8).
#include <cmath>

#include "material/anisotropy_fit.hpp"

namespace sf::test {

inline const Yld2000Data kAA2090{1.000, 0.811, 0.910, 1.035, 0.21, 1.58, 0.69, 0.67};
inline const Yld2000Criterion kAA2090Table3{
    {0.4865, 1.3783, 0.7536, 1.0246, 1.0363, 0.9036, 1.2321, 1.4858}, 8.0};

/// Degrees to radians.
inline double deg(double d) {
  return d * std::acos(-1.0) / 180.0;
}

}  // namespace sf::test
