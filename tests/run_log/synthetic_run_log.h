#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "dream/rectangle_obstacle_t.hpp"

namespace dream::testing {

/// Writes small run logs with exactly the poses, obstacles, radio messages,
/// statuses and faults a test wants, on the channels a run uses (and the
/// damaged or foreign messages a reader must survive).
class SyntheticRunLog {
 public:
  explicit SyntheticRunLog(std::string path) : path_(std::move(path)) {}

  /// DREAM_POSES at `step`: one {x, y, theta} per robot.
  SyntheticRunLog& Poses(int64_t step, const std::vector<std::array<double, 3>>& poses);
  /// DREAM_OBSTACLES at `step`.
  SyntheticRunLog& Obstacles(int64_t step, const std::vector<rectangle_obstacle_t>& obstacles);
  /// DREAM_POSES at `step` of one robot at the origin whose num_robots says
  /// `claimed_robots`: a count that lies about the message's size.
  SyntheticRunLog& LyingPoses(int64_t step, int32_t claimed_robots);
  /// DREAM_RADIO_<sender> sent at `step`.
  SyntheticRunLog& Radio(int64_t step, int sender);
  /// DREAM_STATUS at `step` in `state` (run_status_t) with those robots lost.
  SyntheticRunLog& Status(int64_t step, int8_t state, const std::vector<int32_t>& lost_robot_ids,
                          const std::string& detail);
  /// DREAM_FAULT_<channel_robot> for robot `robot_id` at `step`.
  SyntheticRunLog& Fault(int channel_robot, int32_t robot_id, int64_t step, const std::string& detail);
  /// Any dream message on any channel (e.g. a foreign type on a DREAM_* one),
  /// logged at its utime.
  template <typename Message>
  SyntheticRunLog& MessageOn(const std::string& channel, const Message& message) {
    std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()));
    message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    events_.push_back({channel, message.utime, std::move(bytes)});
    return *this;
  }
  /// `bytes` as they are on `channel` at `utime` (a message made to lie).
  SyntheticRunLog& Bytes(const std::string& channel, int64_t utime, std::vector<uint8_t> bytes) {
    events_.push_back({channel, utime, std::move(bytes)});
    return *this;
  }
  /// Any channel with bytes that are no dream type.
  SyntheticRunLog& Other(const std::string& channel);
  /// Writes the log; returns its path.
  std::string Write() const;

  /// A robot driving from (-1, 0) to (1, 0.5) over `steps` steps, and a
  /// second one standing at (0, -0.5) facing up.
  static SyntheticRunLog TwoRobots(const std::string& path, int steps);

 private:
  struct Event {
    std::string channel;
    int64_t utime;
    std::vector<uint8_t> data;
  };
  std::string path_;
  std::vector<Event> events_;
};

/// A rectangle obstacle for tests.
rectangle_obstacle_t Box(int id, double x, double y, double width, double height);

}  // namespace dream::testing
