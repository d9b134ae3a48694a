#pragma once
// Every part of the run state that a restart needs: the fields of state_fields.hpp with the
// checkpoint role, in their order. The checkpoint writer, its reader and the gather of a
// distributed run's state all walk this list.
//
// A visitor has
//   scalar(name, double& | long& | int& | bool&)   a number of the run or of a tool
//   nodes(name, Matrix3X& | VectorX&)              a per-node array (columns or entries)
//   elements(name, std::vector<double>&, n)        a per-element array (n elements; may be empty)
// and is called with a SolutionState or a const one.
#include <string>
#include <type_traits>

#include "solver/state_fields.hpp"

namespace sf {

/// Visits the state's checkpointed fields. What is left out (state_fields.hpp, kStateLeftOut)
/// is scratch, rebuilt exactly, the model's, or never set when a checkpoint is written.
/// tests/solver/test_checkpoint_layout.cpp pins the order, names and kinds (format 1).
template <class Visitor, class State>
void visit_checkpoint_fields(Visitor& v, State& s) {
  const int n_elements = s.shell.n_elements;
  auto by_kind = [&](const StateField& field, const std::string& key, auto& value) {
    if (!field.has(field_role::checkpoint)) {
      return;
    }
    using T = std::remove_cvref_t<decltype(value)>;
    if constexpr (std::is_arithmetic_v<T>) {
      v.scalar(key, value);
    } else if constexpr (std::is_same_v<T, std::vector<double>>) {
      v.elements(key, value, n_elements);
    } else {
      v.nodes(key, value);
    }
  };
  visit_state_fields(by_kind, s);
}

}  // namespace sf
