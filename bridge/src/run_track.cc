#include "dream/bridge/run_track.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace dream::bridge {
namespace {

std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

bool Finite(double a, double b, double c = 0.0) { return std::isfinite(a) && std::isfinite(b) && std::isfinite(c); }

// A number that is not finite (NaN, inf) in a log's poses, velocities or
// obstacles: the world never publishes one, so the log is damaged or forged.
// Said here, naming the log, robot and step, rather than as a distance of
// "inf" or an error of the rule that met it first.
void RequireFiniteNumbers(const run_log::RunLog& log, const RunTrack& track) {
  const std::string damaged = ": the log is damaged or forged (the world publishes finite numbers only)";
  for (int64_t k = 0; k <= track.last_step(); ++k) {
    const std::string at_step = " at step " + std::to_string(k) + " is not finite (";
    for (int i = 0; i < track.num_robots; ++i) {
      const world::Pose2& p = track.pose(k, i);
      if (!Finite(p.x_m, p.y_m, p.theta_rad)) {
        throw std::runtime_error(log.path() + ": robot " + std::to_string(i) + "'s pose" + at_step + "x " +
                                 Number(p.x_m) + ", y " + Number(p.y_m) + ", theta " + Number(p.theta_rad) + ")" +
                                 damaged);
      }
      const world::UnicycleCommand& c = track.command(k, i);
      if (!Finite(c.v_mps, c.w_radps)) {
        // commands[k] came with the poses of step k + 1.
        throw std::runtime_error(log.path() + ": robot " + std::to_string(i) + "'s velocity at step " +
                                 std::to_string(k + 1) + " is not finite (v " + Number(c.v_mps) + ", w " +
                                 Number(c.w_radps) + ")" + damaged);
      }
    }
    for (const world::ObstacleState& o : track.obstacles[static_cast<size_t>(k)]) {
      if (!Finite(o.center_x_m, o.center_y_m, o.width_m) || !Finite(o.height_m, o.vx_mps, o.vy_mps)) {
        throw std::runtime_error(log.path() + ": obstacle " + std::to_string(o.id) + at_step + "centre " +
                                 Number(o.center_x_m) + ", " + Number(o.center_y_m) + ", size " + Number(o.width_m) +
                                 " x " + Number(o.height_m) + ", velocity " + Number(o.vx_mps) + ", " +
                                 Number(o.vy_mps) + ")" + damaged);
      }
    }
  }
}

}  // namespace

RunTrack RunTrackOf(const run_log::RunLog& log, RunEnd* end) {
  if (const std::optional<std::string> flaw = log.Flaw(/*with_status=*/end != nullptr)) {
    throw std::runtime_error(*flaw);
  }
  // A whole run log: steps 0, 1, 2, ... each once, with one robot count.
  RunTrack track;
  track.num_robots = log.num_robots();
  const auto n = static_cast<size_t>(track.num_robots);
  const size_t steps = log.poses().size();
  track.utime.reserve(steps);
  track.poses.reserve(steps * n);
  track.commands.resize(steps * n);
  track.obstacles.reserve(steps);
  for (size_t k = 0; k < steps; ++k) {
    const robot_poses_t& poses = log.poses()[k];
    track.utime.push_back(poses.utime);
    for (size_t i = 0; i < n; ++i) {
      track.poses.push_back(world::Pose2{poses.x[i], poses.y[i], poses.theta[i]});
      // This step's velocities are what the robots drove with from the step before.
      if (k > 0) track.commands[(k - 1) * n + i] = world::UnicycleCommand{poses.v[i], poses.w[i]};
    }
    std::vector<world::ObstacleState>& obstacles = track.obstacles.emplace_back();
    for (const rectangle_obstacle_t& o : log.obstacles_at(k).obstacles) {
      obstacles.push_back(world::ObstacleState{o.id, o.center_x, o.center_y, o.width, o.height, o.vx, o.vy});
    }
  }
  RequireFiniteNumbers(log, track);
  if (end != nullptr && log.last_status()) {
    const run_status_t& status = *log.last_status();
    end->seen = true;
    end->state = status.state;
    end->detail = status.detail;
    end->step = status.step;
    end->violations = world::ViolationCounts{status.boundary_errors, status.collision_errors, status.actuator_errors,
                                             status.obstacle_collisions};
    end->lost_robot_ids.assign(status.lost_robot_ids.begin(), status.lost_robot_ids.end());
    end->robot_faults = log.robot_faults();
  }
  return track;
}

RunTrack ReadRunTrack(const std::string& log_path, RunEnd* end) {
  return RunTrackOf(run_log::RunLog::Read(log_path), end);
}

}  // namespace dream::bridge
