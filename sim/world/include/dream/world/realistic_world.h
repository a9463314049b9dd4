#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

#include "dream/world/pose2.h"
#include "dream/world/realism_params.h"
#include "dream/world/rectangle_obstacle_spec.h"
#include "dream/world/robot_response.h"
#include "dream/world/robot_traits.h"
#include "dream/world/unicycle_command.h"
#include "dream/world/unicycle_world.h"
#include "dream/world/verdict_reason.h"
#include "dream/world/violation_counts.h"
#include "dream/world/wheel_speeds.h"
#include "dream/world/world.h"
#include "dream/world/world_params.h"

namespace dream::world {

class RealismRandom;

// The official world (a UnicycleWorld, the truth) seen and driven as on the
// real lab (world.realism): poses() and velocities() are what the tracker
// measures and what the agents are sent; commands reach the robots through
// the firmware's models. Violations are those of the true state.
//
// Step() does, for each robot:
//  1. deliver: a command set at step k acts from step k + command_latency_steps
//     (the newest one due wins);
//  2. brake: a robot whose delivered command is older than command_brake_s
//     stops at once (as UnicycleWorld's command timeout, counted from when the
//     command reached the robot, late steps and stalls included);
//  3-4. respond (RobotResponse): dead zone, wheel speeds with axle_length_m
//     clipped to the limit, each wheel's lag (motor_lag_s, motor_startup_m) or
//     acceleration limit, then the robot's own gains and heading drift
//     (RobotTraits, drawn once from the seed);
//  5. the true world steps with what the robot drives (its wheel saturation
//     uses axle_length_m). A late step (step_overrun_mean_s) or a loop stall
//     (loop_stall_probability, loop_stall_max_s) lasts longer than a time
//     step: the robots drive on through it until their brake;
//  6. measure: the true poses of step k + 1 - pose_delay_steps, plus Gaussian
//     noise (pose_noise_moving_factor times larger for a moving robot),
//     rounded to the quanta; in a dropout (one starts with
//     tracking_dropout_probability, times tracking_dropout_at_rest_factor for
//     a robot at rest, and lasts tracking_dropout_mean_steps on average) the
//     robot's previous measurement is kept instead. A robot without a new
//     measurement for longer than tracker_drop_s is lost to the tracker: its
//     last measurement is kept for the rest of the run (the robot itself
//     still drives).
// Actuator errors are counted on the commands as sent, with the official
// wheel radius and base length, as the Robotarium does; boundary, collision
// and obstacle errors on the true poses.
// Random numbers come from `seed` only, one stream per model, so a lockstep
// run repeats exactly; with tracking_dropout_mean_steps 1 and tracker_drop_s
// 0 the draws and poses are those of independent dropouts.
class RealisticWorld final : public World {
 public:
  // Throws std::invalid_argument if params, realism, an obstacle or a pose is
  // invalid.
  RealisticWorld(const WorldParams& params, const RealismParams& realism, uint64_t seed,
                 std::vector<Pose2> initial_poses, const std::vector<RectangleObstacleSpec>& obstacle_specs = {});
  ~RealisticWorld() override;
  RealisticWorld(const RealisticWorld&) = delete;
  RealisticWorld& operator=(const RealisticWorld&) = delete;

  int num_robots() const override { return truth_.num_robots(); }
  int64_t step() const override { return truth_.step(); }
  int64_t utime() const override { return truth_.utime(); }
  double time_step_s() const override { return truth_.time_step_s(); }
  // Measured poses: what the agents are sent.
  const std::vector<Pose2>& poses() const override { return measured_poses_; }
  // The measured poses' velocities (of the same, delayed, step).
  const std::vector<UnicycleCommand>& velocities() const override { return measured_velocities_; }
  void GetObstacleStates(std::vector<ObstacleState>* states) const override { truth_.GetObstacleStates(states); }
  const ViolationCounts& violations() const override { return violations_; }

  // Queues the command for step() + command_latency_steps. Throws like
  // UnicycleWorld::SetCommand.
  void SetCommand(int robot_id, const UnicycleCommand& command) override;
  // Stops the robot at once (its agent is lost) and drops its queued commands.
  void StopRobot(int robot_id) override;
  void Step() override;

  // The true state, for the run log and the verdict.
  const UnicycleWorld& truth() const { return truth_; }
  const std::vector<Pose2>& true_poses() const { return truth_.poses(); }
  const std::vector<UnicycleCommand>& true_velocities() const { return truth_.velocities(); }
  const RealismParams& realism() const { return realism_; }

