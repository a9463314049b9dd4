// The bridge world: agents run unchanged against a lab run replayed on the
// bus. The swap test runs the same code twice (bridge_test_support's
// RunAgainst), once with the simulator and once with the replay of an
// imported lab run, changing nothing but the World.
#include "dream/bridge/lab_replay_world.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>

#include "bridge_test_support.h"
#include "dream/bridge/lab_import.h"
#include "dream/bridge/submission_exporter.h"
#include "dream/bridge/submission_format.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/log_reader.h"
#include "dream/lcm/run_id.h"
#include "dream/node/run_recorder.h"
#include "dream/world/unicycle_world.h"

namespace dream::bridge {
namespace {

using ::testing::HasSubstr;

/// Payloads per channel matching `prefix`, in log order.
std::map<std::string, std::vector<std::vector<uint8_t>>> Messages(const std::string& log, const std::string& prefix) {
  std::map<std::string, std::vector<std::vector<uint8_t>>> messages;
  lcm::LogReader reader(log);
  lcm::LogRecord record;
  while (reader.Next(&record)) {
    if (record.channel.rfind(prefix, 0) != 0) continue;
    lcm::ClearRunId(&record.data);  // each run has its own id; the rest must be equal
    messages[record.channel].push_back(record.data);
  }
  return messages;
}

class LabReplayTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    run_dir_ = new std::string(testing::MakeRunFolder("replay_run", testing::ShippedConfig("go_to_goal")));
    export_dir_ = new std::string(testing::NewFolder("replay_export"));
    ExportSubmission(*run_dir_, *export_dir_, ExportOptions{});
  }
  static void TearDownTestSuite() {
    delete run_dir_;
    delete export_dir_;
  }

  /// Imports a lab result made from the export (perturbed or not); returns the lab run folder.
  static std::string ImportLab(const std::string& name,
                               const std::function<void(int64_t, double*)>& perturb = nullptr) {
    const std::string dir = testing::NewFolder(name);
    testing::WriteText(dir + "/dream_result.npy", formats::EncodeNpy(testing::PerfectLabResult(*export_dir_, perturb)));
    ImportLabRun(dir + "/dream_result.npy", *export_dir_, dir + "/lab");
    return dir + "/lab";
  }

  static std::string* run_dir_;
  static std::string* export_dir_;
};
std::string* LabReplayTest::run_dir_ = nullptr;
std::string* LabReplayTest::export_dir_ = nullptr;

TEST_F(LabReplayTest, AgentsRunUnchangedWhenOnlyTheWorldIsSwapped) {
  const std::string lab_dir = ImportLab("replay_swap");
  const run_config::RunConfig config = run_config::LoadRunConfigFile(lab_dir + "/config.yaml");
  const std::string out = testing::NewFolder("replay_swap_out");

  world::UnicycleWorld simulator(config.world, config.initial_poses, config.obstacles);
  const node::RunOutcome sim_outcome = testing::RunAgainst(simulator, config, out + "/sim.lcmlog");
  LabReplayWorld lab(ReadRunTrack(lab_dir + "/run.lcmlog"), config.world);
  const node::RunOutcome lab_outcome = testing::RunAgainst(lab, config, out + "/lab.lcmlog");

  ASSERT_EQ(lab_outcome.end, node::RunOutcome::End::kFinished) << lab_outcome.reason;
  EXPECT_EQ(lab_outcome.steps, sim_outcome.steps);
  EXPECT_TRUE(lab_outcome.robots_ever_lost.empty());
  EXPECT_EQ(lab_outcome.rejected_commands, 0);
  EXPECT_EQ(lab_outcome.robots_done, sim_outcome.robots_done);
  // On the lab's poses (here: exactly the simulated ones) the agents send the
  // same commands and radio messages, byte for byte, step for step.
  const auto sim_commands = Messages(out + "/sim.lcmlog", "DREAM_CMD_");
  const auto lab_commands = Messages(out + "/lab.lcmlog", "DREAM_CMD_");
  ASSERT_EQ(sim_commands.size(), 8u);
  EXPECT_EQ(lab_commands, sim_commands);
  EXPECT_EQ(Messages(out + "/lab.lcmlog", "DREAM_RADIO_"), Messages(out + "/sim.lcmlog", "DREAM_RADIO_"));
  EXPECT_EQ(Messages(out + "/lab.lcmlog", "DREAM_POSES"), Messages(out + "/sim.lcmlog", "DREAM_POSES"));
  // The world kept them beside the lab's: equal, since the lab drove the plan.
  for (int64_t k = 0; k < lab.step(); k += 50) {
    ASSERT_TRUE(lab.has_agent_command(k, 3));
    EXPECT_NEAR(lab.agent_command(k, 3).v_mps, lab.track().command(k, 3).v_mps, 1e-12) << k;
  }
}

