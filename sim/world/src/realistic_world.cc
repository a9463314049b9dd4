#include "dream/world/realistic_world.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "dream/world/printf_text.h"
#include "dream/world/unicycle_kinematics.h"
#include "realism_random.h"
#include "steps_within.h"
#include "world_argument_check.h"

namespace dream::world {
namespace {

constexpr double kPi = 3.14159265358979323846;

const RealismParams& ValidatedRealism(const RealismParams& realism) {
  std::string error;
  if (!realism.IsValid(&error)) throw std::invalid_argument("RealisticWorld: realism " + error);
  return realism;
}

// The true world: the robot's own axle for its wheel saturation, and no
// command timeout (the brake is modelled here, from when a command reaches
// the robot).
WorldParams TruthParams(const WorldParams& params, const RealismParams& realism) {
  WorldParams truth = params;
  truth.base_length_m = realism.axle_length_m;
  truth.command_timeout_s = std::numeric_limits<double>::infinity();
  return truth;
}

// StepsWithin, with 0 meaning never (the realism models' "off").
int64_t HoldSteps(double time_step_s, double seconds) {
  return seconds == 0.0 ? std::numeric_limits<int64_t>::max() : StepsWithin(time_step_s, seconds);
}

double Quantize(double value, double quantum) { return quantum > 0.0 ? std::round(value / quantum) * quantum : value; }

// A heading as the lab's tracker reports it: wrapped to [-pi, pi) first,
// then rounded, so every value is on the quantum's grid (rounding after the
// wrap would leave the grid near +-pi: -3.128185 = 3.155 - 2 pi). A value
// that rounds onto or past +-pi takes the grid's last value inside. An
// unrounded heading is only wrapped, to (-pi, pi] as the official world's.
double MeasuredHeading(double theta, double quantum) {
  if (quantum <= 0.0) return theta > kPi || theta <= -kPi ? std::atan2(std::sin(theta), std::cos(theta)) : theta;
  theta = std::remainder(theta, 2 * kPi);  // [-pi, pi]
  if (theta >= kPi) theta = -kPi;
  const double lowest = std::ceil(-kPi / quantum);        // the first multiple at or above -pi
  const double highest = std::ceil(kPi / quantum) - 1.0;  // the last multiple below pi
  return std::clamp(std::round(theta / quantum), lowest, highest) * quantum;
}

// Below these a robot counts as at rest for the tracker's models: it moves
// less than 0.07 mm (0.7 mrad) a step.
constexpr double kMovingSpeedMps = 0.002;
constexpr double kMovingTurnRadps = 0.02;

}  // namespace

std::vector<RealisticWorld::Robot> RealisticWorld::MakeRobots(const RealismParams& realism, const WorldParams& params,
                                                              uint64_t seed, int num_robots) {
  std::vector<Robot> robots;
  robots.reserve(static_cast<size_t>(num_robots));
  for (const RobotTraits& traits : RobotTraits::Draw(realism, seed, num_robots)) {
    robots.push_back(Robot{{},
                           {},
                           kNone,
                           0.0,
                           RobotResponse(realism, traits, params.wheel_radius_m, params.max_wheel_speed_radps),
                           false});
  }
  return robots;
}

RealisticWorld::RealisticWorld(const WorldParams& params, const RealismParams& realism, uint64_t seed,
                               std::vector<Pose2> initial_poses,
                               const std::vector<RectangleObstacleSpec>& obstacle_specs)
    : official_(params),
      realism_(ValidatedRealism(realism)),
      truth_(TruthParams(params, realism), std::move(initial_poses), obstacle_specs),
      robots_(MakeRobots(realism_, params, seed, truth_.num_robots())),
      brake_hold_steps_(HoldSteps(params.time_step_s, realism.command_brake_s)),
      pose_history_(static_cast<size_t>(realism.pose_delay_steps) + 1, truth_.poses()),
      velocity_history_(static_cast<size_t>(realism.pose_delay_steps) + 1, truth_.velocities()),
      measured_poses_(truth_.poses()),
      measured_velocities_(truth_.velocities()),
      noise_random_(std::make_unique<RealismRandom>(seed, RealismStream::kNoise)),
      dropout_random_(std::make_unique<RealismRandom>(seed, RealismStream::kDropout)),
      tracker_hold_steps_(HoldSteps(params.time_step_s, realism.tracker_drop_s)),
      tracking_(static_cast<size_t>(truth_.num_robots())) {
  if (realism_.step_overrun_mean_s > 0.0 || realism_.loop_stall_probability > 0.0) {
    timing_random_ = std::make_unique<RealismRandom>(seed, RealismStream::kLoopTiming);
    motion_times_.resize(robots_.size());
  }
  if (realism_.tracking_dropout_mean_steps > 1.0) {
    burst_random_ = std::make_unique<RealismRandom>(seed, RealismStream::kDropoutBurst);
    burst_continue_probability_ = 1.0 - 1.0 / realism_.tracking_dropout_mean_steps;
  }
  Measure(true);
}

RealisticWorld::~RealisticWorld() = default;

void RealisticWorld::CheckRobotId(int robot_id, const char* caller) const {
  world_argument_check::CheckRobotId("RealisticWorld", caller, robot_id, num_robots());
}

void RealisticWorld::SetCommand(int robot_id, const UnicycleCommand& command) {
  CheckRobotId(robot_id, "SetCommand");
  world_argument_check::CheckCommandIsFinite("RealisticWorld", robot_id, command);
  Robot& robot = robots_[static_cast<size_t>(robot_id)];
  const int64_t due_step = step() + realism_.command_latency_steps;
  if (!robot.queue.empty() && robot.queue.back().due_step == due_step) {
    robot.queue.back().command = command;  // a newer command for the same step replaces it
  } else {
    robot.queue.push_back({due_step, command});
  }
  // The Robotarium judges the command as sent, with its own constants.
  robot.sent_over_limit =
      ExceedsWheelSpeedLimit(UnicycleToWheelSpeeds(command, official_.wheel_radius_m, official_.base_length_m),
                             official_.max_wheel_speed_radps);
}

void RealisticWorld::StopRobot(int robot_id) {
  CheckRobotId(robot_id, "StopRobot");
  Robot& robot = robots_[static_cast<size_t>(robot_id)];
  robot.queue.clear();
  robot.delivered = UnicycleCommand{};
  robot.delivered_step = kNone;
  robot.late_since_delivery_s = 0.0;
  robot.response.Stop();
  robot.sent_over_limit = false;
  truth_.StopRobot(robot_id);
}

UnicycleCommand RealisticWorld::Follow(Robot& robot) {
  const int64_t now = step();
  while (!robot.queue.empty() && robot.queue.front().due_step <= now) {
    robot.delivered = robot.queue.front().command;
    robot.delivered_step = robot.queue.front().due_step;
    robot.late_since_delivery_s = 0.0;
    robot.queue.pop_front();
  }
  if (robot.delivered_step == kNone) return robot.delivered;
  const int64_t age_steps = now - robot.delivered_step;
  const bool braked_by_steps = age_steps > brake_hold_steps_;
  // Late steps count too: a command that waited through a stall is older
  // than its steps say.
  const bool braked_by_time =
      robot.late_since_delivery_s > 0.0 && realism_.command_brake_s > 0.0 &&
      static_cast<double>(age_steps) * official_.time_step_s + robot.late_since_delivery_s > realism_.command_brake_s;
  if (braked_by_steps || braked_by_time) {
    // The firmware shorts the motors: the wheels stop at once.
    robot.delivered = UnicycleCommand{};
    robot.delivered_step = kNone;
    robot.late_since_delivery_s = 0.0;
    robot.response.Stop();
  }
  return robot.delivered;
}

double RealisticWorld::DrivenLateTime(const Robot& robot, double late_s) const {
  if (robot.delivered_step == kNone || realism_.command_brake_s == 0.0) return late_s;
  const double age_after_step_s =
      static_cast<double>(step() - robot.delivered_step + 1) * official_.time_step_s + robot.late_since_delivery_s;
  return std::clamp(realism_.command_brake_s - age_after_step_s, 0.0, late_s);
}

double RealisticWorld::DrawLateTime() {
  if (timing_random_ == nullptr) return 0.0;
  // Every draw is taken whether used or not, so the stream stays aligned.
  const double overrun_u = timing_random_->Uniform();
  const double stall_u = timing_random_->Uniform();
  const double stall_length_u = timing_random_->Uniform();
  double late_s = -realism_.step_overrun_mean_s * std::log1p(-overrun_u);  // exponential
  if (stall_u < realism_.loop_stall_probability) {
    const double longest = std::max(realism_.loop_stall_max_s, RealismParams::kMinStallS);
    late_s += RealismParams::kMinStallS + (longest - RealismParams::kMinStallS) * stall_length_u;
    ++stalls_;
  }
  if (late_s > 0.0) {
    ++late_steps_;
    late_time_s_ += late_s;
  }
  return late_s;
}

bool RealisticWorld::IsMoving(const UnicycleCommand& velocity) {
  return std::abs(velocity.v_mps) >= kMovingSpeedMps || std::abs(velocity.w_radps) >= kMovingTurnRadps;
}

void RealisticWorld::Step() {
  const double late_s = DrawLateTime();
  last_late_s_ = late_s;
  const double step_s = official_.time_step_s + late_s;
  bool over_limit = false;
  for (size_t i = 0; i < robots_.size(); ++i) {
    Robot& robot = robots_[i];
    const UnicycleCommand followed = Follow(robot);
    truth_.SetCommand(static_cast<int>(i), robot.response.Drive(followed, step_s));
    if (late_s > 0.0) motion_times_[i] = official_.time_step_s + DrivenLateTime(robot, late_s);
    robot.late_since_delivery_s += late_s;
    over_limit = over_limit || robot.sent_over_limit;
    robot.sent_over_limit = false;
  }
  if (late_s > 0.0) {
    truth_.StepWithMotionTimes(motion_times_);
  } else {
    truth_.Step();
  }
  if (over_limit) ++actuator_errors_;
  violations_ = truth_.violations();
  violations_.actuator_errors = actuator_errors_;
  Measure(false);
}

std::vector<RobotTraits> RealisticWorld::robot_traits() const {
  std::vector<RobotTraits> traits;
  traits.reserve(robots_.size());
  for (const Robot& robot : robots_) traits.push_back(robot.response.traits());
  return traits;
}

void RealisticWorld::Measure(bool first) {
  const auto history_size = static_cast<int64_t>(pose_history_.size());
  const int64_t now = step();
  pose_history_[static_cast<size_t>(now % history_size)] = truth_.poses();
  velocity_history_[static_cast<size_t>(now % history_size)] = truth_.velocities();
  const int64_t seen_step = std::max<int64_t>(0, now - realism_.pose_delay_steps);
  const std::vector<Pose2>& seen_poses = pose_history_[static_cast<size_t>(seen_step % history_size)];
  const std::vector<UnicycleCommand>& seen_velocities =
      velocity_history_[static_cast<size_t>(seen_step % history_size)];

  for (size_t i = 0; i < measured_poses_.size(); ++i) {
    // Every draw is taken whether used or not, so the streams stay aligned.
    const bool moving = IsMoving(seen_velocities[i]);
    const double noise_scale = moving ? realism_.pose_noise_moving_factor : 1.0;
    const double noise_x = noise_random_->Gaussian() * (realism_.pose_noise_m * noise_scale);
    const double noise_y = noise_random_->Gaussian() * (realism_.pose_noise_m * noise_scale);
    const double noise_theta = noise_random_->Gaussian() * (realism_.pose_noise_rad * noise_scale);
    Tracking& tracking = tracking_[i];
    const double dropout_probability =
        moving ? realism_.tracking_dropout_probability
               : std::min(1.0, realism_.tracking_dropout_probability * realism_.tracking_dropout_at_rest_factor);
    if (DropsMeasurement(tracking, dropout_probability, first)) {
      // The tracker repeats its last report; past tracker_drop_s it drops the robot.
      if (!tracking.lost && tracking.missing_steps > tracker_hold_steps_) {
        tracking.lost = true;
        tracker_losses_.push_back({static_cast<int>(i), now});
      }
      continue;
    }

    const Pose2& seen = seen_poses[i];
    Pose2& measured = measured_poses_[i];
    measured.x_m = Quantize(seen.x_m + noise_x, realism_.pose_quantum_m);
    measured.y_m = Quantize(seen.y_m + noise_y, realism_.pose_quantum_m);
    measured.theta_rad = MeasuredHeading(seen.theta_rad + noise_theta, realism_.pose_quantum_rad);
    measured_velocities_[i] = seen_velocities[i];
  }
}

bool RealisticWorld::DropsMeasurement(Tracking& tracking, double probability, bool first) {
  const bool starts = dropout_random_->Uniform() < probability;
  const bool goes_on = burst_random_ != nullptr && burst_random_->Uniform() < burst_continue_probability_;
  if (first) return false;  // step 0 is always measured
  if (tracking.lost) return true;
  if (starts || (tracking.missing_steps > 0 && goes_on)) {
    ++tracking.missing_steps;
    ++dropped_measurements_;
    return true;
  }
  tracking.missing_steps = 0;
  return false;
}

std::optional<VerdictReason> RealisticWorld::TrackerLossReason() const {
  if (tracker_losses_.empty()) return std::nullopt;
  std::string robots;
  for (const TrackerLoss& loss : tracker_losses_) {
    robots +=
        (robots.empty() ? "" : ", ") + std::to_string(loss.robot_id) + " (from step " + std::to_string(loss.step) + ")";
  }
  const bool one = tracker_losses_.size() == 1;
  return VerdictReason{"tracker_lost", RunVerdict::kWarning,
                       std::string(one ? "robot " : "robots ") + robots +
                           " lost to the tracker: no new pose for over " + PrintfText("%g s", realism_.tracker_drop_s) +
                           " (world.realism tracker_drop_s), so " + (one ? "its agent was" : "their agents were") +
                           " sent the last pose for the rest of the run",
                       "summary.json realism_stats; dream log echo RUN DREAM_MEASURED_POSES shows what the agents saw"};
}

}  // namespace dream::world
