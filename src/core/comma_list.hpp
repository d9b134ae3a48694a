#pragma once
// A list of names kept as one comma-separated text (an HDF5 string attribute: a frame's fields,
// a formed part's left-out fields).
#include <algorithm>
#include <string>
#include <vector>

namespace sf {

/// The items of "a,b,c" in order ("" gives none).
inline std::vector<std::string> split_comma_list(const std::string& list) {
  std::vector<std::string> items;
  std::size_t begin = 0;
  while (begin < list.size()) {
    const std::size_t comma = std::min(list.find(',', begin), list.size());
    items.push_back(list.substr(begin, comma - begin));
    begin = comma + 1;
  }
  return items;
}

}  // namespace sf
