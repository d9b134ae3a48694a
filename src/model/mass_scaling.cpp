#include "model/mass_scaling.hpp"

#include <cmath>
#include <cstddef>

#include "element/element_block.hpp"
#include "element/shell_mass.hpp"

namespace sf {

void set_up_mass_scaling(const ShellPart& part, const Matrix3X& x, const ShellState& state,
                         double target_dt, double safety, MassScaling& scaling) {
  scaling.target_dt = target_dt;
  scaling.safety = safety;
  compute_element_masses(part, x, state, scaling.element_mass, scaling.inertia_factor);
  const std::size_t n = scaling.element_mass.size();
  scaling.density_factor.assign(n, 1.0);
  scaling.element_dt.assign(n, 0.0);
  scaling.scaled_dt.assign(n, 0.0);
  const auto corners = static_cast<std::size_t>(corner_count(part));
  scaling.corner_mass.assign(kMassCornerWidth * corners, 0.0);
  scaling.added_mass = 0.0;
  scaling.scaled_elements = 0;
}

namespace {

// Element e's density raised to the target if its step is below it; its step after, the mass
// it added and its nodes' shares written to its corner slots (0 if it added none).
void raise_element_density(const ElementBlock& block, int e, MassScaling& scaling,
                           DensityRaise& raise) {
  const auto ei = static_cast<std::size_t>(e);
  const int n_nodes = block.nodes_per_element();  // the lumped mass's equal shares
  const int first_slot = block.corner_slot(e, 0);
  double* corners =
      scaling.corner_mass.data() + kMassCornerWidth * static_cast<std::ptrdiff_t>(first_slot);
  const double physical_dt = scaling.safety * scaling.element_dt[ei];
  const double factor = scaling.density_factor[ei];
  double node_mass = 0.0;
  double node_inertia = 0.0;
  double dt = physical_dt * std::sqrt(factor);
  if (dt < scaling.target_dt * (1.0 - kMassScalingTolerance)) {
    // dt_e ~ 1 / sqrt(rho): this factor brings the element's step to the target.
    const double ratio = scaling.target_dt / physical_dt;
    const double new_factor = ratio * ratio;
    node_mass = (new_factor - factor) * scaling.element_mass[ei] / n_nodes;
    node_inertia = scaling.inertia_factor[ei] * node_mass;
    if (factor == 1.0) {
      raise.newly_scaled.add(1.0);
    }
    raise.added_mass.add((new_factor - factor) * scaling.element_mass[ei]);
    scaling.density_factor[ei] = new_factor;
    dt = physical_dt * std::sqrt(new_factor);
  }
  for (int a = 0; a < n_nodes; ++a) {
    corners[kMassCornerWidth * a] = node_mass;
    corners[kMassCornerWidth * a + 1] = node_inertia;
  }
  scaling.scaled_dt[ei] = dt;
}

}  // namespace

DensityRaise raise_element_densities(const ShellPart& part, std::span<const ElementRun> runs,
                                     MassScaling& scaling) {
  DensityRaise raise;
  const ElementBlocks blocks = element_blocks(part);
  if (runs.empty()) {
    for (const ElementBlock& block : blocks) {
      for (int e = block.first; e < block.end(); ++e) {
        raise_element_density(block, e, scaling, raise);
      }
    }
    return raise;
  }
  for (const ElementRun& run : runs) {  // each run within one block (element_runs)
    const ElementBlock& block = blocks.of(run.begin);
    for (int e = run.begin; e < run.end; ++e) {
      raise_element_density(block, e, scaling, raise);
    }
  }
  return raise;
}

TimeStepCheck scale_mass_to_time_step(const ShellPart& part, const NodeCorners& nodes,
                                      const Matrix3X& x, MassScaling& scaling, VectorX& nodal_mass,
                                      VectorX& rotational_inertia) {
  const StableStep physical = compute_element_time_steps(part, x, scaling.element_dt);
  TimeStepCheck check;
  if (!scaling.enabled()) {
    check.dt = scaling.safety * physical.dt;
    check.element = physical.element;
    return check;
  }
  const DensityRaise raise = raise_element_densities(part, {}, scaling);
  check.mass_added = raise.added_mass.round();
  if (check.mass_added > 0.0) {
    add_corner_masses(nodes, scaling.corner_mass, nodal_mass, rotational_inertia);
    scaling.added_mass += check.mass_added;
    scaling.scaled_elements += static_cast<int>(raise.newly_scaled.round());
  }
  const StableStep scaled = smallest_time_step(scaling.scaled_dt);
  check.dt = scaled.dt;
  check.element = scaled.element;
  return check;
}

}  // namespace sf
