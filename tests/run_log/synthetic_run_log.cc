#include "synthetic_run_log.h"

#include "dream/node/run_recorder.h"
#include "dream/obstacles_t.hpp"
#include "dream/radio_message_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/run_status_t.hpp"

namespace dream::testing {
namespace {

constexpr int64_t kStepUs = 33000;

}  // namespace

rectangle_obstacle_t Box(int id, double x, double y, double width, double height) {
  rectangle_obstacle_t box{};
  box.id = id;
  box.center_x = x;
  box.center_y = y;
  box.width = width;
  box.height = height;
  return box;
}

SyntheticRunLog& SyntheticRunLog::Poses(int64_t step, const std::vector<std::array<double, 3>>& poses) {
  robot_poses_t message{};
  message.utime = step * kStepUs;
  message.step = step;
  message.num_robots = static_cast<int32_t>(poses.size());
  for (const auto& pose : poses) {
    message.x.push_back(pose[0]);
    message.y.push_back(pose[1]);
    message.theta.push_back(pose[2]);
    message.v.push_back(0.0);
    message.w.push_back(0.0);
  }
  return MessageOn("DREAM_POSES", message);
}

SyntheticRunLog& SyntheticRunLog::LyingPoses(int64_t step, int32_t claimed_robots) {
  Poses(step, {{0.0, 0.0, 0.0}});
  // After the 8-byte fingerprint: utime, step, run_id (8 bytes each), then num_robots, big-endian.
  std::vector<uint8_t>& bytes = events_.back().data;
  for (size_t i = 0; i < 4; ++i) bytes[32 + i] = static_cast<uint8_t>(claimed_robots >> (24 - 8 * i));
  return *this;
}

SyntheticRunLog& SyntheticRunLog::Obstacles(int64_t step, const std::vector<rectangle_obstacle_t>& obstacles) {
  obstacles_t message{};
  message.utime = step * kStepUs;
  message.step = step;
  message.num_obstacles = static_cast<int32_t>(obstacles.size());
  message.obstacles = obstacles;
  return MessageOn("DREAM_OBSTACLES", message);
}

SyntheticRunLog& SyntheticRunLog::Radio(int64_t step, int sender) {
  radio_message_t message{};
  message.utime = step * kStepUs;
  message.step = step;
  message.sender_id = sender;
  message.payload_size = 0;
  return MessageOn("DREAM_RADIO_" + std::to_string(sender), message);
}

SyntheticRunLog& SyntheticRunLog::Status(int64_t step, int8_t state, const std::vector<int32_t>& lost_robot_ids,
                                         const std::string& detail) {
  run_status_t message{};
  message.utime = step * kStepUs;
  message.step = step;
  message.state = state;
  message.num_lost = static_cast<int32_t>(lost_robot_ids.size());
  message.lost_robot_ids = lost_robot_ids;
  message.detail = detail;
  return MessageOn("DREAM_STATUS", message);
}

SyntheticRunLog& SyntheticRunLog::Fault(int channel_robot, int32_t robot_id, int64_t step, const std::string& detail) {
  robot_fault_t message{};
  message.utime = step * kStepUs;
  message.step = step;
  message.robot_id = robot_id;
  message.detail = detail;
  return MessageOn("DREAM_FAULT_" + std::to_string(channel_robot), message);
}

SyntheticRunLog& SyntheticRunLog::Other(const std::string& channel) {
  events_.push_back({channel, 0, {1, 2, 3}});
  return *this;
}

std::string SyntheticRunLog::Write() const {
  node::RunRecorder recorder(path_);
  for (const Event& event : events_) {
    recorder.Write(event.channel, event.utime, event.data.data(), static_cast<int>(event.data.size()));
  }
  recorder.Close();
  return path_;
}

SyntheticRunLog SyntheticRunLog::TwoRobots(const std::string& path, int steps) {
  SyntheticRunLog log(path);
  for (int step = 0; step <= steps; ++step) {
    const double u = static_cast<double>(step) / steps;
    log.Poses(step, {{-1.0 + 2.0 * u, 0.5 * u, 0.0}, {0.0, -0.5, 1.5707963}});
  }
  return log;
}

}  // namespace dream::testing
