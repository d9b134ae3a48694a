#pragma once
// The operations built from the case, and the rule that moves the tools across them
// (docs/process-chain.md, "Operations"):
// - a tool in play moves by the motion its operation gives it, counted from the operation's
//   start and added to where it stands then;
// - without one, it goes on with its motion in effect if it moved in the operation before (so
//   that one draw split in two operations is the same draw), and starts its case motion again,
//   from where it stands and from the operation's start, if it stood still;
// - a tool not in play stands still, out of contact.
#include "casefile/case_config.hpp"
#include "contact/tool_placement.hpp"
#include "model/model.hpp"

namespace sf {

/// Builds model.operations from config.operations (none: nothing) and sets time.end_time to the
/// last one's planned end. Throws InputError for a stroke a motion never reaches, or a gap end
/// whose tools never meet along the tool's direction.
void build_operations(const CaseConfig& config, Model& model);

/// Whether tool `tool` turns in its case motion or in any operation's motion.
bool ever_turns(const Model& model, int tool);

/// The motion in effect from `origin` (the case's own, or an operation's).
const RigidToolMotion& motion_in_effect(const Model& model, int tool,
                                        const ToolMotionOrigin& origin);
/// mm, the travel at time t (s) of a tool moving by its motion in effect from `origin`.
double travel_in_effect(const Model& model, int tool, const ToolMotionOrigin& origin, double t);
/// mm, its displacement at t.
Vec3 displacement_in_effect(const Model& model, int tool, const ToolMotionOrigin& origin, double t);
/// mm/s, its speed along the motion's direction at t.
double speed_in_effect(const Model& model, int tool, const ToolMotionOrigin& origin, double t);
/// Where it stands at t: the placement at `origin` turned about the motion's axis through its
/// pivot (both as the origin placed them) by the turn since, then moved by the travel since.
ToolPlacement placement_in_effect(const Model& model, int tool, const ToolMotionOrigin& origin,
                                  double t);
/// rad, its turn at t (the origin's and its motion's since).
double angle_in_effect(const Model& model, int tool, const ToolMotionOrigin& origin, double t);

/// s, when a stroke end's tool, moving by its motion in effect from `origin`, reaches the
/// operation's stroke; nullopt if it never does.
std::optional<double> stroke_end_time(const Model& model, const Operation& op,
                                      const ToolMotionOrigin& origin);

/// s, stroke_end_time, or InputError naming the operation when the tool, at `travel_now` (mm) at
/// the operation's start t0 (s), has passed the stroke already or never reaches it.
double checked_stroke_end(const Model& model, const Operation& op, const ToolMotionOrigin& origin,
                          double t0, double travel_now);

/// Where a tool stands: its travel (mm), placement and turn (rad).
struct ToolStanding {
  double travel = 0.0;
  ToolPlacement placement;
  double angle = 0.0;
};

/// Where the tool moving by its motion in effect from `origin` stands at t (s).
ToolStanding standing_in_effect(const Model& model, int tool, const ToolMotionOrigin& origin,
                                double t);

/// The origin of tool `tool`'s motion in operation `k` starting at time t0 (s), the tool then
/// standing at `here`, its origin before `before`, `moved`: whether it moved in the operation
/// before (in play there). Meaningless for a tool not in play in k.
ToolMotionOrigin origin_at_start(const Model& model, int k, int tool,
                                 const ToolMotionOrigin& before, bool moved, double t0,
                                 const ToolStanding& here);

}  // namespace sf
