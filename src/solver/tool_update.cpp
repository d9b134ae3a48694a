#include "solver/tool_update.hpp"

#include "model/operation_plan.hpp"

namespace sf {

// A force-controlled tool's travel at t(n+1) is found in the same cycle as the blank's positions,
// so the contact at t(n+1) sees both at t(n+1).
void move_tools(const Model& model, SolutionState& s, double time_before, double weight,
                double dt) {
  for (std::size_t t = 0; t < s.tools.size(); ++t) {
    ToolState& tool = s.tools[t];
    tool.previous_displacement = tool.displacement;
    tool.previous_force = tool.force;
    tool.previous_rotation = tool.rotation;
    tool.previous_moment = tool.moment;
    if (tool.held) {
      continue;  // travel and displacement stay
    }
    if (const auto& driven = model.tools[t].force_control) {
      driven->step(time_before, tool.force, weight, dt, tool.velocity, tool.travel);
      tool.displacement = tool.travel * driven->direction();
    } else {
      const int index = static_cast<int>(t);
      const ToolStanding here = standing_in_effect(model, index, tool.origin, s.time);
      tool.travel = here.travel;
      tool.displacement = here.placement.translation;
      tool.rotation = here.placement.rotation;
      tool.angle = here.angle;
    }
  }
}

double press_torque(const Model& model, int tool, const ToolState& state) {
  const RigidToolMotion& motion = motion_in_effect(model, tool, state.origin);
  const ToolPlacement here{state.rotation, state.displacement};
  const Vec3 axis = state.rotation * motion.axis();
  const Vec3 pivot = here.apply(motion.pivot());
  return -(state.moment - pivot.cross(state.force)).dot(axis);
}

}  // namespace sf
