// The command arrows: each robot's newest DREAM_CMD_<id> of the run drawn, live (BusFrameCollector)
// and in replay (RunReplayJson's "commands").
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/robot_commands_t.hpp"
#include "dream/velocity_command_t.hpp"
#include "dream/view/bus_frame_collector.h"
#include "dream/view/frame_json.h"
#include "dream/view/live_view.h"
#include "dream/view/view_server.h"
#include "dream/view/replay_json.h"
#include "synthetic_run_log.h"
#include "temp_folder.h"
#include "two_robot_view_bus.h"

namespace dream::view {
namespace {

using dream::testing::SyntheticRunLog;
using dream::testing::TempFolder;

velocity_command_t Command(int64_t run_id, int64_t step, int32_t robot, double v, double w) {
  velocity_command_t command{};
  command.run_id = run_id;
  command.step = step;
  command.utime = step * 33000;
  command.robot_id = robot;
  command.agent_id = 1;
  command.v = v;
  command.w = w;
  return command;
}

using CommandArrowsTest = TwoRobotViewBus;

TEST_F(CommandArrowsTest, EachRobotsNewestCommandOfTheRunIsInTheFrame) {
  Step(4, 0);
  Step(4, 1);
  Send("DREAM_CMD_0", Command(4, 1, 0, 0.1, 0.5));
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  ASSERT_EQ(frame_.command_v_mps.size(), 2u);
  EXPECT_EQ(frame_.command_v_mps[0], 0.1);
  EXPECT_EQ(frame_.command_w_radps[0], 0.5);
  EXPECT_TRUE(std::isnan(frame_.command_v_mps[1]));  // robot 1 has said nothing yet
  const nlohmann::json json = nlohmann::json::parse(FrameJson(frame_));
  EXPECT_EQ(json["cv"][0], 0.1);
  EXPECT_TRUE(json["cv"][1].is_null());
}

TEST_F(CommandArrowsTest, CommandsNotOfTheRunDrawnOrItsRobotsOrAheadOfItAreNotDrawn) {
  Step(4, 0);
  Step(4, 1);
  Send("DREAM_CMD_0", Command(4, 1, 0, 0.1, 0.0));
  Send("DREAM_CMD_0", Command(5, 1, 0, 0.9, 0.0));  // another run
  Send("DREAM_CMD_1", Command(4, 1, 0, 0.9, 0.0));  // robot 0's, on robot 1's channel
  Send("DREAM_CMD_0", Command(4, 7, 0, 0.9, 0.0));  // a step not drawn yet
  Send("DREAM_CMD_0", Command(4, 0, 0, 0.9, 0.0));  // older than the one kept
  Send("DREAM_CMD_9", Command(4, 1, 9, 0.9, 0.0));  // no robot of the run
  Send("DREAM_CMD_1", Command(4, 1, 1, 0.0, 0.0));
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  ASSERT_EQ(frame_.command_v_mps.size(), 2u);
  EXPECT_EQ(frame_.command_v_mps[0], 0.1);
  EXPECT_EQ(frame_.command_v_mps[1], 0.0);
  bus_.Publish("DREAM_CMD_0", "not a command", 13);
  Handle();
  EXPECT_EQ(collector_.bad_messages(), 1);
}

robot_commands_t Commands(int64_t run_id, int64_t step, std::vector<int32_t> robots, std::vector<double> v) {
  robot_commands_t commands{};
  commands.run_id = run_id;
  commands.step = step;
  commands.agent_id = 1;
  commands.num_commands = static_cast<int32_t>(robots.size());
  commands.robot_id = std::move(robots);
  commands.w.assign(v.size(), 0.25);
  commands.done.assign(v.size(), 0);
  commands.v = std::move(v);
  return commands;
}

// A `dream run` script's DREAM_CMDS: each entry drawn as its robot's DREAM_CMD_<id> would be.
TEST_F(CommandArrowsTest, EveryRobotsCommandInOneMessageIsDrawnEntryByEntry) {
  Step(4, 0);
  Step(4, 1);
  robot_commands_t commands = Commands(4, 1, {1, 0}, {0.05, 0.1});
  commands.w = {0.25, -0.5};
  Send("DREAM_CMDS", commands);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  ASSERT_EQ(frame_.command_v_mps.size(), 2u);
  EXPECT_EQ(frame_.command_v_mps[0], 0.1);
  EXPECT_EQ(frame_.command_w_radps[0], -0.5);
  EXPECT_EQ(frame_.command_v_mps[1], 0.05);
  Send("DREAM_CMDS", Commands(4, 1, {9, 1}, {0.9, 0.07}));  // robot 9 is no robot of the run: left out
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.command_v_mps[0], 0.1);
  EXPECT_EQ(frame_.command_v_mps[1], 0.07);
  Send("DREAM_CMDS", Commands(5, 1, {1, 0}, {0.7, 0.7}));  // another run's: not drawn
  EXPECT_FALSE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(collector_.bad_messages(), 0);
  bus_.Publish("DREAM_CMDS", "not commands", 12);
  Handle();
  EXPECT_EQ(collector_.bad_messages(), 1);
}

// What the world refuses whole (lcm::CommandBatch) the view refuses too: no arrow, a bad message.
TEST_F(CommandArrowsTest, AMessageTheWorldRefusesWholeDrawsNoArrowAndIsCounted) {
  Step(4, 0);
  Step(4, 1);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  Send("DREAM_CMDS", Commands(4, 1, {0, 1, 0}, {0.1, 0.2, 0.3}));  // robot 0 listed twice
  EXPECT_FALSE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_TRUE(frame_.command_v_mps.empty());
  EXPECT_EQ(collector_.bad_messages(), 1);
  Send("DREAM_CMDS", Commands(4, 1, {1, 0, 9}, {0.1, 0.2, 0.3}));  // 3 entries, the run has 2 robots
  EXPECT_FALSE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(collector_.bad_messages(), 2);
  Send("DREAM_CMDS", Commands(5, 1, {0, 0}, {0.1, 0.2}));  // another run's: not this run's to judge
  EXPECT_EQ(collector_.bad_messages(), 2);
  Send("DREAM_CMDS", Commands(4, 1, {0}, {0.15}));
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  ASSERT_EQ(frame_.command_v_mps.size(), 2u);
  EXPECT_EQ(frame_.command_v_mps[0], 0.15);
  EXPECT_TRUE(std::isnan(frame_.command_v_mps[1]));
}

// dream view on udpm: the commands (most of a run's datagrams) only once a page shows the arrows.
TEST_F(CommandArrowsTest, ACollectorAskedForNoCommandsHearsThemOnlyOnceSubscribed) {
  lcm::LcmBus bus("memq://");
  BusFrameCollector collector(bus, world::WorldParams(), &RunChoice::Clock::now, false);
  auto step = [&](int64_t s) {
    robot_poses_t poses{};
    poses.run_id = 4;
    poses.step = s;
    poses.num_robots = 1;
    poses.x = poses.y = poses.theta = poses.v = poses.w = {0.0};
    run_status_t status{};
    status.run_id = 4;
    status.step = s;
    status.state = run_status_t::RUNNING;
    status.num_robots = 1;
    lcm::Publish(bus, "DREAM_STATUS", status);
    lcm::Publish(bus, "DREAM_POSES", poses);
    lcm::Publish(bus, "DREAM_CMD_0", Command(4, s, 0, 0.1 * static_cast<double>(s + 1), 0.0));
    robot_commands_t commands{};
    commands.run_id = 4;
    commands.step = s;
    commands.num_commands = 1;
    commands.robot_id = {0};
    commands.v = {0.5 * static_cast<double>(s + 1)};
    commands.w = {0.0};
    commands.done = {0};
    if (s == 2) lcm::Publish(bus, "DREAM_CMDS", commands);
    while (bus.HandleSubscriptions(0) > 0) {
    }
  };
  step(0);
  ASSERT_TRUE(collector.TakeFrame(&frame_, &version_));
  EXPECT_TRUE(frame_.command_v_mps.empty());  // not subscribed: not heard
  collector.SubscribeCommands();
  collector.SubscribeCommands();  // once is enough: a second call changes nothing
  step(1);
  ASSERT_TRUE(collector.TakeFrame(&frame_, &version_));
  ASSERT_EQ(frame_.command_v_mps.size(), 1u);
  EXPECT_EQ(frame_.command_v_mps[0], 0.2);
  step(2);  // DREAM_CMDS, heard once subscribed too
  ASSERT_TRUE(collector.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.command_v_mps[0], 1.5);
}

TEST(LiveViewCommandsTest, APageAsksForTheCommands) {
  lcm::LcmBus bus("memq://");
  ViewServer server({"127.0.0.1", 0, false, 4});
  ViewSetup setup;
  setup.commands_on_request = true;
  LiveView live(bus, server, setup);
  live.TakePageRequests();
  EXPECT_FALSE(live.collector().hears_commands());  // no page asked
  EXPECT_FALSE(live.OnPageMessage("commands please"));
  EXPECT_TRUE(live.OnPageMessage("commands"));
  EXPECT_FALSE(live.collector().hears_commands());  // the bus's thread subscribes, not the page's
  live.TakePageRequests();
  EXPECT_TRUE(live.collector().hears_commands());
  setup.commands_on_request = false;  // dream run --view: from the start
  EXPECT_TRUE(LiveView(bus, server, setup).collector().hears_commands());
}

TEST_F(CommandArrowsTest, ANewRunStartsWithoutCommands) {
  Step(4, 0);
  Send("DREAM_CMD_0", Command(4, 0, 0, 0.1, 0.0));
  lcm::Publish(bus_, "DREAM_STATUS", [] {
    run_status_t finished{};
    finished.run_id = 4;
    finished.state = run_status_t::FINISHED;
    return finished;
  }());
  Step(6, 0);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.run_id, 6);
  EXPECT_TRUE(frame_.command_v_mps.empty());
  EXPECT_FALSE(nlohmann::json::parse(FrameJson(frame_)).contains("cv"));
}

