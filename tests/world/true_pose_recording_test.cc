// TruePoseRecording: with world.realism the log keeps the truth on DREAM_POSES
// and the message the agents were sent on DREAM_MEASURED_POSES, just before it.
#include "dream/node/true_pose_recording.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>
#include <unistd.h>
#include <vector>

#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/log_reader.h"
#include "dream/robot_poses_t.hpp"
#include "dream/world/realistic_world.h"
#include "dream/node/run_recorder.h"

namespace dream::world {
namespace {

// What SimNode publishes on DREAM_POSES for the world's current step.
std::vector<uint8_t> PosesMessage(const World& world) {
  robot_poses_t poses;
  poses.utime = world.utime();
  poses.step = world.step();
  poses.run_id = 42;
  poses.num_robots = world.num_robots();
  for (int i = 0; i < world.num_robots(); ++i) {
    const Pose2& pose = world.poses()[static_cast<size_t>(i)];
    poses.x.push_back(pose.x_m);
    poses.y.push_back(pose.y_m);
    poses.theta.push_back(pose.theta_rad);
    poses.v.push_back(world.step() > 0 ? world.velocities()[static_cast<size_t>(i)].v_mps : 0.0);
    poses.w.push_back(world.step() > 0 ? world.velocities()[static_cast<size_t>(i)].w_radps : 0.0);
  }
  std::vector<uint8_t> bytes(static_cast<size_t>(poses.getEncodedSize()));
  poses.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

robot_poses_t Decoded(const lcm::LogRecord& record) {
  robot_poses_t poses;
  EXPECT_TRUE(lcm::Decode(record.data.data(), static_cast<int>(record.data.size()), &poses)) << record.channel;
  return poses;
}

TEST(TruePoseRecordingTest, LogKeepsTheTruthOnPosesAndTheMeasurementBesideIt) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("true_pose_recording_" + std::to_string(::getpid()) + ".lcmlog"))
          .string();
  RealismParams realism;
  realism.pose_noise_m = 0.01;
  realism.pose_delay_steps = 1;
  RealisticWorld world(WorldParams{}, realism, 3, {{0.0, 0.0, 0.0}, {0.5, 0.5, 1.0}});
  std::vector<uint8_t> step0, step1;
  {
    node::RunRecorder recorder(path);
    std::optional<node::TruePoseRecording> truth;
    truth.emplace(recorder, world);
    step0 = PosesMessage(world);
    recorder.Write(lcm::kPosesChannel, world.utime(), step0.data(), static_cast<int>(step0.size()));
    recorder.Write(lcm::kStatusChannel, world.utime(), "s", 1);  // other channels pass through
    world.SetCommand(0, {0.1, 0.5});
    world.Step();
    step1 = PosesMessage(world);
    recorder.Write(lcm::kPosesChannel, world.utime(), step1.data(), static_cast<int>(step1.size()));
    truth.reset();  // from here on DREAM_POSES is written as given
    recorder.Write(lcm::kPosesChannel, world.utime(), step1.data(), static_cast<int>(step1.size()));
    recorder.Close();
  }
  const std::vector<lcm::LogRecord> records = lcm::LogReader::ReadAll(path);
  std::filesystem::remove(path);
  ASSERT_EQ(records.size(), 6u);
  const std::vector<std::string> channels{"DREAM_MEASURED_POSES", "DREAM_POSES", "DREAM_STATUS",
                                          "DREAM_MEASURED_POSES", "DREAM_POSES", "DREAM_POSES"};
  for (size_t i = 0; i < records.size(); ++i) EXPECT_EQ(records[i].channel, channels[i]) << i;

  EXPECT_EQ(records[0].data, step0);  // the message as the agents got it
  EXPECT_EQ(records[3].data, step1);
  EXPECT_EQ(records[5].data, step1);
  const robot_poses_t truth0 = Decoded(records[1]);
  const robot_poses_t truth1 = Decoded(records[4]);
  EXPECT_EQ(records[1].utime, 0);
  EXPECT_EQ(records[4].utime, 33000);
  EXPECT_EQ(truth1.step, 1);
  EXPECT_EQ(truth1.run_id, 42);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(truth1.x[i], world.true_poses()[i].x_m);
    EXPECT_EQ(truth1.y[i], world.true_poses()[i].y_m);
    EXPECT_EQ(truth1.theta[i], world.true_poses()[i].theta_rad);
    EXPECT_EQ(truth1.v[i], world.true_velocities()[i].v_mps);
    EXPECT_EQ(truth0.v[i], 0.0);
  }
  EXPECT_EQ(truth0.x[1], 0.5);
  EXPECT_NE(Decoded(records[0]).x[1], 0.5);  // measured with noise
  EXPECT_GT(truth1.x[0], 0.0);               // the truth moved
}

}  // namespace
}  // namespace dream::world
