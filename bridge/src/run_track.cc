#include "dream/bridge/run_track.h"

#include <stdexcept>

#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/log_reader.h"
#include "dream/obstacles_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/run_status_t.hpp"

namespace dream::bridge {

RunTrack ReadRunTrack(const std::string& log_path, RunEnd* end) {
  RunTrack track;
  std::vector<sim::ObstacleState> obstacles;
  int64_t obstacles_step = -1;
  lcm::LogReader reader(log_path);
  lcm::LogRecord record;
  robot_poses_t poses;
  obstacles_t obstacle_message;
  run_status_t status;
  robot_fault_t fault;
  std::map<int, std::string> faults;
  auto fail = [&log_path](const std::string& problem) { throw std::runtime_error(log_path + ": " + problem); };
  // A message the reader cannot use, named by the event's index and byte offset.
  auto undecodable = [&](const char* channel, const std::string& problem) {
    fail("event " + std::to_string(reader.event_index()) + " at byte " + std::to_string(reader.event_offset()) + ": a " +
         channel + " message cannot be decoded; in the message: " + problem);
  };
  while (reader.Next(&record)) {
    const int size = static_cast<int>(record.data.size());
    if (record.channel == lcm::kPosesChannel) {
      if (auto problem = lcm::DecodeProblem(record.data.data(), size, &poses)) undecodable("DREAM_POSES", *problem);
      const int64_t expected = track.last_step() + 1;
      if (poses.step != expected) {
        fail("DREAM_POSES jumps from step " + std::to_string(track.last_step()) + " to step " +
             std::to_string(poses.step) + "; a run log has every step once, in order");
      }
      if (track.num_robots == 0) {
        if (poses.num_robots < 1) fail("DREAM_POSES at step 0 has no robots");
        track.num_robots = poses.num_robots;
      } else if (poses.num_robots != track.num_robots) {
        fail("DREAM_POSES at step " + std::to_string(poses.step) + " has " + std::to_string(poses.num_robots) +
             " robots, earlier steps " + std::to_string(track.num_robots));
      }
      const auto n = static_cast<size_t>(track.num_robots);
      // This step's velocities are what the robots drove with from the step before.
      if (poses.step > 0) {
        for (size_t i = 0; i < n; ++i) {
          track.commands[(static_cast<size_t>(poses.step) - 1) * n + i] = sim::UnicycleCommand{poses.v[i], poses.w[i]};
        }
      }
      track.utime.push_back(poses.utime);
      for (size_t i = 0; i < n; ++i) track.poses.push_back(sim::Pose2{poses.x[i], poses.y[i], poses.theta[i]});
      track.commands.resize(track.poses.size());
      track.obstacles.push_back(obstacles_step == poses.step ? obstacles : std::vector<sim::ObstacleState>{});
    } else if (record.channel == lcm::kObstaclesChannel) {
      if (auto problem = lcm::DecodeProblem(record.data.data(), size, &obstacle_message)) undecodable("DREAM_OBSTACLES", *problem);
      obstacles.clear();
      for (const rectangle_obstacle_t& o : obstacle_message.obstacles) {
        obstacles.push_back(sim::ObstacleState{o.id, o.center_x, o.center_y, o.width, o.height, o.vx, o.vy});
      }
      obstacles_step = obstacle_message.step;
    } else if (record.channel == lcm::kStatusChannel && end != nullptr) {
      if (auto problem = lcm::DecodeProblem(record.data.data(), size, &status)) undecodable("DREAM_STATUS", *problem);
      end->seen = true;
      end->state = status.state;
      end->detail = status.detail;
      end->step = status.step;
      end->violations = sim::ViolationCounts{status.boundary_errors, status.collision_errors, status.actuator_errors,
                                             status.obstacle_collisions};
      end->lost_robot_ids.assign(status.lost_robot_ids.begin(), status.lost_robot_ids.end());
    } else if (end != nullptr && record.channel.rfind(lcm::kFaultChannelPrefix, 0) == 0) {
      // Only a fault whose robot the world then lost counts (below): one from
      // another agent, which the world refused, names a robot that drove on.
      const std::optional<int> id = lcm::RobotIdFromChannel(record.channel, lcm::kFaultChannelPrefix);
      if (id && lcm::Decode(record.data.data(), size, &fault) && fault.robot_id == *id && faults.count(*id) == 0) {
        faults[*id] = "step " + std::to_string(fault.step) + ": " + fault.detail;  // bounded by lcm::Decode
      }
    }
  }
  if (end != nullptr) {
    for (int id : end->lost_robot_ids) {
      if (faults.count(id) != 0) end->robot_faults[id] = faults[id];
    }
  }
  if (track.utime.empty()) fail("the log holds no DREAM_POSES messages: it is not a run log");
  return track;
}

}  // namespace dream::bridge
