#include "implicit/static_constraints.hpp"

#include <fmt/core.h>

#include "core/errors.hpp"
#include "core/log.hpp"
#include "implicit/rigid_body_modes.hpp"

namespace sf {

StaticConstraints make_static_constraints(const Matrix3X& x, std::vector<unsigned char> held,
                                          ImplicitConfig::RigidBodyModes mode,
                                          const std::function<std::string(int)>& node_name,
                                          const NodeFrames& frames) {
  StaticConstraints c;
  const RigidBodyModes modes = find_free_rigid_body_modes(x, held, frames);
  c.free_modes = modes.free_modes;
  std::string listed;
  for (const std::string& m : modes.free_modes) {
    listed += (listed.empty() ? "" : "; ") + m;
  }
  if (modes.free_count > 0 && mode == ImplicitConfig::RigidBodyModes::error) {
    throw InputError(fmt::format(
        "static step: the constraints leave {} rigid-body mode{} free ({}), so the stiffness is "
        "singular; hold them with [[boundary]] entries, or set implicit.rigid_body_modes = "
        "\"auto\" to hold a minimal set of degrees of freedom automatically",
        modes.free_count, modes.free_count == 1 ? "" : "s", listed));
  }
  for (const auto& [node, dof] : modes.added) {
    held[static_cast<std::size_t>(node)] |= static_cast<unsigned char>(1u << dof);
    c.added.push_back(fmt::format("{} {}{}", node_name(node), kDofNames[dof],
                                  frames.has(node) ? " (node axes)" : ""));
  }
  c.added_holds = modes.added;
  if (!c.added.empty()) {
    std::string holds;
    for (const std::string& h : c.added) {
      holds += (holds.empty() ? "" : ", ") + h;
    }
    log_info("  rigid-body modes left free by the constraints: {}; held: {}\n", listed, holds);
  }
  c.dofs = DofMap(held, frames);
  return c;
}

}  // namespace sf
