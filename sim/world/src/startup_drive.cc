#include "dream/world/startup_drive.h"

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Core>

#include "dream/barriers/unicycle_barrier.h"
#include "dream/robotarium/robotarium_constants.h"
#include "dream/world/hybrid_pose_controller.h"
#include "dream/world/unicycle_world.h"
#include "barrier_input.h"
#include "field_check.h"

#ifndef DREAM_STARTUP_MAX_STEPS
#error "DREAM_STARTUP_MAX_STEPS comes from bridge/python/run_submission.py (sim/world/CMakeLists.txt)"
#endif

namespace dream::world {

namespace {

constexpr double kPi = 3.141592653589793;
// rps initialize(): a robot that moved less than 0.1 m in 150 steps is stuck.
constexpr int kDeadlockSteps = 5 * 30;
constexpr double kDeadlockEpsilonM = 0.1;
// ... and is sent to a waypoint up to 0.25 m away; a command this small means it is turning or done.
constexpr double kWaypointReachM = 0.25;
constexpr double kStillCommand = 0.1;

double UnitUniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// numpy's uniform(low, high) = low + (high - low) * u, also when low > high as rps calls it.
double Uniform(std::mt19937_64& rng, double low, double high) { return low + (high - low) * UnitUniform(rng); }

double Wrap(double angle) { return std::atan2(std::sin(angle), std::cos(angle)); }

double PlanarDistance(const Pose2& a, const Pose2& b) {
  const double dx = a.x_m - b.x_m;
  const double dy = a.y_m - b.y_m;
  return std::sqrt(dx * dx + dy * dy);
}

bool AtPose(const Pose2& pose, const Pose2& goal) {
  return PlanarDistance(pose, goal) <= StartupDrive::kAtPositionM &&
         std::abs(Wrap(pose.theta_rad - goal.theta_rad)) <= StartupDrive::kAtHeadingRad;
}

bool AllAtPose(const std::vector<Pose2>& poses, const std::vector<Pose2>& goals) {
  for (std::size_t i = 0; i < poses.size(); ++i) {
    if (!AtPose(poses[i], goals[i])) return false;
  }
  return true;
}

// The robots rps's deadlock logic looks after. rps computes them as
// arange(N)[~isin(arange(N), at_pose_mask)] with the boolean mask itself, so
// isin compares indices with True (1) and False (0): robot 0 is left out
// while any robot is away from its pose, robot 1 while any robot is on its
// pose, every robot from 2 on is always in. The quirk is the drive's, kept.
struct DeadlockWatch {
  bool any_at = false;
  bool any_away = false;
};

DeadlockWatch DeadlockWatchOf(const std::vector<char>& at_pose) {
  DeadlockWatch watch;
  for (char at : at_pose) (at ? watch.any_at : watch.any_away) = true;
  return watch;
}

bool Watched(int i, const DeadlockWatch& watch) {
  if (i >= 2) return true;
  return i == 0 ? !watch.any_away : !watch.any_at;
}

Pose2 Waypoint(const Pose2& from, const Arena& arena, std::mt19937_64& rng) {
  Pose2 waypoint;
  waypoint.x_m = Uniform(rng, std::min(from.x_m + kWaypointReachM, arena.x_max_m),
                         std::max(from.x_m - kWaypointReachM, arena.x_min_m));
  waypoint.y_m = Uniform(rng, std::min(from.y_m + kWaypointReachM, arena.y_max_m),
                         std::max(from.y_m - kWaypointReachM, arena.y_min_m));
  waypoint.theta_rad = Uniform(rng, -kPi, kPi);
  return waypoint;
}

// rps initialize()'s deadlock rule, per robot: one that moved less than 0.1 m
// in 150 steps while its command was not small is sent to a random waypoint
// within 0.25 m (a new one every 150 steps) until it has moved 0.1 m.
class DeadlockBreaker {
 public:
  DeadlockBreaker(const std::vector<Pose2>& start, const Arena& arena, uint64_t seed)
      : timers_(start.size(), 0),
        last_still_(start),
        waypointing_(start.size(), 0),
        waypoints_(start.size()),
        arena_(arena),
        rng_(seed) {}

