#include "dream/bridge/run_track.h"

#include <stdexcept>

namespace dream::bridge {

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
      track.poses.push_back(sim::Pose2{poses.x[i], poses.y[i], poses.theta[i]});
      // This step's velocities are what the robots drove with from the step before.
      if (k > 0) track.commands[(k - 1) * n + i] = sim::UnicycleCommand{poses.v[i], poses.w[i]};
    }
    std::vector<sim::ObstacleState>& obstacles = track.obstacles.emplace_back();
    for (const rectangle_obstacle_t& o : log.obstacles_at(k).obstacles) {
      obstacles.push_back(sim::ObstacleState{o.id, o.center_x, o.center_y, o.width, o.height, o.vx, o.vy});
    }
  }
  if (end != nullptr && log.last_status()) {
    const run_status_t& status = *log.last_status();
    end->seen = true;
    end->state = status.state;
    end->detail = status.detail;
    end->step = status.step;
    end->violations = sim::ViolationCounts{status.boundary_errors, status.collision_errors, status.actuator_errors,
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