  // A robot the tracker dropped (tracker_drop_s): from the measurement of
  // `step` on, its agents are sent its last measured pose.
  struct TrackerLoss {
    int robot_id = 0;
    int64_t step = 0;
  };
  // In the order they were lost; each robot at most once.
  const std::vector<TrackerLoss>& tracker_losses() const { return tracker_losses_; }
  // Steps that ran late (an overrun or a stall), stalls among them, and the
  // total time beyond whole steps.
  int64_t late_steps() const { return late_steps_; }
  int64_t stalls() const { return stalls_; }
  double late_time_s() const { return late_time_s_; }
  // Whether a robot moving at `velocity` counts as moving for the tracker's
  // models (noise, dropouts); dream calibrate classes measurements by it too.
  static bool IsMoving(const UnicycleCommand& velocity);
  // How much longer than a time step the last Step() lasted (0 on time).
  double last_late_s() const { return last_late_s_; }
  // Each robot's drawn gains and drift.
  std::vector<RobotTraits> robot_traits() const;
  // Robot-steps whose measurement was dropped (the previous one sent again),
  // robots lost to the tracker not counted after their loss.
  int64_t dropped_measurements() const { return dropped_measurements_; }
  // A kWarning "tracker_lost" naming every robot lost to the tracker and when;
  // none when no robot was.
  std::optional<VerdictReason> TrackerLossReason() const;

 private:
  static constexpr int64_t kNone = -1;

  struct QueuedCommand {
    int64_t due_step = 0;
    UnicycleCommand command;
  };
  struct Robot {
    std::deque<QueuedCommand> queue;
    UnicycleCommand delivered;           // the command the firmware follows
    int64_t delivered_step = kNone;      // when it reached the robot; kNone: no command
    double late_since_delivery_s = 0.0;  // time beyond whole steps since then (late steps, stalls)
    RobotResponse response;              // its firmware, motors, gains and drift
    bool sent_over_limit = false;        // newest command since the last Step() exceeds the wheel limit
  };

  // What the tracker knows of a robot.
  struct Tracking {
    int64_t missing_steps = 0;  // measurements dropped in a row
    bool lost = false;          // dropped by the tracker for the rest of the run
  };

  void CheckRobotId(int robot_id, const char* caller) const;
  // The command robot's firmware follows this step, after delivery and brake.
  UnicycleCommand Follow(Robot& robot);
  // How long this step's `late_s` the robot still drives before its brake.
  double DrivenLateTime(const Robot& robot, double late_s) const;
  // This step's time beyond one time step: an overrun, a stall (0 when both are off).
  double DrawLateTime();

  void Measure(bool first);
  // Whether robot i's measurement of this step is dropped; draws its dropout numbers.
  bool DropsMeasurement(Tracking& tracking, double probability, bool first);
  static std::vector<Robot> MakeRobots(const RealismParams& realism, const WorldParams& params, uint64_t seed,
                                       int num_robots);

  WorldParams official_;  // the Robotarium's constants, for the actuator check
  RealismParams realism_;
  UnicycleWorld truth_;
  std::vector<Robot> robots_;
  std::vector<double> motion_times_;              // per robot, this step's driving time (late steps only)
  std::unique_ptr<RealismRandom> timing_random_;  // only with overruns or stalls
  int64_t late_steps_ = 0;
  int64_t stalls_ = 0;
  double late_time_s_ = 0.0;
  double last_late_s_ = 0.0;
  int64_t brake_hold_steps_ = 0;
  int64_t actuator_errors_ = 0;
  ViolationCounts violations_{};

  // True poses and velocities of the last pose_delay_steps + 1 steps, by step
  // modulo their count.
  std::vector<std::vector<Pose2>> pose_history_;
  std::vector<std::vector<UnicycleCommand>> velocity_history_;
  std::vector<Pose2> measured_poses_;
  std::vector<UnicycleCommand> measured_velocities_;
  std::unique_ptr<RealismRandom> noise_random_;
  std::unique_ptr<RealismRandom> dropout_random_;
  std::unique_ptr<RealismRandom> burst_random_;  // only with tracking_dropout_mean_steps > 1
  double burst_continue_probability_ = 0.0;
  int64_t tracker_hold_steps_ = 0;  // dropped measurements in a row a robot survives
  std::vector<Tracking> tracking_;
  std::vector<TrackerLoss> tracker_losses_;
  int64_t dropped_measurements_ = 0;
};

}  // namespace dream::world
