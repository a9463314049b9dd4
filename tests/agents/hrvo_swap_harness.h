#pragma once
// A closed-loop HRVO run in the Robotarium-faithful UnicycleWorld, shared by
// hrvo_scenario_test and the hrvo_comparison program: every robot drives at
// max speed towards its goal (the thesis's Robot_c.update), HRVO makes the
// velocity safe, the thesis's dxi_to_dxu and actuator_limit turn it into a
// unicycle command. HRVO's "current velocity" is its previous output (the
// thesis's self.dxi).
#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "dream/agents/hrvo/hrvo_avoidance.h"
#include "dream/world/pose2.h"

namespace dream::agents {

struct HrvoSwapOptions {
  double max_speed_mps = 0.2;        ///< preferred speed towards the goal
  double arrive_tolerance_m = 0.05;  ///< within this the preferred velocity is zero
  double neighbour_range_m = 1.0;    ///< the movement sensor's range (exact world poses)
  /// Neighbour velocity reported to HRVO: true, that of the point this far
  /// ahead of the centre (the thesis's movement sensor, 0.05 m); 0 gives
  /// the centre's velocity. Both from the velocities the world held during
  /// the previous step.
  double velocity_point_ahead_m = 0.05;
  double vel_gain = 0.8;  ///< the thesis's dxi_to_dxu gains
  double ang_gain = 3.0;
  /// false: every robot senses and updates every step. true: the thesis's
  /// Appendix B timers -- robot i starts after 20 + i steps, then updates its
  /// command every 4 + i%2 steps, its movement sensor every 3 + i%2 and its
  /// odometry every 2 + i%2, acting on the latest (stale) readings and
  /// holding its command in between.
  bool thesis_timing = false;
  int64_t max_steps = 4000;
  double near_miss_m = 0.2;  ///< centre distance counted as a near miss
};

struct HrvoSwapResult {
  bool completed = false;         ///< every robot within tolerance of its goal at once
  int64_t completion_steps = -1;  ///< first step at which that held
  int64_t collision_errors = 0;   ///< the world's (Robotarium) count
  int64_t boundary_errors = 0;
  int64_t near_miss_steps = 0;  ///< steps with some pair's centres closer than near_miss_m
  double min_distance_m = 1e9;  ///< smallest centre distance seen
  int64_t calls = 0;            ///< SafeVelocity calls
  double ns_per_call = 0.0;     ///< mean thread CPU time per SafeVelocity call
};

using HrvoFactory = std::function<std::unique_ptr<HrvoAvoidance>()>;

HrvoSwapResult RunHrvoSwap(const std::vector<world::Pose2>& start, const std::vector<Eigen::Vector2d>& goals,
                           const HrvoFactory& make_hrvo, const HrvoSwapOptions& options);

/// The thesis's circle (Appendix B): robot i at angle 2 pi i / n on a circle,
/// facing the centre, each pose perturbed uniformly by up to jitter_m per
/// coordinate and jitter_rad in heading (seeded; seed 0 and zero jitter give
/// the exact circle).
std::vector<world::Pose2> CirclePoses(int num_robots, double radius_m, double jitter_m, double jitter_rad,
                                      uint64_t seed);
/// Each robot's diametrically opposite point.
std::vector<Eigen::Vector2d> AntipodalGoals(int num_robots, double radius_m);

/// Random crossings: start poses (random headings) and goals uniform in
/// [-1.3, 1.3] x [-0.75, 0.75] m, starts and goals each at least 0.35 m
/// apart (seeded).
void RandomCrossing(int num_robots, uint64_t seed, std::vector<world::Pose2>* start,
                    std::vector<Eigen::Vector2d>* goals);

}  // namespace dream::agents
