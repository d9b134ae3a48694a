#pragma once
// The press line's operations as the solver runs them ([[operations]], docs/process-chain.md):
// per operation, the tools in play, the motions it redefines, and what ends it. A case without
// [[operations]] has none: it runs as one forming operation to time.end_time.
#include <optional>
#include <string>
#include <vector>

#include "casefile/case_config.hpp"
#include "core/types.hpp"
#include "model/rigid_tool_motion.hpp"

namespace sf {

struct Operation {
  std::string name;
  std::string entry;  ///< "operations[1] ('OP20-draw')", for messages
  OperationConfig::Kind kind = OperationConfig::Kind::forming;
  OperationConfig::End end = OperationConfig::End::time;
  /// per tool: in play (its contact acts and it moves) or standing still out of contact
  std::vector<unsigned char> in_play;
  /// per tool: the motion this operation gives it (time from the operation's start), or none
  std::vector<std::optional<RigidToolMotion>> motions;
  int tool = -1;         ///< the tool of a stroke, force or gap end
  int gap_to = -1;       ///< a gap end's other tool
  double stroke = 0.0;   ///< mm, the tool's travel since the case's start
  double time = 0.0;     ///< s: a time end's duration, else the longest the operation may take
  double force = 0.0;    ///< N, push against the tool's motion
  double gap = 0.0;      ///< mm
  double rest = 1e-3;    ///< -, kinetic energy / its peak
  double damping = 0.0;  ///< 1/s, mass-proportional
  /// mm: a gap end's clearance from `tool` to `gap_to` along `tool`'s direction with both at
  /// their reference positions (the clearance at a time is this less their relative travel)
  double reference_clearance = 0.0;
  /// s, the end the plan expects: a stroke or time end's when the operations before it end as
  /// planned, else its start plus `time` (the model's time.end_time is the last one's)
  double planned_end = 0.0;
  /// A trim's line (mm, a closed polyline), the direction it is projected along and the side
  /// kept (solver/trim.hpp).
  std::vector<Vec3> trim_line;
  /// Or (trim_line empty) the outline of this tool where it stands at the trim, grown by
  /// trim_offset (mm)
  int trim_tool = -1;
  double trim_offset = 0.0;
  Vec3 trim_direction = Vec3(0.0, 0.0, -1.0);
  /// Cut the elements the line crosses along it (solver/trim_cut.hpp), else remove them by
  /// their centres (solver/trim.hpp)
  bool trim_cut = false;
  double sliver_fraction = 0.1;  ///< -, a cut's smallest piece over its parent element
  bool keep_inside = true;
};

/// Where a tool's motion in effect starts: the operation that gave it (-1: the case's own
/// [[tools]] motion), the time it counts from and the travel, placement and turn it adds to.
struct ToolMotionOrigin {
  int operation = -1;
  double start = 0.0;                ///< s
  double travel = 0.0;               ///< mm
  Vec3 displacement = Vec3::Zero();  ///< mm, the placement's translation
  Mat3 rotation = Mat3::Identity();  ///< the placement's rotation (contact/tool_placement.hpp)
  double angle = 0.0;                ///< rad, the turn it adds to
};

}  // namespace sf
