#pragma once
// Friction of one contact node: an elastic stick spring in the tangent plane with a return
// mapping onto the slip limit (docs/contact.md, "Friction laws"). The coefficient is
//
//   mu(p, v) = mu_b(p, v) f(v),   mu_b = mu_c(v) (p / p0)^(n - 1)  or  mu_b = mu_T(p),
//   mu_c(v) = mu_d + (mu_s - mu_d) exp(-c |v|),
//
// p the contact pressure (MPa), v the slip speed (mm/s), mu_T a table against the pressure and f
// a table against the slip speed (1 when not given). mu_c is the exponential static-to-dynamic
// decay used by LS-DYNA's contact friction (FS, FD, DC; LS-DYNA Keyword User's Manual, *CONTACT)
// -- quoted from that manual's description, not re-checked against the primary source here:
// grade C. The power law mu_0 (p / p0)^(n - 1) is the pressure-dependent coefficient of forming
// practice (e.g. AutoForm's and TriboForm's pressure-dependent friction, Hol et al. 2012, Wear) as
// the issue states it; its primary source was not checked here: grade C. With a ratio r != 1 the
// limit is the ellipse (F_1 / mu)^2 + (F_2 / (r mu))^2 <= F_n^2 in the axes along and across the
// rolling direction (orthotropic Coulomb friction, e.g. Mroz & Stupkiewicz 1994; not checked
// here: grade C), with a radial return: the force opposes the slip.
#include <string>
#include <string_view>
#include <vector>

#include "core/types.hpp"

namespace sf {

/// A piecewise-linear table y(x) of a friction law: the abscissae strictly increasing, the end
/// values held beyond them.
struct FrictionTable {
  std::vector<double> x;  ///< abscissae, strictly increasing (pressure MPa or slip speed mm/s)
  std::vector<double> y;  ///< the values at them (a coefficient or a factor, -)

  bool empty() const { return x.empty(); }
  /// y at `at`: linear between the points, y.front() below x.front(), y.back() above x.back().
  /// No allocation.
  double operator()(double at) const;
  /// Throws InputError naming the tool and the table ("pressure", "speed") unless it has >= 2
  /// points, finite abscissae >= 0 strictly increasing and finite values >= 0. No allocation
  /// unless it throws.
  void validate(std::string_view tool, std::string_view name) const;
};

/// The ends of a pair's friction tables that a node's pressure or slip speed may lie beyond.
enum class TableEnd { pressure_below, pressure_above, speed_below, speed_above };
inline constexpr int kTableEnds = 4;

/// Friction parameters of a contact pair. Units: mm, s, N, MPa.
struct FrictionParameters {
  double static_coefficient = 0;   ///< mu_s >= 0 (0: frictionless)
  double dynamic_coefficient = 0;  ///< mu_d, 0 <= mu_d <= mu_s
  double decay = 0;                ///< c >= 0, s/mm: mu falls from mu_s to mu_d as exp(-c |v|)
  /// k_t / k: the tangential (stick) stiffness as a multiple of the node's normal penalty
  /// stiffness, 0 < ratio <= 1. The default 1 gives the stick spring the same frequency as the
  /// normal spring, which the penalty stiffness cap already keeps stable (the normal and
  /// tangential springs act in orthogonal directions, so the node's contact frequency stays
  /// sqrt(max(k, k_t) / m)); a larger k_t would break that cap, a smaller one lets a sticking
  /// node creep elastically by |F_t| / k_t.
  double tangential_stiffness_ratio = 1.0;
  /// n > 0, -: the pressure power law's exponent, mu_c(v) (p / p0)^(n - 1); 1: no power law.
  double pressure_exponent = 1.0;
  double reference_pressure = 1.0;  ///< p0 > 0, MPa (used when pressure_exponent != 1)
  /// mu_T(p), the coefficient against the contact pressure (MPa), instead of mu_c and the power
  /// law (then static_coefficient, dynamic_coefficient and decay are 0); empty: none.
  FrictionTable pressure_table;
  /// f(v), a factor on the coefficient against the slip speed (mm/s); empty: none (1).
  FrictionTable speed_table;
  /// r > 0, -: the coefficient across `rolling_direction` over the one along it; 1: isotropic.
  double across_ratio = 1.0;
  /// Unit, global axes: the along direction, projected on the contact's tangent plane.
  Vec3 rolling_direction = Vec3::UnitX();