TEST(ReplayCommandsTest, EachFrameHasTheCommandsAnsweringItsStep) {
  TempFolder folder;
  SyntheticRunLog log = SyntheticRunLog::TwoRobots(folder / "run.lcmlog", 3);
  log.MessageOn("DREAM_CMD_0", Command(0, 2, 0, 0.12, -0.5));
  log.MessageOn("DREAM_CMD_1", Command(0, 2, 1, 0.05, 0.25));
  log.MessageOn("DREAM_CMD_1", Command(0, 3, 1, 0.07, 0.0));
  const run_log::RunLog run = run_log::RunLog::Read(log.Write());
  ASSERT_EQ(run.commands().size(), 3u) << "the synthetic log's run id";
  const nlohmann::json replay = nlohmann::json::parse(RunReplayJson(run, ViewSetup()));
  ASSERT_EQ(replay["commands"].size(), 4u);
  EXPECT_TRUE(replay["commands"][0].is_null());  // no command answers step 0
  EXPECT_EQ(replay["commands"][2], nlohmann::json::parse("[0.12, -0.5, 0.05, 0.25]"));
  EXPECT_TRUE(replay["commands"][3][0].is_null());  // robot 0 said nothing at step 3
  EXPECT_EQ(replay["commands"][3][2], 0.07);
}

}  // namespace
}  // namespace dream::view
