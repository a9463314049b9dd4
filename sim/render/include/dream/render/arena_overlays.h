#pragma once

#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "dream/robot_poses_t.hpp"
#include "dream/world/located_violation.h"

namespace dream::render {

/// How far a robot's sensor sees: `range_m` within a field of view of
/// `field_of_view_rad` centred on `direction_rad` from its heading.
struct SensorReach {
  double range_m = 1.0;
  double direction_rad = 0.0;
  double field_of_view_rad = 2 * M_PI;
};

/// What a run's config adds to its pictures, beyond what the log holds: the
/// goals, the sensors' reach and who hears whom on the radio. All optional;
/// the log alone draws the run. (The `dream` command fills this from the run
/// folder's config.yaml; see docs/rendering.md.)
struct ArenaOverlays {
  /// True when robot `receiver` hears robot `sender` with the robots at `poses`.
  using RadioHearing = std::function<bool(int receiver, int sender, const robot_poses_t& poses)>;

  /// goals_m[i]: robot i's goals in order (none: no markers).
  std::vector<std::vector<std::array<double, 2>>> goals_m;
  /// The robots' movement/obstacle sensors, drawn round each robot when
  /// draw_sensor_ranges is set.
  std::vector<SensorReach> sensor_reaches;
  bool draw_sensor_ranges = false;
  /// Who hears whom; drawn when draw_radio_links is set: each DREAM_RADIO_<n>
  /// broadcast as lines from its sender to the robots that hear it, or, in a
  /// log without radio messages, every pair that could hear each other.
  RadioHearing hears;
  bool draw_radio_links = false;
  /// What the controllers drew (DREAM_DRAW_<id> in the log): a picture shows
  /// each robot's drawing at its last step, a video frame at its step.
  bool draw_drawings = true;
  /// The run's name (config `name`, summary.json "run") and verdict
  /// (RunVerdictName: "clean", "warning", "rejected"; summary.json "verdict"),
  /// written at the start of the caption; empty: not shown.
  std::string run_name;
  std::string verdict;
  /// A run declared `sim_only: true` (summary.json "sim_only"): the caption
  /// says so, so that a clean picture is not taken for a lab-ready run.
  bool sim_only = false;
  /// The run's violations, located (LocateViolations on its log): each marked
  /// where it happened with its first step; none: no marks.
  world::LocatedViolations violations;
};

/// `overlays`' run name and verdict as the start of a caption, each followed
/// by " — " ("go_to_goal — clean (no errors or warnings) — "); a known verdict
/// is explained unless `short_verdict`; then "sim-only run (never to the lab)
/// — " for a sim_only run. Empty when none is known.
std::string RunLabel(const ArenaOverlays& overlays, bool short_verdict = false);

}  // namespace dream::render
