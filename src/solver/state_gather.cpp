#include "solver/state_gather.hpp"

#include <type_traits>

#include "solver/state_fields.hpp"

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

// Gathers the per-node and per-element arrays of the fields with a role; scalars are the same
// on every process (exact all-reduces, replicated tools) and stay as they are.
class FieldGather {
 public:
  FieldGather(Domain& domain, int n_elements) : domain_(domain), n_elements_(n_elements) {}
  template <class T>
  void operator()(const StateField& /*field*/, const std::string& /*key*/, T& value) {
    if constexpr (std::is_same_v<T, std::vector<double>>) {
      gather_element_field(domain_, value, n_elements_);
    } else if constexpr (!std::is_arithmetic_v<T>) {
      if (value.size() > 0) {  // empty alike on every process (friction, distance bounds off)
        gather_node_field(domain_, value);
      }
    }
  }

 private:
  Domain& domain_;
  int n_elements_;
};

void gather_fields_to_root(SolutionState& s, unsigned role) {
  if (s.domain->processes() == 1) {
    return;
  }
  FieldGather gather(*s.domain, s.shell.n_elements);
  visit_state_fields_with(role, gather, s);
}

}  // namespace

void gather_checkpoint_state_to_root(SolutionState& s) {
  gather_fields_to_root(s, field_role::checkpoint);
}

void gather_formed_part_to_root(SolutionState& s) {
  gather_fields_to_root(s, field_role::formed_part);
}

void gather_state_to_root(SolutionState& s) {
  gather_fields_to_root(s, field_role::output);
}

}  // namespace sf
