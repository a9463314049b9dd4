#include "dream/render/run_track.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/log_reader.h"
#include "dream/radio_message_t.hpp"
#include "dream/world/robotarium_constants.h"

namespace dream::sim {

RunTrack RunTrack::Read(const std::string& log_path) {
  RunTrack track;
  track.log_path_ = log_path;
  track.obstacles_.emplace_back();  // "no obstacles yet", for poses before the first DREAM_OBSTACLES
  track.obstacles_.front().step = std::numeric_limits<int64_t>::min();
  lcm::LogReader reader(log_path);
  lcm::LogRecord record;
  while (reader.Next(&record)) {
    const int size = static_cast<int>(record.data.size());
    if (record.channel == lcm::kPosesChannel) {
      robot_poses_t poses;
      if (!lcm::Decode(record.data.data(), size, &poses)) continue;
      track.num_robots_ = std::max(track.num_robots_, poses.num_robots);
      track.poses_.push_back(std::move(poses));
    } else if (record.channel == lcm::kObstaclesChannel) {
      obstacles_t obstacles;
      if (lcm::Decode(record.data.data(), size, &obstacles)) track.obstacles_.push_back(std::move(obstacles));
    } else if (lcm::RobotIdFromChannel(record.channel, lcm::kRadioChannelPrefix)) {
      radio_message_t message;
      if (lcm::Decode(record.data.data(), size, &message)) track.radio_sends_.push_back({message.step, message.sender_id});
    }
  }
  if (track.poses_.empty()) throw std::runtime_error("no poses in " + log_path + ": nothing to render");

  // The world publishes a step's obstacles next to its poses, in either order:
  // match them by step, not by position in the log.
  std::stable_sort(track.obstacles_.begin() + 1, track.obstacles_.end(),
                   [](const obstacles_t& a, const obstacles_t& b) { return a.step < b.step; });
  std::stable_sort(track.radio_sends_.begin(), track.radio_sends_.end(),
                   [](const RadioSend& a, const RadioSend& b) { return a.step < b.step; });
  track.obstacle_index_.reserve(track.poses_.size());
  size_t next = 0;
  for (const robot_poses_t& poses : track.poses_) {
    while (next + 1 < track.obstacles_.size() && track.obstacles_[next + 1].step <= poses.step) ++next;
    track.obstacle_index_.push_back(next);
  }
  return track;
}

double RunTrack::duration_s() const {
  return static_cast<double>(last_step() - first_step()) * RobotariumConstants::kTimeStepSeconds;
}

size_t RunTrack::PoseIndexAtStep(int64_t step) const {
  const auto after = std::upper_bound(poses_.begin(), poses_.end(), step,
                                      [](int64_t s, const robot_poses_t& poses) { return s < poses.step; });
  return after == poses_.begin() ? 0 : static_cast<size_t>(after - poses_.begin() - 1);
}

std::vector<std::vector<std::array<double, 2>>> RunTrack::MovingObstaclePaths() const {
  std::map<int32_t, std::vector<std::array<double, 2>>> paths;
  for (size_t i = 1; i < obstacles_.size(); ++i) {
    for (const rectangle_obstacle_t& o : obstacles_[i].obstacles) {
      std::vector<std::array<double, 2>>& path = paths[o.id];
      if (path.empty() || path.back()[0] != o.center_x || path.back()[1] != o.center_y) {
        path.push_back({o.center_x, o.center_y});
      }
    }
  }
  std::vector<std::vector<std::array<double, 2>>> moving;
  for (auto& [id, path] : paths) {
    (void)id;
    if (path.size() > 1) moving.push_back(std::move(path));
  }
  return moving;
}

bool RunTrack::HasMovingObstacles() const { return !MovingObstaclePaths().empty(); }

std::vector<std::array<double, 2>> RunTrack::MinimumDistanceSeries() const {
  std::vector<std::array<double, 2>> series;
  series.reserve(poses_.size());
  for (const robot_poses_t& poses : poses_) {
    double closest_sq = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < poses.x.size(); ++i) {
      for (size_t j = i + 1; j < poses.x.size(); ++j) {
        const double dx = poses.x[i] - poses.x[j];
        const double dy = poses.y[i] - poses.y[j];
        closest_sq = std::min(closest_sq, dx * dx + dy * dy);
      }
    }
    if (std::isfinite(closest_sq)) series.push_back({static_cast<double>(poses.step), std::sqrt(closest_sq)});
  }
  return series;
}

}  // namespace dream::sim
