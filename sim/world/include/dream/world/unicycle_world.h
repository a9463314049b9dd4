#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "dream/world/pose2.h"
#include "dream/world/rectangle_obstacle.h"
#include "dream/world/rectangle_obstacle_spec.h"
#include "dream/world/step_events.h"
#include "dream/world/unicycle_command.h"
#include "dream/world/violation_counts.h"
#include "dream/world/world.h"
#include "dream/world/world_params.h"

namespace dream::world {

class PairwiseRules;

// The Robotarium V2 world without any transport: unicycle robots, held
// velocity commands, the official validation rules, plus virtual rectangular
// obstacles and the hardware's command timeout.
//
// Step() does, in this order (same as rps/robotarium.py step()):
//  0. command timeout: a robot whose last SetCommand was issued at step c is
//     stopped (velocity zeroed) at the first step s with (s - c) * dt >
//     command_timeout_s. With dt = 0.033 s and 0.5 s: a command set at step k
//     still drives steps k..k+15 (15 * 0.033 = 0.495 s) and is zeroed at k+16.
//  1. validate the current poses and held velocities: +1 boundary error if any
//     robot is strictly outside the arena; +1 collision error per pair whose
//     centres, moved collision_offset forward along the heading, are <=
//     collision_diameter apart; +1 actuator error if any wheel speed exceeds
//     the limit; +1 obstacle collision per (robot, obstacle) pair whose
//     collision disc (same offset centre, radius collision_diameter / 2)
//     touches the obstacle at its current position.
//  2. saturate every wheel (uni->diff, clip, diff->uni) and keep the result as
//     the held velocity.
//  3. Euler step: x += dt v cos th; y += dt v sin th; th += dt w;
//     th = atan2(sin th, cos th).
//  4. advance the obstacles; step() + 1.
// Collisions are found with a uniform grid (cell >= collision
// diameter), giving exactly the brute-force pair count in O(N). Step() does
// not allocate once its event lists have grown to their working size.
// There is no robot-count limit here; the configuration layer enforces 50
// (128, the bus's bound, for a run declared `sim_only: true`).
class UnicycleWorld final : public World {
 public:
  // Throws std::invalid_argument if params or an obstacle spec is invalid,
  // obstacle ids repeat, or a pose is not finite.
  UnicycleWorld(const WorldParams& params, std::vector<Pose2> initial_poses,
                const std::vector<RectangleObstacleSpec>& obstacle_specs = {});
  ~UnicycleWorld() override;
  UnicycleWorld(UnicycleWorld&&) noexcept;
  UnicycleWorld& operator=(UnicycleWorld&&) noexcept;
  UnicycleWorld(const UnicycleWorld&) = delete;
  UnicycleWorld& operator=(const UnicycleWorld&) = delete;

  // Replaces the robot's held velocity (unsaturated, as the official
  // set_velocities stores it) and restarts its command timeout. Throws
  // std::out_of_range for a bad id, std::invalid_argument if not finite.
  void SetCommand(int robot_id, const UnicycleCommand& command) override;
  // Zeroes the held velocity (e.g. the robot's agent was lost). Throws
  // std::out_of_range for a bad id.
  void StopRobot(int robot_id) override;

  void Step() override;
  // Step() in which robot i moves for motion_time_s[i] instead of one time
  // step (the real lab's late steps and loop stalls: the robots keep driving
  // while the script is late); validation, obstacles and the clock are those
  // of one step. Throws std::invalid_argument unless there is one finite,
  // non-negative time per robot.
  void StepWithMotionTimes(const std::vector<double>& motion_time_s);

  int num_robots() const override { return static_cast<int>(poses_.size()); }
  // Poses at time step() * dt.
  const std::vector<Pose2>& poses() const override { return poses_; }
  // Held velocities: as set by SetCommand, or saturated by the last Step.
  const std::vector<UnicycleCommand>& velocities() const override { return velocities_; }
  // Obstacles at time step() * dt (centre, size, velocity).
  const std::vector<RectangleObstacle>& obstacles() const { return obstacles_; }
  // The same as plain states, for whoever publishes any World.
  void GetObstacleStates(std::vector<ObstacleState>* states) const override;
  // Number of steps taken.
  int64_t step() const override { return step_; }
  // step() * the time step in whole microseconds (33,000 on the Robotarium).
  int64_t utime() const override { return step_ * step_utime_; }
  double time_step_s() const override { return params_.time_step_s; }
  double time_s() const { return static_cast<double>(step_) * params_.time_step_s; }
  const ViolationCounts& violations() const override { return violations_; }
  // What the most recent Step() found (step == -1 before the first).
  const StepEvents& last_step_events() const { return events_; }
  const WorldParams& params() const { return params_; }
  // Largest command age, in steps, that is still applied (15 for the
  // Robotarium); INT64_MAX when the timeout is disabled.
  int64_t command_hold_steps() const { return command_hold_steps_; }

 private:
  static constexpr int64_t kNoCommand = -1;

  void CheckRobotId(int robot_id, const char* caller) const;
  void ApplyCommandTimeouts();
  // Step()'s body; robot i moves for motion_time_s[i], or one time step when null.
  void StepRobots(const double* motion_time_s);

  WorldParams params_;
  std::vector<Pose2> poses_;
  std::vector<UnicycleCommand> velocities_;
  std::vector<RectangleObstacle> obstacles_;
  // Step index at which each robot's current command was set, or kNoCommand.
  std::vector<int64_t> command_step_;
  int64_t command_hold_steps_ = 0;
  int64_t step_utime_ = 0;
  int64_t step_ = 0;
  ViolationCounts violations_{};
  StepEvents events_{};

  // Collision centres and the rules on them, sized once.
  std::unique_ptr<PairwiseRules> pairwise_rules_;
};

}  // namespace dream::world