  // Robot i at `pose` heading for `goal` at the drive's iteration; may replace its command.
  void Steer(std::size_t i, const Pose2& pose, const Pose2& goal, int iteration, HybridPoseController* controller,
             UnicycleCommand* command) {
    const double moved_m = PlanarDistance(last_still_[i], pose);
    if (waypointing_[i]) {
      *command = controller->ApplyOne(pose, waypoints_[i]);
      if (moved_m > kDeadlockEpsilonM) {
        waypointing_[i] = 0;
      } else if (iteration - timers_[i] > kDeadlockSteps) {
        waypoints_[i] = Waypoint(pose, arena_, rng_);
        timers_[i] = iteration;
      }
    } else if (iteration - timers_[i] > kDeadlockSteps && moved_m < kDeadlockEpsilonM) {
      waypointing_[i] = 1;
      waypoints_[i] = Waypoint(pose, arena_, rng_);
      timers_[i] = iteration;
    } else if (moved_m > kDeadlockEpsilonM || Small(controller->ApplyOne(pose, goal))) {
      timers_[i] = iteration;
      last_still_[i] = pose;
    }
  }

 private:
  static bool Small(const UnicycleCommand& command) {
    return std::sqrt(command.v_mps * command.v_mps + command.w_radps * command.w_radps) <= kStillCommand;
  }

  std::vector<int> timers_;
  std::vector<Pose2> last_still_;
  std::vector<char> waypointing_;
  std::vector<Pose2> waypoints_;
  Arena arena_;
  std::mt19937_64 rng_;
};

std::vector<StartupDriveResult::Miss> MissesOf(const std::vector<Pose2>& poses, const std::vector<Pose2>& goals) {
  std::vector<StartupDriveResult::Miss> misses;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    if (AtPose(poses[i], goals[i])) continue;
    misses.push_back(
        {static_cast<int>(i), PlanarDistance(poses[i], goals[i]), Wrap(poses[i].theta_rad - goals[i].theta_rad)});
  }
  return misses;
}

}  // namespace

int StartupDrive::MaxSteps() { return DREAM_STARTUP_MAX_STEPS; }

StartupDrive::StartupDrive(const WorldParams& world, std::vector<Pose2> start_poses, int max_steps)
    : world_(field_check::Checked("StartupDrive", world)), start_poses_(std::move(start_poses)), max_steps_(max_steps) {
  if (max_steps_ < 1)
    throw std::invalid_argument("StartupDrive: max_steps must be >= 1, got " + std::to_string(max_steps));
  for (std::size_t i = 0; i < start_poses_.size(); ++i) {
    const Pose2& pose = start_poses_[i];
    if (!std::isfinite(pose.x_m) || !std::isfinite(pose.y_m) || !std::isfinite(pose.theta_rad)) {
      throw std::invalid_argument("StartupDrive: start pose of robot " + std::to_string(i) + " is not finite");
    }
  }
}

std::vector<Pose2> StartupDrive::ChargerSlots(const WorldParams& world) {
  // generate_initial_poses(N, width = arena width - robot diameter, height = arena height - diameter).
  const double diameter_m = robotarium::RobotariumConstants::kRobotDiameterMeters;
  const double width_m = world.arena.x_max_m - world.arena.x_min_m - diameter_m;
  const double height_m = world.arena.y_max_m - world.arena.y_min_m - diameter_m;
  constexpr int kPerEdge = kChargerSlots / 2;
  std::vector<Pose2> slots;
  for (int k = 0; k < kPerEdge; ++k) {
    // numpy's linspace(-w/2, w/2, 11): start + k * step, the last one exactly the end.
    const double step_m = width_m / (kPerEdge - 1);
    const double x_m = k == kPerEdge - 1 ? width_m / 2 : -width_m / 2 + k * step_m;
    slots.push_back({x_m, -height_m / 2, kPi / 2});
    slots.push_back({x_m, height_m / 2, -kPi / 2});
  }
  return slots;
}

