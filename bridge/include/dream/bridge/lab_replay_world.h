#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dream/bridge/run_track.h"
#include "dream/world/violation_checker.h"
#include "dream/world/world.h"
#include "dream/world/world_params.h"

namespace dream::node {
class RunRecorder;
}  // namespace dream::node

namespace dream::bridge {

/// The bridge world: a lab run (imported with `dream import`) replayed step
/// by step. The poses, velocities and obstacles it offers are the lab's, at
/// the lab's timestamps; commands from agents change nothing in it and are
/// kept beside the lab's (agent_command()), so the same agent processes that
/// ran against the simulator run against the real poses, unchanged, and
/// their commands can be compared with what the lab executed. Violations are
/// counted on the lab's poses with the Robotarium's rules.
class LabReplayWorld final : public world::World {
 public:
  /// @param track the lab run; needs at least one step.
  /// @param lab_command_log if not null, the lab's command of every robot is
  ///        written to it as DREAM_LAB_CMD_<id> at every step (must outlive
  ///        the world).
  /// @throws std::invalid_argument when the track is empty or inconsistent.
  LabReplayWorld(RunTrack track, const world::WorldParams& params, node::RunRecorder* lab_command_log = nullptr);

  int num_robots() const override { return track_.num_robots; }
  int64_t step() const override { return step_; }
  int64_t utime() const override { return track_.utime[static_cast<size_t>(step_)]; }
  double time_step_s() const override { return params_.time_step_s; }
  const std::vector<world::Pose2>& poses() const override { return poses_; }
  const std::vector<world::UnicycleCommand>& velocities() const override { return velocities_; }
  void GetObstacleStates(std::vector<world::ObstacleState>* states) const override;
  const world::ViolationCounts& violations() const override { return checker_.counts(); }
  void SetCommand(int robot_id, const world::UnicycleCommand& command) override;
  void StopRobot(int robot_id) override;
  /// Validates the lab's poses of this step with the lab's commands, records
  /// the agents' held commands for it, moves on to the next recorded step.
  /// @throws std::out_of_range past the last recorded step.
  void Step() override;
  int64_t last_step() const override { return track_.last_step(); }

  const RunTrack& track() const { return track_; }
  /// Whether an agent had a command for `robot` at `step` (< step()).
  bool has_agent_command(int64_t step, int robot) const;
  /// The agent's command for `robot` at `step` (zero when it had none).
  const world::UnicycleCommand& agent_command(int64_t step, int robot) const;

 private:
  void Load();
  void CheckRobotId(int robot_id, const char* caller) const;

  RunTrack track_;
  world::WorldParams params_;
  node::RunRecorder* lab_command_log_;
  world::ViolationChecker checker_;
  int64_t step_ = 0;
  std::vector<world::Pose2> poses_;
  std::vector<world::UnicycleCommand> velocities_;
  std::vector<world::UnicycleCommand> lab_commands_;  // this step's, for the actuator check
  std::vector<world::UnicycleCommand> held_;          // agents' current commands
  std::vector<uint8_t> has_held_;
  std::vector<world::UnicycleCommand> agent_commands_;  // step-major, steps 0..last_step()-1
  std::vector<uint8_t> has_agent_command_;
};

}  // namespace dream::bridge
