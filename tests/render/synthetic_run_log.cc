#include "synthetic_run_log.h"

#include "dream/obstacles_t.hpp"
#include "dream/radio_message_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/node/run_recorder.h"

namespace dream::sim::testing {
namespace {

constexpr int64_t kStepUs = 33000;

template <typename Message>
std::vector<uint8_t> Encode(const Message& message) {
  std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

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
  events_.push_back({"DREAM_POSES", message.utime, Encode(message)});
  return *this;
}

SyntheticRunLog& SyntheticRunLog::Obstacles(int64_t step, const std::vector<rectangle_obstacle_t>& obstacles) {
  obstacles_t message{};
  message.utime = step * kStepUs;
  message.step = step;
  message.num_obstacles = static_cast<int32_t>(obstacles.size());
  message.obstacles = obstacles;
  events_.push_back({"DREAM_OBSTACLES", message.utime, Encode(message)});
  return *this;
}

SyntheticRunLog& SyntheticRunLog::Radio(int64_t step, int sender) {
  radio_message_t message{};
  message.utime = step * kStepUs;
  message.step = step;
  message.sender_id = sender;
  message.payload_size = 0;
  events_.push_back({"DREAM_RADIO_" + std::to_string(sender), message.utime, Encode(message)});
  return *this;
}

SyntheticRunLog& SyntheticRunLog::Other(const std::string& channel) {
  events_.push_back({channel, 0, {1, 2, 3}});
  return *this;
}

std::string SyntheticRunLog::Write() const {
  RunRecorder recorder(path_);
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

}  // namespace dream::sim::testing