std::vector<Pose2> StartupDrive::PlaceOnChargers(const WorldParams& world, int num_robots, uint64_t seed) {
  if (num_robots < 0 || num_robots > kChargerSlots) {
    throw std::invalid_argument(
        std::to_string(num_robots) + " robots: the Robotarium's start-up drive places robots on " +
        std::to_string(kChargerSlots) + " charger slots (the official V2 simulator fails above that)");
  }
  std::vector<Pose2> slots = ChargerSlots(world);
  std::mt19937_64 rng(seed);
  // A partial Fisher-Yates shuffle: num_robots distinct slots in random order.
  for (int i = 0; i < num_robots; ++i) {
    const int remaining = kChargerSlots - i;
    const int pick = i + std::min(remaining - 1, static_cast<int>(UnitUniform(rng) * remaining));
    std::swap(slots[static_cast<std::size_t>(i)], slots[static_cast<std::size_t>(pick)]);
  }
  slots.resize(static_cast<std::size_t>(num_robots));
  return slots;
}

StartupDriveResult StartupDrive::Run(uint64_t seed, const StepObserver& observer) const {
  const int n = static_cast<int>(start_poses_.size());
  if (n > kChargerSlots) {
    StartupDriveResult refused;
    refused.seed = seed;
    refused.refusal = std::to_string(n) + " robots do not fit the " + std::to_string(kChargerSlots) +
                      " charger slots the start-up drive starts from (the official V2 simulator fails above " +
                      std::to_string(kChargerSlots) + ")";
    return refused;
  }
  // The waypoints from a stream of their own, so a placement is the same whatever the drive draws.
  StartupDriveResult result = RunFrom(PlaceOnChargers(world_, n, seed), seed ^ 0x9e3779b97f4a7c15ULL, observer);
  result.seed = seed;
  return result;
}

StartupDriveResult StartupDrive::RunFrom(const std::vector<Pose2>& charger_poses, uint64_t seed,
                                         const StepObserver& observer) const {
  const std::size_t n = start_poses_.size();
  if (charger_poses.size() != n) {
    throw std::invalid_argument("StartupDrive::RunFrom: " + std::to_string(charger_poses.size()) +
                                " charger poses for " + std::to_string(n) + " robots");
  }
  StartupDriveResult result;
  result.seed = seed;
  result.charger_poses = charger_poses;

  WorldParams params = world_;
  params.command_timeout_s = std::numeric_limits<double>::infinity();  // rps holds commands
  UnicycleWorld world(params, charger_poses);
  barriers::UnicycleBarrier barrier(barriers::UnicycleBarrierParams::Rps());
  HybridPoseController controller;

  DeadlockBreaker deadlock(charger_poses, params.arena, seed);
  std::vector<char> at_pose(n, 0);
  std::vector<UnicycleCommand> commands;
  Eigen::Matrix2Xd wanted(2, static_cast<Eigen::Index>(n));
  Eigen::Matrix3Xd pose_matrix(3, static_cast<Eigen::Index>(n));

  // rps: x = get_poses(); step() with no velocity set; then the loop tests the
  // poses read before each step.
  std::vector<Pose2> x = world.poses();
  world.Step();
  if (observer) observer(1, world.poses());
  int step = 0;  // rps's own counter: loop iterations before this one
  while (!AllAtPose(x, start_poses_)) {
    if (world.step() >= max_steps_) {  // check-submission's StartupTimeout: the next step is one too many
      result.steps = static_cast<int>(world.step());
      result.final_poses = world.poses();
      result.misses = MissesOf(result.final_poses, start_poses_);
      return result;
    }
    x = world.poses();
    controller.Apply(x, start_poses_, &commands);
    for (std::size_t i = 0; i < n; ++i) at_pose[i] = AtPose(x[i], start_poses_[i]);
    const DeadlockWatch watch = DeadlockWatchOf(at_pose);
    for (std::size_t i = 0; i < n; ++i) {
      if (Watched(static_cast<int>(i), watch))
        deadlock.Steer(i, x[i], start_poses_[i], step, &controller, &commands[i]);
    }
    ++step;
    FillBarrierInput(commands, x, &wanted, &pose_matrix);
    const barriers::BarrierResult safe = barrier.Apply(wanted, pose_matrix);
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Index k = static_cast<Eigen::Index>(i);
      world.SetCommand(static_cast<int>(i), UnicycleCommand{safe.commands(0, k), safe.commands(1, k)});
    }
    world.Step();
    if (observer) observer(static_cast<int>(world.step()), world.poses());
  }
  result.settled = true;
  result.steps = static_cast<int>(world.step());
  result.final_poses = world.poses();
  return result;
}

}  // namespace dream::world
