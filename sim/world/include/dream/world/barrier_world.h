#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "dream/barriers/unicycle_barrier.h"
#include "dream/world/world.h"

namespace dream::world {

/// A world whose robots' commands pass through the Robotarium's unicycle
/// barrier certificate before every step (config `barriers:` with
/// `apply_in: world`), as a Robotarium script's `dxu = barrier(dxu, x)` does
/// before `set_velocities`: all robots' commands at once, on the poses the
/// robots are seen at (`poses()`: the measured ones under `world.realism`,
/// what the lab's script reads from `get_poses()`). A robot without a command
/// (lost, silent) enters the QP standing still, so the others keep clear of
/// it. When the QP fails every robot stops for that step, as in rps.
///
/// Everything else is the wrapped world's: its step, checks and counts;
/// SteppingWorldOf() gives it to code that asks what kind of world runs.
class BarrierWorld final : public World {
 public:
  /// @throws std::invalid_argument for bad barrier parameters.
  BarrierWorld(std::unique_ptr<World> inner, const barriers::UnicycleBarrierParams& params);

  int num_robots() const override { return inner_->num_robots(); }
  int64_t step() const override { return inner_->step(); }
  int64_t utime() const override { return inner_->utime(); }
  double time_step_s() const override { return inner_->time_step_s(); }
  const std::vector<Pose2>& poses() const override { return inner_->poses(); }
  /// What the robots drove with: the certificate's commands, saturated.
  const std::vector<UnicycleCommand>& velocities() const override { return inner_->velocities(); }
  void GetObstacleStates(std::vector<ObstacleState>* states) const override { inner_->GetObstacleStates(states); }
  const ViolationCounts& violations() const override { return inner_->violations(); }
  void SetCommand(int robot_id, const UnicycleCommand& command) override;
  void StopRobot(int robot_id) override;
  /// Filters the held commands through the certificate, then steps.
  void Step() override;
  int64_t last_step() const override { return inner_->last_step(); }
  /// The world that steps (a UnicycleWorld or RealisticWorld).
  const World& inner() const { return *inner_; }

  /// Steps whose QP failed (every robot was stopped for them).
  int64_t failed_steps() const { return failed_steps_; }
  /// Steps where the certificate changed some robot's command by more than 1e-9.
  int64_t steps_changed() const { return steps_changed_; }
  const barriers::UnicycleBarrierParams& params() const { return barrier_.params(); }

 private:
  std::unique_ptr<World> inner_;
  barriers::UnicycleBarrier barrier_;
  std::vector<UnicycleCommand> wanted_;
  std::vector<bool> commanded_;
  Eigen::Matrix2Xd commands_;
  Eigen::Matrix3Xd pose_matrix_;
  int64_t failed_steps_ = 0;
  int64_t steps_changed_ = 0;
};

/// `world`, or the world a BarrierWorld wraps: what code that asks which kind
/// of world runs (a RealisticWorld?) looks at.
const World& SteppingWorldOf(const World& world);

}  // namespace dream::world
