#pragma once
// A blank node seen from a rigid tool that translates and may turn (its mesh's point X stands at
// R X + displacement): the node in the tool's mesh frame, and the step of the tool's point where
// the node is. Shared by the penalty contact and the drawbead lines.
#include "contact/penalty_contact.hpp"

namespace sf {

/// Whether the tool turns now or turned a step ago (else the rotations are skipped).
inline bool tool_turns(const ContactKinematics& k) {
  return k.tool_rotation != Mat3::Identity() || k.tool_rotation_previous != Mat3::Identity();
}

/// Blank node i in the tool's mesh frame, R^T (x_i - displacement) (mm).
inline Vec3 node_in_tool_frame(const ContactKinematics& k, bool turns, int i) {
  return turns ? Vec3(k.tool_rotation.transpose() * (k.x.col(i) - k.tool_displacement))
               : Vec3(k.x.col(i) - k.tool_displacement);
}

/// The step over the last time step (mm) of the tool's point at p (its mesh frame):
/// (R - R_previous) p + the displacement's increment; a translating tool's own step.
inline Vec3 tool_step_at(const ContactKinematics& k, bool turns, const Vec3& p) {
  return turns ? Vec3((k.tool_rotation - k.tool_rotation_previous) * p +
                      k.tool_displacement_increment)
               : k.tool_displacement_increment;
}

}  // namespace sf
