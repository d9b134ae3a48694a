#include "model/node_frames.hpp"

namespace sf {

void NodeFrames::set(int node, const NodeFrame& frame) {
  int& at = index_.at(static_cast<std::size_t>(node));
  if (at < 0) {
    at = static_cast<int>(frames_.size());
    frames_.push_back(frame);
  } else {
    frames_[static_cast<std::size_t>(at)] = frame;
  }
}

Vec3 NodeFrames::axis(int node, int dof) const {
  if (!has(node)) {
    return Vec3::Unit(dof % 3);
  }
  const NodeFrame& f = of(node);
  return dof < 3 ? Vec3(f.translation.col(dof)) : Vec3(f.rotation.col(dof - 3));
}

}  // namespace sf
