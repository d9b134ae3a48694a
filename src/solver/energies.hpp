#pragma once
// Energy accounting of an explicit run (N mm = mJ in the forming units).

namespace sf {

struct Energies {
  double kinetic = 0.0;        ///< translational + rotational, at the half step
  double internal = 0.0;       ///< work of the element forces, hourglass work excluded
  double hourglass = 0.0;      ///< work of the hourglass forces
  double contact = 0.0;        ///< elastic energy stored in the penalty springs, 1/2 k g^2
  double external_work = 0.0;  ///< work done on the blank by the moving tools (and loads)

  double total() const { return kinetic + internal + hourglass + contact; }
  /// (total - external work) relative to the larger of the two; 0 when nothing has happened.
  double balance_error() const;
  /// kinetic / internal, the quasi-static check of a forming run (0 while nothing is strained).
  double kinetic_ratio() const {
    return internal + hourglass > 0.0 ? kinetic / (internal + hourglass) : 0.0;
  }
};

inline double Energies::balance_error() const {
  const double scale = external_work > total() ? external_work : total();
  if (scale <= 0.0) {
    return 0.0;
  }
  return (total() - external_work) / scale;
}

}  // namespace sf