  bool active() const { return static_coefficient > 0 || !pressure_table.empty(); }
  /// Whether the coefficient depends on the contact pressure (the pair then needs the nodes'
  /// areas).
  bool needs_pressure() const { return pressure_exponent != 1.0 || !pressure_table.empty(); }
  /// mu_c(v) for the slip speed v (mm/s): the Coulomb coefficient with its decay.
  double coefficient(double slip_speed) const;
  /// mu(p, v) for the contact pressure p > 0 (MPa; ignored unless needs_pressure()) and the slip
  /// speed v (mm/s); sets bit (1 << TableEnd) of *beyond (when given) for each table end that p
  /// or v lies beyond. Equal to coefficient(v), bit for bit, without the laws beyond Coulomb.
  double coefficient(double pressure, double slip_speed, unsigned* beyond = nullptr) const;
  /// The limit's factor for a trial force along the unit tangent `t` at a contact of unit normal
  /// `normal`: 1 / sqrt(cos^2 a + sin^2 a / r^2), a the angle between t and the rolling
  /// direction's projection on the tangent plane (the ellipse's radius over mu F_n); (1 + r) / 2
  /// where that projection is shorter than 1e-6 (the direction normal to the contact).
  double direction_factor(const Vec3& normal, const Vec3& t) const;
  /// Throws InputError (naming the tool) unless 0 <= mu_d <= mu_s, c >= 0,
  /// 0 < tangential_stiffness_ratio <= 1, n > 0 (with p0 > 0 when n != 1), valid tables (a
  /// pressure table without mu_s, mu_d, c or n), r > 0 and a unit rolling direction (all finite).
  void validate(std::string_view tool) const;
};

/// The warning for a node met beyond `end` of the pair's friction tables: what was met, which
/// end value is held, for the contact `where` ("case.toml: contact[0], tool 'die'") at time t (s).
std::string friction_table_warning(const FrictionParameters& law, TableEnd end,
                                   std::string_view where, double time, long cycle);

/// The outcome of one friction update.
struct FrictionStep {
  Vec3 force = Vec3::Zero();  ///< friction force on the blank node, N (in the tangent plane)
  double slip = 0;            ///< plastic (slip) part of the tangential increment, mm, >= 0
  double work = 0;            ///< friction work dissipated in this update, N mm, >= 0
  bool sliding = false;       ///< the trial force exceeded the Coulomb limit
  unsigned beyond = 0;        ///< bit (1 << TableEnd) for each friction table end p or v lay beyond
};

/// One friction update of a node in contact (backward-Euler return mapping):
///  1. `stored_force` (the elastic stick force of the previous update, N) is rotated into the
///     tangent plane of `normal` (unit): projected and rescaled to its length, so that a tilting
///     normal keeps it tangent without changing it (dropped if it has no tangential part);
///  2. trial = rotated - k_t du_t, du_t the tangential part of `increment` (mm, the node's
///     displacement relative to the tool over the step);
///  3. limit = mu(p, |du_t| / dt) * normal_force (dt <= 0: slip speed 0), times the direction
///     factor of the trial force (law.direction_factor) when law.across_ratio != 1; 0 when
///     normal_force is 0; if |trial| <= limit the node sticks, else the force is scaled back to
///     the limit along the trial force (slides: a radial return, exact backward Euler for a slip
///     along the force) and the slip is (|trial| - limit) / k_t, the work dissipated limit * slip.
/// On return `stored_force` holds the new force. normal_force >= 0 (N), k_t > 0 (N/mm),
/// pressure: the contact pressure (MPa), used only when law.needs_pressure().
/// |force| <= limit always. No allocation.
FrictionStep coulomb_friction_update(const FrictionParameters& law, Vec3& stored_force,
                                     const Vec3& normal, const Vec3& increment, double dt,
                                     double normal_force, double k_t, double pressure = 0.0);

}  // namespace sf
