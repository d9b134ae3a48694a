#pragma once
// The bytes of every state field with a role (solver/state_fields.hpp), by key: two states are
// the same bits where their maps are equal. Run numbers as the files keep them (a double).
#include <map>
#include <string>
#include <type_traits>

#include "solver/state_fields.hpp"

namespace sf::test {

inline std::map<std::string, std::string> state_field_bytes(const SolutionState& s, unsigned role) {
  std::map<std::string, std::string> bytes;
  auto record = [&](const StateField&, const std::string& key, const auto& value) {
    using T = std::remove_cvref_t<decltype(value)>;
    if constexpr (std::is_arithmetic_v<T>) {
      const double as_double = static_cast<double>(value);
      bytes[key] = std::string(reinterpret_cast<const char*>(&as_double), sizeof(double));
    } else {
      bytes[key] = std::string(reinterpret_cast<const char*>(value.data()),
                               sizeof(double) * static_cast<std::size_t>(value.size()));
    }
  };
  visit_state_fields_with(role, record, s);
  return bytes;
}

}  // namespace sf::test
