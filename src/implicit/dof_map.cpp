#include "implicit/dof_map.hpp"

namespace sf {

DofMap::DofMap(const std::vector<unsigned char>& held, NodeFrames frames)
    : held_(held), frames_(std::move(frames)), equation_(6 * held.size(), -1) {
  for (std::size_t node = 0; node < held.size(); ++node) {
    for (int dof = 0; dof < 6; ++dof) {
      if ((held[node] & (1u << dof)) == 0) {
        equation_[6 * node + static_cast<std::size_t>(dof)] = equation_count_++;
        node_of_.push_back(static_cast<int>(node));
        dof_of_.push_back(static_cast<unsigned char>(dof));
      }
    }
  }
}

std::string DofMap::dof_name(int node, int dof) const {
  return frames_.has(node) ? std::string(kDofNames[dof]) + " (node axes)" : kDofNames[dof];
}

}  // namespace sf
