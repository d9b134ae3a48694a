#pragma once
// A file's path as messages show it: 'path'.
#include <fmt/core.h>

#include <filesystem>
#include <string>

namespace sf {

inline std::string quoted(const std::filesystem::path& path) {
  return fmt::format("'{}'", path.string());
}

}  // namespace sf
