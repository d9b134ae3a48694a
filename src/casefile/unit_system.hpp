#pragma once
// The case's unit system, from its `units` string "LENGTH-TIME-MASS-FORCE-STRESS" (e.g.
// "mm-s-tonne-N-MPa", "m-s-kg-N-Pa"). The solver is unit-agnostic; the system only names units in
// messages and is checked for consistency (force = mass x length / time^2, stress = force /
// length^2), so that a case cannot claim units its numbers do not follow.
#include <string>
#include <string_view>
#include <vector>

namespace sf {

/// The dimension of a quantity as powers of length, time and mass (a stress: -1, -2, 1).
struct Dimension {
  int length = 0;
  int time = 0;
  int mass = 0;
};

/// A consistent system of the five base units a case is written in, by their names.
struct UnitSystem {
  std::string length;  ///< e.g. "mm"
  std::string time;    ///< e.g. "s"
  std::string mass;    ///< e.g. "tonne"
  std::string force;   ///< e.g. "N"
  std::string stress;  ///< e.g. "MPa"
  /// The base units' sizes in SI (m, s, kg); 0 for "consistent", a system of no known size.
  double length_si = 0.0;
  double time_si = 0.0;
  double mass_si = 0.0;

  /// Whether the sizes are known (a named system, not "consistent").
  bool named() const { return length_si > 0.0; }
  /// The size in SI units of this system's unit of a quantity of dimension d (MPa: 1e6 Pa);
  /// 0 when the system is not named.
  double si_size(const Dimension& d) const;

  /// Derived units as messages write them.
  std::string velocity() const { return length + "/" + time; }             ///< "mm/s"
  std::string acceleration() const { return length + "/" + time + "^2"; }  ///< "mm/s^2"
  std::string density() const { return mass + "/" + length + "^3"; }       ///< "tonne/mm^3"
  std::string moment() const { return force + " " + length; }              ///< "N mm", also energy
  std::string stiffness() const { return force + "/" + length; }           ///< "N/mm"
  std::string area() const { return length + "^2"; }                       ///< "mm^2"
  std::string rate() const { return "1/" + time; }                         ///< "1/s"
};

/// Parses "LENGTH-TIME-MASS-FORCE-STRESS", or "consistent": a consistent set with no names (the
/// data of a benchmark given in no named system), printed as [L], [T], [M], [F], [F/L^2].
/// Accepted names: length m, cm, mm, um; time s, ms, us; mass kg, g, mg, tonne; force N, kN, MN,
/// mN, dyn; stress Pa, kPa, MPa, GPa, Ba. The five
/// must be consistent to 1e-9: force = mass x length / time^2 and stress = force / length^2.
/// Throws std::invalid_argument with a message saying which part is unknown (and the names
/// accepted there) or which relation fails (and the unit that would satisfy it).
UnitSystem parse_unit_system(std::string_view text);

/// Every consistent named system parse_unit_system accepts (e.g. mm-s-tonne-N-MPa, m-s-kg-N-Pa,
/// mm-ms-kg-kN-GPa): the systems a case can be written in, which bound what its numbers can mean.
const std::vector<UnitSystem>& accepted_unit_systems();

}  // namespace sf
