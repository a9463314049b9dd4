#include "dream/session/placed_start.h"

#include <cstdint>
#include <vector>

#include "dream/config/config_error.h"
#include "dream/lcm/channels.h"
#include "dream/robot_poses_t.hpp"
#include "dream/world/startup_drive.h"
#include "dream/world/startup_drive_trials.h"

namespace dream::session {

run_config::RunConfig PlacedStart::Drive(const run_config::RunConfig& config, node::RunRecorder& recorder) {
  const world::StartupDrive drive(config.world, config.initial_poses);
  // The drive's poses are kept until it ends: its utimes count back from step 0.
  std::vector<std::vector<world::Pose2>> steps;
  const world::StartupDriveResult result =
      drive.Run(world::StartupDriveTrials::PlacementSeed(config.seed, 0),
                [&steps](int, const std::vector<world::Pose2>& poses) { steps.push_back(poses); });
  if (!result.settled) {
    throw config::ConfigError(config.name + ": world.start: placed: the Robotarium's start-up drive did not bring " +
                              "the robots onto their start poses: " + result.DescribeMisses());
  }
  const int64_t step_utime = static_cast<int64_t>(config.world.time_step_s * 1e6 + 0.5);
  dream::robot_poses_t message;
  message.num_robots = config.num_robots;
  std::vector<uint8_t> buffer;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    message.step = static_cast<int64_t>(k) + 1;
    message.utime = -static_cast<int64_t>(steps.size() - k) * step_utime;
    message.run_id = 0;  // recorded only; the run's id is drawn when it starts
    message.x.clear();
    message.y.clear();
    message.theta.clear();
    for (const world::Pose2& pose : steps[k]) {
      message.x.push_back(pose.x_m);
      message.y.push_back(pose.y_m);
      message.theta.push_back(pose.theta_rad);
    }
    message.v.assign(steps[k].size(), 0.0);
    message.w.assign(steps[k].size(), 0.0);
    const int size = message.getEncodedSize();
    buffer.resize(static_cast<std::size_t>(size));
    message.encode(buffer.data(), 0, size);
    recorder.Write(lcm::kStartupPosesChannel, message.utime, buffer.data(), size);
  }
  run_config::RunConfig placed = config;
  placed.initial_poses = result.final_poses;
  return placed;
}

}  // namespace dream::session
