#include "model/mass_scaling.hpp"

#include <cmath>
#include <limits>

#include "element/shell_mass.hpp"

namespace sf {

void set_up_mass_scaling(const ShellPart& part, const Matrix3X& x, const ShellState& state,
                         double target_dt, double safety, MassScaling& scaling) {
  scaling.target_dt = target_dt;
  scaling.safety = safety;
  compute_element_masses(part, x, state, scaling.element_mass, scaling.inertia_factor);
  scaling.density_factor.assign(scaling.element_mass.size(), 1.0);
  scaling.element_dt.assign(scaling.element_mass.size(), 0.0);
  scaling.added_mass = 0.0;
  scaling.scaled_elements = 0;
}

TimeStepCheck scale_mass_to_time_step(const ShellPart& part, const Matrix3X& x,
                                      MassScaling& scaling, VectorX& nodal_mass,
                                      VectorX& rotational_inertia) {
  const StableStep physical = compute_element_time_steps(part, x, scaling.element_dt);
  return scale_mass_to_element_steps(part, physical, scaling, nodal_mass, rotational_inertia);
}

TimeStepCheck scale_mass_to_element_steps(const ShellPart& part, const StableStep& physical,
                                          MassScaling& scaling, VectorX& nodal_mass,
                                          VectorX& rotational_inertia) {
  TimeStepCheck check;
  if (!scaling.enabled()) {
    check.dt = scaling.safety * physical.dt;
    check.element = physical.element;
    return check;
  }
  const double target = scaling.target_dt;
  const double trigger = target * (1.0 - kMassScalingTolerance);
  check.dt = std::numeric_limits<double>::infinity();
  const int n_el = element_count(part);
  const int n_quads = static_cast<int>(part.quads.cols());
  for (int e = 0; e < n_el; ++e) {
    const auto ei = static_cast<std::size_t>(e);
    const double physical_dt = scaling.safety * scaling.element_dt[ei];
    double factor = scaling.density_factor[ei];
    double dt = physical_dt * std::sqrt(factor);
    if (dt < trigger) {
      // dt_e ~ 1 / sqrt(rho): this factor brings the element's step to the target.
      const double ratio = target / physical_dt;
      const double new_factor = ratio * ratio;
      // Shared equally by the element's nodes, as the lumped mass (4 for a quad, 3 for a
      // triangle).
      const int n_nodes = e < n_quads ? 4 : 3;
      const double node_mass = (new_factor - factor) * scaling.element_mass[ei] / n_nodes;
      const double node_inertia = scaling.inertia_factor[ei] * node_mass;
      for (int a = 0; a < n_nodes; ++a) {
        const int node = e < n_quads ? part.quads(a, e) : part.triangles(a, e - n_quads);
        nodal_mass[node] += node_mass;
        rotational_inertia[node] += node_inertia;
      }
      if (factor == 1.0) {
        ++scaling.scaled_elements;
      }
      const double added = (new_factor - factor) * scaling.element_mass[ei];
      check.mass_added += added;
      scaling.added_mass += added;
      scaling.density_factor[ei] = new_factor;
      factor = new_factor;
      dt = physical_dt * std::sqrt(factor);
    }
    if (dt < check.dt) {
      check.dt = dt;
      check.element = e;
    }
  }
  return check;
}

}  // namespace sf
