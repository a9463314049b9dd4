#include "hrvo_swap_harness.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <time.h>

#include "dream/agents/framework/actuator_limits.h"
#include "dream/agents/framework/robot.h"
#include "dream/world/unicycle_world.h"

namespace dream::agents {
namespace {

double ThreadCpuNs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e9 * static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec);
}

struct Readings {
  Eigen::Vector3d pose = Eigen::Vector3d::Zero();  // odometry
  std::vector<HrvoNeighbour> neighbours;           // movement sensor
};

}  // namespace

HrvoSwapResult RunHrvoSwap(const std::vector<world::Pose2>& start, const std::vector<Eigen::Vector2d>& goals,
                           const HrvoFactory& make_hrvo, const HrvoSwapOptions& options) {
  const int n = static_cast<int>(start.size());
  if (goals.size() != start.size()) throw std::invalid_argument("RunHrvoSwap: one goal per robot");
  world::UnicycleWorld world(world::WorldParams{}, start);
  const ActuatorLimits limits;
  // The thesis's dxi_to_dxu is the library's, so this harness cannot drift from the robots.
  RobotParams drive;
  drive.vel_gain = options.vel_gain;
  drive.ang_gain = options.ang_gain;
  std::vector<std::unique_ptr<HrvoAvoidance>> hrvo;
  for (int i = 0; i < n; ++i) hrvo.push_back(make_hrvo());
  std::vector<Eigen::Vector2d> dxi(static_cast<size_t>(n), Eigen::Vector2d::Zero());
  std::vector<Readings> readings(static_cast<size_t>(n));
  std::vector<UnicycleCommand> held(static_cast<size_t>(n));
  std::vector<Eigen::Vector2d> preferred(static_cast<size_t>(n), Eigen::Vector2d::Zero());
  std::vector<int> due_robots;

  const auto due = [&](int i, int64_t step, int period) {
    if (!options.thesis_timing) return true;
    const int64_t delay = 20 + i;
    return step > delay && (step - delay) % period == 0;
  };
  const auto sense_odometry = [&](int i) {
    const world::Pose2& p = world.poses()[static_cast<size_t>(i)];
    readings[static_cast<size_t>(i)].pose = {p.x_m, p.y_m, p.theta_rad};
  };
  // Velocity of the point velocity_point_ahead_m ahead of robot j's centre,
  // from the velocity the world held during the last step.
  const auto measured_velocity = [&](int j) -> Eigen::Vector2d {
    const world::Pose2& p = world.poses()[static_cast<size_t>(j)];
    const world::UnicycleCommand& u = world.velocities()[static_cast<size_t>(j)];
    const double c = std::cos(p.theta_rad), s = std::sin(p.theta_rad);
    const double a = options.velocity_point_ahead_m;
    return {c * u.v_mps - a * s * u.w_radps, s * u.v_mps + a * c * u.w_radps};
  };
  const auto sense_movement = [&](int i) {
    std::vector<HrvoNeighbour>& out = readings[static_cast<size_t>(i)].neighbours;
    out.clear();
    const world::Pose2& self = world.poses()[static_cast<size_t>(i)];
    for (int j = 0; j < n; ++j) {
      const world::Pose2& other = world.poses()[static_cast<size_t>(j)];
      const Eigen::Vector2d rel(other.x_m - self.x_m, other.y_m - self.y_m);
      const double d = rel.norm();
      if (j == i || d <= 0.0 || d > options.neighbour_range_m) continue;
      out.push_back({rel, measured_velocity(j)});
    }
  };

  HrvoSwapResult result;
  double total_ns = 0.0;
  for (int64_t step = 0; step < options.max_steps; ++step) {
    // Metrics on the poses the world is about to validate.
    bool all_arrived = true;
    bool near_miss = false;
    for (int i = 0; i < n; ++i) {
      const world::Pose2& p = world.poses()[static_cast<size_t>(i)];
      if (std::hypot(goals[static_cast<size_t>(i)].x() - p.x_m, goals[static_cast<size_t>(i)].y() - p.y_m) >=
          options.arrive_tolerance_m) {
        all_arrived = false;
      }
      for (int j = i + 1; j < n; ++j) {
        const world::Pose2& q = world.poses()[static_cast<size_t>(j)];
        const double d = std::hypot(p.x_m - q.x_m, p.y_m - q.y_m);
        result.min_distance_m = std::min(result.min_distance_m, d);
        if (d < options.near_miss_m) near_miss = true;
      }
    }
    if (near_miss) ++result.near_miss_steps;
    if (all_arrived) {
      result.completed = true;
      result.completion_steps = step;
      break;
    }

    // Thesis order: robots act on the readings they have, then sensors run.
    due_robots.clear();
    for (int i = 0; i < n; ++i) {
      if (!due(i, step, options.thesis_timing ? 4 + i % 2 : 1)) continue;
      due_robots.push_back(i);
      if (!options.thesis_timing) {
        sense_odometry(i);
        sense_movement(i);
      }
      const Readings& r = readings[static_cast<size_t>(i)];
      const Eigen::Vector2d delta = goals[static_cast<size_t>(i)] - r.pose.head<2>();
      const double dist = delta.norm();
      preferred[static_cast<size_t>(i)] = dist < options.arrive_tolerance_m
                                              ? Eigen::Vector2d::Zero()
                                              : Eigen::Vector2d(options.max_speed_mps * delta / dist);
    }
    // Only the SafeVelocity calls are timed (thread CPU time).
    const double t0 = ThreadCpuNs();
    for (const int i : due_robots) {
      const size_t k = static_cast<size_t>(i);
      const Readings& r = readings[k];
      dxi[k] = hrvo[k]->SafeVelocity(r.pose.head<2>(), dxi[k], preferred[k], r.neighbours);
    }
    total_ns += ThreadCpuNs() - t0;
    result.calls += static_cast<int64_t>(due_robots.size());
    for (const int i : due_robots) {
      const size_t k = static_cast<size_t>(i);
      held[k] = limits.Apply(Robot::DxiToDxu(dxi[k], readings[k].pose.z(), drive));
    }
    for (int i = 0; i < n; ++i) {
      if (options.thesis_timing) {
        if (due(i, step, 3 + i % 2)) sense_movement(i);
        if (due(i, step, 2 + i % 2)) sense_odometry(i);
      }
      const size_t k = static_cast<size_t>(i);
      world.SetCommand(i, {held[k].v_mps, held[k].w_radps});
    }
    world.Step();
  }
  result.collision_errors = world.violations().collision_errors;
  result.boundary_errors = world.violations().boundary_errors;
  result.ns_per_call = result.calls > 0 ? total_ns / static_cast<double>(result.calls) : 0.0;
  return result;
}

