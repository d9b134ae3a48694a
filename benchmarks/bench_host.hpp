#pragma once
// The host a benchmark ran on, as its figures must name it: the CPU's model name from
// /proc/cpuinfo (what `lscpu` prints), or "unknown".
#include <fstream>
#include <string>

namespace sf::bench {

inline std::string machine_name() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(colon + 2);
    }
  }
  return "unknown";
}

}  // namespace sf::bench
