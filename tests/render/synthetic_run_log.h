#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "dream/rectangle_obstacle_t.hpp"

namespace dream::sim::testing {

/// Writes small run logs with exactly the poses, obstacles and radio
/// messages a test wants, on the channels a run uses.
class SyntheticRunLog {
 public:
  explicit SyntheticRunLog(std::string path) : path_(std::move(path)) {}

  /// DREAM_POSES at `step`: one {x, y, theta} per robot.
  SyntheticRunLog& Poses(int64_t step, const std::vector<std::array<double, 3>>& poses);
  /// DREAM_OBSTACLES at `step`.
  SyntheticRunLog& Obstacles(int64_t step, const std::vector<rectangle_obstacle_t>& obstacles);
  /// DREAM_RADIO_<sender> sent at `step`.
  SyntheticRunLog& Radio(int64_t step, int sender);
  /// Any other channel (bytes that are no dream type).
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

}  // namespace dream::sim::testing
