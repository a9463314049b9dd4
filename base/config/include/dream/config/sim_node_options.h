#pragma once

#include <cstdint>
#include <string>

namespace dream::config {

/// How the world paces its steps.
enum class WorldMode {
  /// Step k+1 only after every live agent answered step k: deterministic for
  /// a seed, as fast as the agents can go.
  kLockstep,
  /// One step per 0.033 s of wall time with each robot's latest command, as
  /// on the Robotarium.
  kRealTime,
};

/// Parses "lockstep" / "realtime". @throws std::invalid_argument otherwise.
WorldMode ParseWorldMode(const std::string& text);
const char* WorldModeName(WorldMode mode);

/// Options of SimNode. Wall-clock durations are in seconds of real time;
/// everything else is in simulated steps.
struct SimNodeOptions {
  WorldMode mode = WorldMode::kLockstep;
  /// The run ends after this many steps. Must be >= 1.
  int64_t max_steps = 3000;
  /// End the run early once every robot's command says done.
  bool stop_when_done = true;
  /// `world.script_ends_run`: a Robotarium script's run (dream run SCRIPT.py
  /// writes it in the run's config): the script is every robot's agent and the run ends with it.
  /// Every robot's command for a step saying done ends the run at that step,
  /// those commands not applied (the script's last step() was the run's last
  /// step, as the official simulator counts); every robot's controller failed
  /// (DREAM_FAULT: the script raised) ends it at once, the script's error its reason.
  bool script_ends_run = false;
  /// Lockstep: an agent silent this long (wall time) is marked lost and its
  /// robot stops; it rejoins when it speaks again. Must be > 0.
  double agent_timeout_s = 2.0;
  /// Wall time to wait at step 0 for every robot's agent. Must be > 0.
  double start_timeout_s = 30.0;
  /// While waiting, the current step is published again this often, so a
  /// datagram lost on udpm cannot stall the run. At least
  /// kMinResendIntervalS: more often floods the bus (memq's queue overflows
  /// and the agents' answers are lost with the rest).
  double resend_interval_s = 0.25;
  static constexpr double kMinResendIntervalS = 0.01;
  /// Commands beyond these magnitudes (or NaN/inf) are rejected as absurd and
  /// the robot holds still. Far above the Robotarium's limits (0.2 m/s,
  /// 3.6 rad/s): merely fast commands are saturated and counted as actuator
  /// warnings, as on the Robotarium.
  double max_abs_v_mps = 10.0;
  double max_abs_w_radps = 100.0;
  /// Both limits under `world.command_limits: official`: any finite command
  /// is taken (and saturated at the wheels), as the official simulator does.
  static constexpr double kOfficialCommandLimit = 1e12;
  /// Progress lines every this many wall seconds when the output is not a
  /// terminal (0: no progress at all). The CLI shows them through a
  /// ProgressReporter (SimNode::set_progress_reporter); a terminal gets a bar.
  double progress_interval_s = 2.0;
  /// Simulated seconds per wall second, to watch a run (dream run --view,
  /// --pace). Lockstep: a step is taken no sooner than this pace allows
  /// (still only once every live robot answered: the run is the same); 0
  /// (the default): as fast as the agents answer. Real time: the step period
  /// is time_step / pace (0 means 1). At most kMaxPace.
  double pace = 0.0;
  static constexpr double kMaxPace = 1000.0;

  /// False with a message naming the field, its value and the allowed range.
  bool IsValid(std::string* error) const;
};

}  // namespace dream::config