std::vector<world::Pose2> CirclePoses(int num_robots, double radius_m, double jitter_m, double jitter_rad,
                                      uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<world::Pose2> poses;
  for (int i = 0; i < num_robots; ++i) {
    const double angle = 2.0 * M_PI * i / num_robots;
    world::Pose2 p{radius_m * std::cos(angle), radius_m * std::sin(angle), angle + M_PI};
    p.x_m += jitter_m * unit(rng);
    p.y_m += jitter_m * unit(rng);
    p.theta_rad = std::remainder(p.theta_rad + jitter_rad * unit(rng), 2.0 * M_PI);
    poses.push_back(p);
  }
  return poses;
}

std::vector<Eigen::Vector2d> AntipodalGoals(int num_robots, double radius_m) {
  std::vector<Eigen::Vector2d> goals;
  for (int i = 0; i < num_robots; ++i) {
    const double angle = 2.0 * M_PI * i / num_robots + M_PI;
    goals.emplace_back(radius_m * std::cos(angle), radius_m * std::sin(angle));
  }
  return goals;
}

void RandomCrossing(int num_robots, uint64_t seed, std::vector<world::Pose2>* start,
                    std::vector<Eigen::Vector2d>* goals) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> x(-1.3, 1.3), y(-0.75, 0.75), heading(-M_PI, M_PI);
  const auto spread = [&] {
    std::vector<Eigen::Vector2d> points;
    while (static_cast<int>(points.size()) < num_robots) {
      const Eigen::Vector2d p(x(rng), y(rng));
      bool apart = true;
      for (const Eigen::Vector2d& q : points) apart = apart && (p - q).norm() > 0.35;
      if (apart) points.push_back(p);
    }
    return points;
  };
  const std::vector<Eigen::Vector2d> from = spread();
  *goals = spread();
  start->clear();
  for (const Eigen::Vector2d& p : from) start->push_back({p.x(), p.y(), heading(rng)});
}

}  // namespace dream::agents
