#pragma once
// Names that become part of the results (tool and part names, draw-in names, history groups):
// HDF5 link names, XML attribute values and file names. They are kept plain.
#include <string_view>

namespace sf {

/// Letters, digits, '_', '-' and '.', not empty and not starting with '.'.
inline bool is_plain_name(std::string_view name) {
  if (name.empty() || name.front() == '.') {
    return false;
  }
  for (const char c : name) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       c == '_' || c == '-' || c == '.';
    if (!plain) {
      return false;
    }
  }
  return true;
}

/// What a user is told a plain name is.
inline constexpr std::string_view kPlainNameRule =
    "letters, digits, '_', '-', '.', not starting with '.' (it names results: HDF5 datasets, "
    "XDMF files)";

}  // namespace sf
