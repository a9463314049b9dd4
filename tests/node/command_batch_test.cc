#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "dream/lcm/bad_message_log.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/log_reader.h"
#include "dream/node/command_intake.h"
#include "dream/node/run_recorder.h"
#include "dream/node/sim_node.h"
#include "dream/robot_poses_t.hpp"
#include "quiet_bus.h"
#include "dream/robot_commands_t.hpp"
#include "../support/sample_lcm_messages.h"
#include "dream/velocity_command_t.hpp"
#include "dream/world/unicycle_world.h"

// DREAM_CMDS (robot_commands_t): every robot's command in one message, each
// entry taken exactly as its robot's DREAM_CMD_<id> from the same agent.
namespace dream::node {
namespace {

constexpr int64_t kRunId = 77;
constexpr int64_t kAgent = 500;

struct EntryHeard {
  std::string channel;
  velocity_command_t command;
  Heard heard;
};

robot_commands_t Batch(const std::vector<int32_t>& ids, int64_t agent = kAgent) {
  return dream::testing::CommandBatchOf(ids, kRunId, agent);
}

class CommandBatchTest : public ::testing::Test {
 protected:
  CommandBatchTest()
      : world_(world::WorldParams{}, {{-1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}),
        robots_(3),
        intake_({world_, options_, kRunId, robots_, bad_messages_, clock_,
                 [this](int64_t run_id, const std::string& seen_on) {
                   other_worlds_.push_back(seen_on + " " + std::to_string(run_id));
                 }}) {}

  Heard TakeAll(const robot_commands_t& batch) {
    heard_.clear();
    return intake_.TakeAll("DREAM_CMDS", batch,
                           [this](const std::string& channel, const velocity_command_t& c, Heard h) {
                             heard_.push_back({channel, c, h});
                           });
  }

  config::SimNodeOptions options_;
  world::UnicycleWorld world_;
  std::vector<RobotSlot> robots_;
  lcm::BadMessageLog bad_messages_;
  NodeClock clock_;
  std::vector<std::string> other_worlds_;
  CommandIntake intake_;
  std::vector<EntryHeard> heard_;
};

TEST_F(CommandBatchTest, EachEntryIsTakenAsItsRobotsCommandAndToldAsThatMessage) {
  EXPECT_EQ(TakeAll(Batch({2, 0, 1})), Heard::kUsed);
  ASSERT_EQ(heard_.size(), 3u);
  const std::vector<std::string> channels = {"DREAM_CMD_2", "DREAM_CMD_0", "DREAM_CMD_1"};
  for (size_t i = 0; i < 3; ++i) {
    const velocity_command_t& c = heard_[i].command;
    EXPECT_EQ(heard_[i].channel, channels[i]);
    EXPECT_EQ(heard_[i].heard, Heard::kUsed);
    EXPECT_EQ(c.robot_id, std::stoi(channels[i].substr(10)));
    EXPECT_EQ(c.run_id, kRunId);
    EXPECT_EQ(c.agent_id, kAgent);
    EXPECT_DOUBLE_EQ(c.v, 0.01 * (c.robot_id + 1));
    EXPECT_DOUBLE_EQ(robots_[static_cast<size_t>(c.robot_id)].v_mps, c.v);
    EXPECT_EQ(robots_[static_cast<size_t>(c.robot_id)].owner_agent_id, kAgent);
  }
  EXPECT_TRUE(robots_[1].done);
  EXPECT_FALSE(robots_[0].done);
  EXPECT_EQ(intake_.rejected_commands(), 0);
  // The world resends its step: the same message again is a repeat, not recorded twice.
  EXPECT_EQ(TakeAll(Batch({2, 0, 1})), Heard::kUsed);
  for (const EntryHeard& entry : heard_) EXPECT_EQ(entry.heard, Heard::kRepeat);
}

TEST_F(CommandBatchTest, ARobotListedTwiceRefusesTheWholeMessage) {
  EXPECT_EQ(TakeAll(Batch({0, 1, 0})), Heard::kRefused);
  EXPECT_TRUE(heard_.empty());
  EXPECT_EQ(intake_.rejected_commands(), 1);
  EXPECT_EQ(robots_[1].command_step, RobotSlot{}.command_step) << "no entry of a refused message is taken";
  ASSERT_EQ(bad_messages_.first().count("DREAM_CMDS"), 1u);
  EXPECT_NE(bad_messages_.first().at("DREAM_CMDS").reason.find("robot 0 is listed twice"), std::string::npos);
}

TEST_F(CommandBatchTest, MoreEntriesThanTheRunsRobotsRefuseTheWholeMessage) {
  EXPECT_EQ(TakeAll(Batch({0, 1, 2, 3})), Heard::kRefused);
  EXPECT_TRUE(heard_.empty());
  EXPECT_NE(bad_messages_.first().at("DREAM_CMDS").reason.find("4 commands, but this run has 3 robots"),
            std::string::npos);
}

TEST_F(CommandBatchTest, AnEntryForARobotTheRunDoesNotHaveIsRefusedTheOthersTaken) {
  EXPECT_EQ(TakeAll(Batch({0, 7})), Heard::kUsed);
  ASSERT_EQ(heard_.size(), 2u);
  EXPECT_EQ(heard_[0].heard, Heard::kUsed);
  EXPECT_EQ(heard_[1].heard, Heard::kRefused);
  EXPECT_EQ(heard_[1].channel, "DREAM_CMD_7");
  EXPECT_NE(bad_messages_.first().at("DREAM_CMDS robot 7").reason.find("robot 7 does not exist"), std::string::npos);
  TakeAll(Batch({-1}));
  EXPECT_EQ(heard_.at(0).heard, Heard::kRefused);
  EXPECT_EQ(intake_.rejected_commands(), 2);
}

TEST_F(CommandBatchTest, AnotherRunsCommandsAreRefusedAndItsWorldNoted) {
  robot_commands_t batch = Batch({0, 1});
  batch.run_id = 78;
  TakeAll(batch);
  for (const EntryHeard& entry : heard_) EXPECT_EQ(entry.heard, Heard::kRefused);
  EXPECT_EQ(intake_.rejected_commands(), 2);
  ASSERT_FALSE(other_worlds_.empty());
  EXPECT_EQ(other_worlds_[0], "DREAM_CMDS robot 0 78");
}

TEST_F(CommandBatchTest, AFutureStepIsRefused) {
  robot_commands_t batch = Batch({0});
  batch.step = 5;
  TakeAll(batch);
  EXPECT_EQ(heard_.at(0).heard, Heard::kRefused);
  EXPECT_NE(bad_messages_.first().at("DREAM_CMDS robot 0").reason.find("answers step 5 but the world is at step 0"),
            std::string::npos);
}

TEST_F(CommandBatchTest, ANanEntryHoldsItsRobotStillAndTheOthersDrive) {
  robot_commands_t batch = Batch({0, 1});
  batch.v[0] = std::numeric_limits<double>::quiet_NaN();
  TakeAll(batch);
  EXPECT_EQ(heard_.at(0).heard, Heard::kRefused);
  EXPECT_EQ(heard_.at(1).heard, Heard::kUsed);
  EXPECT_EQ(robots_[0].v_mps, 0.0);
  EXPECT_EQ(robots_[0].command_step, 0) << "an absurd command still answers the step";
  EXPECT_DOUBLE_EQ(robots_[1].v_mps, 0.02);
  EXPECT_NE(bad_messages_.first().at("DREAM_CMDS robot 0").reason.find("absurd velocity"), std::string::npos);
}

TEST_F(CommandBatchTest, ASecondAgentsBatchIsAConflictForEveryRobotItNames) {
  TakeAll(Batch({0, 1}));
  robot_commands_t second = Batch({1, 2}, kAgent + 1);
  TakeAll(second);
  EXPECT_EQ(heard_.at(0).heard, Heard::kRefused) << "robot 1 is driven by the first agent";
  EXPECT_EQ(heard_.at(1).heard, Heard::kUsed) << "robot 2 had no agent";
  EXPECT_EQ(intake_.command_conflicts(), 1);
  EXPECT_EQ(robots_[1].owner_agent_id, kAgent);
  EXPECT_EQ(robots_[2].owner_agent_id, kAgent + 1);
}

TEST_F(CommandBatchTest, AnEntryIsCheckedAsItsPerRobotMessageWouldBe) {
  // The same commands sent per robot to a second intake leave the same slots and counts.
  std::vector<RobotSlot> robots(3);
  lcm::BadMessageLog bad_messages;
  CommandIntake per_robot({world_, options_, kRunId, robots, bad_messages, clock_, [](int64_t, const std::string&) {}});
  robot_commands_t batch = Batch({0, 1, 2});
  batch.w[2] = std::numeric_limits<double>::infinity();
  TakeAll(batch);
  for (const EntryHeard& entry : heard_) {
    EXPECT_EQ(per_robot.Take(entry.channel, entry.command), entry.heard) << entry.channel;
  }
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(robots[i].command_step, robots_[i].command_step);
    EXPECT_EQ(robots[i].v_mps, robots_[i].v_mps);
    EXPECT_EQ(robots[i].w_radps, robots_[i].w_radps);
    EXPECT_EQ(robots[i].done, robots_[i].done);
  }
  EXPECT_EQ(per_robot.rejected_commands(), intake_.rejected_commands());
}

// Through the world: a script-like agent answers every step with one DREAM_CMDS for
// the three robots (and, at step 2, a forged one listing robot 0 twice).
TEST(CommandBatchRunTest, TheWorldDrivesEveryRobotFromOneMessageAndLogsEachAsItsDreamCmd) {
  lcm::LcmBus bus("memq://");
  testing::QuietBus quiet_bus(bus);
  world::UnicycleWorld world(world::WorldParams{}, {{-1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}});
  lcm::BadMessageLog bad_poses;
  const lcm::Subscription agent = lcm::Subscribe<robot_poses_t>(
      bus, lcm::kPosesChannel,
      [&bus](const std::string&, const robot_poses_t& poses) {
        robot_commands_t commands = Batch({0, 1, 2});
        commands.utime = poses.utime;
        commands.step = poses.step;
        commands.run_id = poses.run_id;
        commands.v = {0.1, 0.05, -0.1};
        commands.w = {0.0, 0.0, 0.0};
        commands.done = {0, 0, 0};
        if (poses.step == 2) {
          robot_commands_t forged = commands;
          forged.robot_id = {0, 0, 2};
          forged.v = {-0.2, -0.2, -0.2};
          lcm::Publish(bus, lcm::kCommandsChannel, forged);
        }
        lcm::Publish(bus, lcm::kCommandsChannel, commands);
      },
      bad_poses);
  config::SimNodeOptions options;
  options.max_steps = 6;
  options.stop_when_done = false;
  options.start_timeout_s = 0.5;
  options.progress_interval_s = 0.0;
  const std::string log_path = ::testing::TempDir() + "/command_batch_" + std::to_string(::getpid()) + ".lcmlog";
  RunOutcome outcome;
  {
    RunRecorder recorder(log_path);
    SimNode node(quiet_bus, world, &recorder, options);
    node.set_clock(quiet_bus.clock());
    std::atomic<bool> stop{false};
    outcome = node.Run(stop);
    recorder.Close();
  }
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_EQ(outcome.steps, 6);
  EXPECT_NEAR(world.poses()[0].x_m, -1.0 + 6 * 0.033 * 0.1, 1e-12) << "the forged message moved nothing";
  EXPECT_NEAR(world.poses()[2].x_m, 1.0 - 6 * 0.033 * 0.1, 1e-12);
  EXPECT_EQ(outcome.rejected_commands, 1);
  EXPECT_EQ(outcome.bad_messages.at("DREAM_CMDS"), 1);
  std::map<std::string, std::vector<int64_t>> steps_logged;
  for (const lcm::LogRecord& record : lcm::LogReader::ReadAll(log_path)) {
    if (record.channel.rfind("DREAM_CMD", 0) != 0) continue;
    velocity_command_t command;
    ASSERT_TRUE(lcm::Decode(record.data.data(), static_cast<int>(record.data.size()), &command)) << record.channel;
    EXPECT_EQ(record.channel, lcm::CommandChannel(command.robot_id));
    EXPECT_EQ(command.agent_id, kAgent);
    EXPECT_EQ(command.run_id, outcome.run_id);
    steps_logged[record.channel].push_back(command.step);
  }
  std::remove(log_path.c_str());
  const std::vector<int64_t> every_step = {0, 1, 2, 3, 4, 5};
  EXPECT_EQ(steps_logged, (std::map<std::string, std::vector<int64_t>>{
                              {"DREAM_CMD_0", every_step}, {"DREAM_CMD_1", every_step}, {"DREAM_CMD_2", every_step}}));
}

}  // namespace
}  // namespace dream::node
