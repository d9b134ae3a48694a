#pragma once
// Expects `f` to throw an InputError whose message holds every one of `parts`.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "core/errors.hpp"

namespace sf::test {

inline void expect_input_error(const std::function<void()>& f,
                               const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string text = e.what();
    for (const std::string& p : parts) {
      EXPECT_NE(text.find(p), std::string::npos) << "'" << p << "' not in: " << text;
    }
  }
}

}  // namespace sf::test
