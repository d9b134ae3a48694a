#include "solver/state_gather.hpp"

#include "solver/checkpoint_fields.hpp"

namespace sf {

namespace {

void gather_node_field(Domain& domain, Matrix3X& field) {
  domain.gather_nodes(std::span<double>(field.data(), static_cast<std::size_t>(field.size())), 3);
}

void gather_node_field(Domain& domain, VectorX& field) {
  domain.gather_nodes(std::span<double>(field.data(), static_cast<std::size_t>(field.size())), 1);
}

// An element field of `per_element` values per element (nothing if it is not stored).
void gather_element_field(Domain& domain, std::vector<double>& field, int n_elements) {
  if (field.empty() || n_elements == 0) {
    return;
  }
  domain.gather_elements(field, static_cast<int>(field.size()) / n_elements);
}

// Gathers the checkpoint's per-node and per-element arrays; scalars are the same on every
// process (exact all-reduces, replicated tools) and stay as they are.
class CheckpointGather {
 public:
  explicit CheckpointGather(Domain& domain) : domain_(domain) {}
  template <class T>
  void scalar(const std::string& /*name*/, T& /*value*/) {}
  void nodes(const std::string& /*name*/, Matrix3X& a) {
    if (a.size() > 0) {  // empty alike on every process (friction, distance bounds off)
      gather_node_field(domain_, a);
    }
  }
  void nodes(const std::string& /*name*/, VectorX& a) {
    if (a.size() > 0) {
      gather_node_field(domain_, a);
    }
  }
  void elements(const std::string& /*name*/, std::vector<double>& a, int n) {
    gather_element_field(domain_, a, n);
  }

 private:
  Domain& domain_;
};

}  // namespace

void gather_checkpoint_state_to_root(SolutionState& s) {
  if (s.domain->processes() == 1) {
    return;
  }
  CheckpointGather gather(*s.domain);
  visit_checkpoint_fields(gather, s);
}

void gather_state_to_root(SolutionState& s) {
  Domain& domain = *s.domain;
  if (domain.processes() == 1) {
    return;
  }
  for (Matrix3X* field :
       {&s.x, &s.v, &s.omega, &s.rotation, &s.f_int, &s.m_int, &s.f_contact, &s.f_ext, &s.m_ext}) {
    gather_node_field(domain, *field);
  }
  for (VectorX* field : {&s.half_thickness, &s.mass, &s.rotational_inertia}) {
    gather_node_field(domain, *field);
  }
  ShellState& shell = s.shell;
  for (std::vector<double>* field :
       {&shell.sxx, &shell.syy, &shell.sxy, &shell.eps_p, &shell.flow_stress, &shell.flow_stress_at,
        &shell.sxz, &shell.syz, &shell.thickness, &shell.hourglass, &shell.director,
        &shell.back_stress}) {
    gather_element_field(domain, *field, shell.n_elements);
  }
  gather_element_field(domain, s.scaling.element_dt, shell.n_elements);
}

}  // namespace sf
