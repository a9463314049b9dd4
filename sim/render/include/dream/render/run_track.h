#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "dream/obstacles_t.hpp"
#include "dream/robot_poses_t.hpp"

namespace dream::sim {

/// What a run's LCM log says happened, as pictures and videos need it: every
/// DREAM_POSES step in order, the obstacles at each of those steps, and who
/// spoke on the radio when. Works on any log with the dream channels:
/// simulated or imported from the lab.
class RunTrack {
 public:
  /// One DREAM_RADIO_<n> message: robot `sender_id` broadcast at `step`.
  struct RadioSend {
    int64_t step = 0;
    int32_t sender_id = 0;
  };

  /// Reads `log_path`; undecodable records are skipped.
  /// @throws std::runtime_error naming the file when it cannot be read, and
  ///         "no poses in <log>: nothing to render" when it holds no DREAM_POSES.
  static RunTrack Read(const std::string& log_path);

  const std::string& log_path() const { return log_path_; }
  /// Every DREAM_POSES message, in log order (never empty).
  const std::vector<robot_poses_t>& poses() const { return poses_; }
  /// obstacles_at(i): the obstacles at the step of poses()[i] (the last
  /// DREAM_OBSTACLES published for that step or before; none before the first).
  const std::vector<rectangle_obstacle_t>& obstacles_at(size_t pose_index) const {
    return obstacles_[obstacle_index_[pose_index]].obstacles;
  }
  /// Radio broadcasts by step (log order within a step).
  const std::vector<RadioSend>& radio_sends() const { return radio_sends_; }

  /// The most robots any step has.
  int num_robots() const { return num_robots_; }
  int64_t first_step() const { return poses_.front().step; }
  int64_t last_step() const { return poses_.back().step; }
  /// Simulated seconds from the first to the last step.
  double duration_s() const;
  /// The index of the last pose whose step is <= `step` (0 before the first).
  size_t PoseIndexAtStep(int64_t step) const;
  /// The centre path of each obstacle that moved during the run, by id.
  std::vector<std::vector<std::array<double, 2>>> MovingObstaclePaths() const;
  /// True when some obstacle is not where it started at some step.
  bool HasMovingObstacles() const;
  /// {step, distance between the two closest robot centres, metres} per step
  /// with at least two robots.
  std::vector<std::array<double, 2>> MinimumDistanceSeries() const;

 private:
  std::string log_path_;
  std::vector<robot_poses_t> poses_;
  std::vector<obstacles_t> obstacles_;      // [0] is an empty message: "no obstacles yet"
  std::vector<size_t> obstacle_index_;      // per pose: index into obstacles_
  std::vector<RadioSend> radio_sends_;
  int num_robots_ = 0;
};

}  // namespace dream::sim