TEST_F(LabReplayTest, RealPosesDriveTheAgentsAndTheLabCommandsAreRecordedBeside) {
  // A lab whose robots drift 1 cm to the right from step 100 on.
  const std::string lab_dir = ImportLab("replay_drift", [](int64_t k, double* row) {
    if (k < 100) return;
    for (int i = 0; i < 8; ++i) row[ResultLayout::X(8, i)] += 0.01;
  });
  const run_config::RunConfig config = run_config::LoadRunConfigFile(lab_dir + "/config.yaml");
  const std::string out = testing::NewFolder("replay_drift_out");
  node::RunRecorder lab_commands(out + "/lab_commands.lcmlog");
  LabReplayWorld lab(ReadRunTrack(lab_dir + "/run.lcmlog"), config.world, &lab_commands);
  const node::RunOutcome outcome = testing::RunAgainst(lab, config, out + "/replay.lcmlog");
  lab_commands.Close();
  ASSERT_EQ(outcome.end, node::RunOutcome::End::kFinished) << outcome.reason;
  // The agents saw the drift and answered it: their commands now differ from the lab's.
  double largest_difference = 0.0;
  for (int64_t k = 100; k < lab.step(); ++k) {
    if (!lab.has_agent_command(k, 0)) continue;
    largest_difference =
        std::max(largest_difference, std::abs(lab.agent_command(k, 0).v_mps - lab.track().command(k, 0).v_mps));
  }
  EXPECT_GT(largest_difference, 1e-4);
  const auto recorded = Messages(out + "/lab_commands.lcmlog", lcm::kLabCommandChannelPrefix);
  ASSERT_EQ(recorded.size(), 8u);
  EXPECT_EQ(recorded.at("DREAM_LAB_CMD_0").size(), static_cast<size_t>(lab.step()));
}

TEST(LabReplayWorldTest, ReplaysTheTrackAndCountsViolationsOnIt) {
  RunTrack track;
  track.num_robots = 2;
  for (int64_t k = 0; k <= 3; ++k) {
    track.utime.push_back(k * 40000);
    const double gap = k >= 2 ? 0.1 : 0.5;  // the robots collide from step 2
    track.poses.push_back({0.0, 0.0, 0.0});
    track.poses.push_back({gap, 0.0, 0.0});
    track.commands.push_back({k < 3 ? 0.1 : 0.0, 0.0});
    track.commands.push_back({k < 3 ? 20.0 : 0.0, 0.0});  // over the wheel limit: an actuator error
    track.obstacles.push_back({{0, 1.0, 0.5, 0.2, 0.2, 0.0, 0.0}});
  }
  LabReplayWorld world(track, world::WorldParams{});
  EXPECT_EQ(world.num_robots(), 2);
  EXPECT_EQ(world.last_step(), 3);
  EXPECT_EQ(world.velocities()[0].v_mps, 0.0);
  world.SetCommand(1, {0.05, 0.5});
  world.Step();
  EXPECT_EQ(world.utime(), 40000);
  EXPECT_EQ(world.velocities()[1].v_mps, 20.0);  // what the lab drove with during step 0
  std::vector<world::ObstacleState> obstacles;
  world.GetObstacleStates(&obstacles);
  ASSERT_EQ(obstacles.size(), 1u);
  EXPECT_EQ(obstacles[0].center_x_m, 1.0);
  world.StopRobot(1);
  world.Step();
  world.Step();
  EXPECT_EQ(world.violations().collision_errors, 1);
  EXPECT_EQ(world.violations().actuator_errors, 3);
  EXPECT_TRUE(world.has_agent_command(0, 1));
  EXPECT_FALSE(world.has_agent_command(1, 1));
  EXPECT_FALSE(world.has_agent_command(0, 0));
  EXPECT_EQ(world.agent_command(0, 1).w_radps, 0.5);
  EXPECT_THROW(world.Step(), std::out_of_range);
  EXPECT_THROW(world.SetCommand(2, {}), std::out_of_range);
  EXPECT_THROW(world.SetCommand(0, {std::nan(""), 0.0}), std::invalid_argument);
  RunTrack empty;
  EXPECT_THROW(LabReplayWorld(empty, world::WorldParams{}), std::invalid_argument);
}

}  // namespace
}  // namespace dream::bridge
