#include "dream/node/sim_node.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>

#include "dream/applied_commands_t.hpp"
#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/log_reader.h"
#include "dream/node/run_recorder.h"
#include "dream/node/progress_reporter.h"
#include "dream/robot_fault_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/velocity_command_t.hpp"
#include "quiet_bus.h"
#include "scripted_agent.h"

namespace dream::node {
namespace {

using testing::ScriptedAgent;

/// Three robots in a row, far apart, facing +x.
std::vector<world::Pose2> ThreeRobots() { return {{-1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}; }

config::SimNodeOptions FastOptions(int64_t max_steps) {
  config::SimNodeOptions options;
  options.max_steps = max_steps;
  options.stop_when_done = false;
  options.agent_timeout_s = 0.05;
  options.start_timeout_s = 0.5;
  options.progress_interval_s = 0.0;
  return options;
}

/// Every robot drives forward at 0.1 m/s.
ScriptedAgent::Decide Forward(double v = 0.1) {
  return [v](const robot_poses_t&, velocity_command_t* command) {
    command->v = v;
    return true;
  };
}

class SimNodeTest : public ::testing::Test {
 protected:
  SimNodeTest() : bus_("memq://"), world_(world::WorldParams{}, ThreeRobots()) {}

  void AddAgent(int robot_id, ScriptedAgent::Decide decide, int64_t agent_id = 0) {
    agents_.push_back(
        std::make_unique<ScriptedAgent>(bus_, robot_id, agent_id == 0 ? 100 + robot_id : agent_id, std::move(decide)));
  }

  RunOutcome Run(config::SimNodeOptions options) {
    SimNode node(quiet_bus_, world_, nullptr, options);
    node.set_clock(quiet_bus_.clock());
    std::atomic<bool> stop{false};
    return node.Run(stop);
  }

  /// The lost robots of every DREAM_STATUS the world sends from now on.
  const std::vector<std::vector<int32_t>>& RecordLostRobotsPerStep() {
    subscriptions_.push_back(lcm::Subscribe<run_status_t>(
        bus_, lcm::kStatusChannel,
        [this](const std::string&, const run_status_t& status) { lost_per_step_.push_back(status.lost_robot_ids); },
        bad_status_));
    return lost_per_step_;
  }

  lcm::LcmBus bus_;
  // The node's view of bus_: time passes only while it waits on a quiet bus,
  // so an answering agent is never late however loaded the machine (with
  // the wall clock, a 0.05 s agent timeout once marked answering agents lost).
  testing::QuietBus quiet_bus_{bus_};
  world::UnicycleWorld world_;
  std::vector<std::unique_ptr<ScriptedAgent>> agents_;
  std::vector<std::vector<int32_t>> lost_per_step_;
  lcm::BadMessageLog bad_status_;
  std::vector<lcm::Subscription> subscriptions_;  // last: ends before what the handlers use
};

TEST_F(SimNodeTest, LockstepRunsEveryStepWithTheAgentsCommands) {
  for (int id = 0; id < 3; ++id) AddAgent(id, Forward());
  const RunOutcome outcome = Run(FastOptions(30));
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_EQ(outcome.steps, 30);
  EXPECT_EQ(world_.step(), 30);
  // 30 steps of 0.033 s at 0.1 m/s straight ahead.
  EXPECT_NEAR(world_.poses()[0].x_m, -1.0 + 30 * 0.033 * 0.1, 1e-12);
  EXPECT_TRUE(outcome.robots_ever_lost.empty());
  EXPECT_EQ(outcome.rejected_commands, 0);
}

TEST_F(SimNodeTest, RunEndsWhenEveryRobotReportsDone) {
  for (int id = 0; id < 3; ++id) {
    AddAgent(id, [](const robot_poses_t& poses, velocity_command_t* command) {
      command->done = poses.step >= 12;
      return true;
    });
  }
  config::SimNodeOptions options = FastOptions(1000);
  options.stop_when_done = true;
  const RunOutcome outcome = Run(options);
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_EQ(outcome.steps, 13);  // the answer to step 12 says done; the world takes that step and stops
  EXPECT_EQ(outcome.robots_done.size(), 3u);
}

TEST_F(SimNodeTest, NonFiniteAndAbsurdCommandsAreRejectedAndTheRobotHoldsStill) {
  AddAgent(0, [](const robot_poses_t& poses, velocity_command_t* command) {
    command->v = poses.step == 5 ? std::nan("") : poses.step == 6 ? 50.0 : 0.1;
    command->w = poses.step == 7 ? INFINITY : 0.0;
    return true;
  });
  AddAgent(1, Forward());
  AddAgent(2, Forward());
  const RunOutcome outcome = Run(FastOptions(10));
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_EQ(outcome.rejected_commands, 3);
  // Robot 0 moved on 7 of 10 steps.
  EXPECT_NEAR(world_.poses()[0].x_m, -1.0 + 7 * 0.033 * 0.1, 1e-12);
  EXPECT_EQ(outcome.bad_messages.at("DREAM_CMD_0"), 3);
  // What the first refusal was and at which step, for the verdict's reason.
  ASSERT_EQ(outcome.bad_message_first.count("DREAM_CMD_0"), 1u);
  EXPECT_EQ(outcome.bad_message_first.at("DREAM_CMD_0").rfind("step 5: rejected command: ", 0), 0u)
      << outcome.bad_message_first.at("DREAM_CMD_0");
}

TEST_F(SimNodeTest, CommandsForUnknownRobotsAndGarbageAreCountedNotFatal) {
  for (int id = 0; id < 3; ++id) AddAgent(id, Forward());
  AddAgent(7, Forward());  // this run has robots 0..2 only
  const lcm::Subscription garbage_sender =
      bus_.Subscribe(lcm::kPosesChannel, [this](const std::string&, const void*, int) {
        const char garbage[] = "\x01\x02not a command";
        bus_.Publish("DREAM_CMD_1", garbage, sizeof(garbage));
      });
  const RunOutcome outcome = Run(FastOptions(10));
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_EQ(outcome.steps, 10);
  // One bad message of each kind per step; those sent after the world took
  // its last step are never read, hence not all 11.
  EXPECT_GE(outcome.bad_messages.at("DREAM_CMD_7"), 9);
  EXPECT_GE(outcome.bad_messages.at("DREAM_CMD_1"), 9);
  EXPECT_GE(outcome.rejected_commands, 9);
}

TEST_F(SimNodeTest, SecondAgentForARobotIsRefusedAndTheFirstKeepsIt) {
  AddAgent(0, Forward(0.1), /*agent_id=*/1);
  AddAgent(0, Forward(-0.1), /*agent_id=*/2);
  AddAgent(1, Forward());
  AddAgent(2, Forward());
  const RunOutcome outcome = Run(FastOptions(10));
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_GE(outcome.rejected_commands, 10);
  EXPECT_NEAR(world_.poses()[0].x_m, -1.0 + 10 * 0.033 * 0.1, 1e-12);
}

TEST_F(SimNodeTest, EveryWorldMessageCarriesTheRunsIdAndCommandsOfAnotherRunAreRefused) {
  std::set<int64_t> run_ids;
  AddAgent(0, [&run_ids](const robot_poses_t& poses, velocity_command_t* command) {
    run_ids.insert(poses.run_id);
    command->v = 0.1;
    return true;
  });
  // Robot 1's agent answers a world that is not this one: it never drives robot 1.
  AddAgent(1, [](const robot_poses_t&, velocity_command_t* command) {
    command->run_id = 0x5ec0d;
    command->v = 0.2;
    return true;
  });
  AddAgent(2, Forward());
  config::SimNodeOptions options = FastOptions(10);
  options.start_timeout_s = 0.2;
  const RunOutcome outcome = Run(options);
  EXPECT_EQ(outcome.end, RunOutcome::End::kStartTimeout);
  ASSERT_EQ(run_ids.size(), 1U);
  EXPECT_EQ(*run_ids.begin(), outcome.run_id);
  EXPECT_NE(outcome.run_id, 0);
  EXPECT_GE(outcome.rejected_commands, 1);
  EXPECT_EQ(outcome.other_worlds, std::set<int64_t>{0x5ec0d});
}

TEST_F(SimNodeTest, ASecondWorldsStatusOnTheBusIsReported) {
  AddAgent(0, [this](const robot_poses_t& poses, velocity_command_t* command) {
    if (poses.step == 2) {
      run_status_t other{};
      other.run_id = 0x0e15e;
      other.state = run_status_t::RUNNING;
      other.detail = "another world";
      lcm::Publish(bus_, lcm::kStatusChannel, other);
    }
    command->v = 0.1;
    return true;
  });
  AddAgent(1, Forward());
  AddAgent(2, Forward());
  const RunOutcome outcome = Run(FastOptions(5));
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_EQ(outcome.other_worlds, std::set<int64_t>{0x0e15e});
}

TEST_F(SimNodeTest, TwoDifferentCommandsForOneRobotAndStepAreAConflictTheFirstIsAppliedAndLogged) {
  // Agent 100 drives robot 0; at step 3 a copy of its agent id (as a forger
  // reading the bus would send) commands robot 0 backwards for the same step.
  AddAgent(0, [this](const robot_poses_t& poses, velocity_command_t* command) {
    command->v = 0.1;
    if (poses.step == 3) {
      velocity_command_t forged = *command;
      forged.v = -0.2;
      lcm::Publish(bus_, lcm::kCommandChannelPrefix + std::string("0"), *command);
      lcm::Publish(bus_, lcm::kCommandChannelPrefix + std::string("0"), forged);
      lcm::Publish(bus_, lcm::kCommandChannelPrefix + std::string("0"), *command);  // a resend: not a conflict
      return false;
    }
    return true;
  });
  AddAgent(1, Forward());
  AddAgent(2, Forward());
  const std::string log_path = ::testing::TempDir() + "/conflict_" + std::to_string(::getpid()) + ".lcmlog";
  RunOutcome outcome;
  {
    RunRecorder recorder(log_path);
    SimNode node(quiet_bus_, world_, &recorder, FastOptions(6));
    node.set_clock(quiet_bus_.clock());
    std::atomic<bool> stop{false};
    outcome = node.Run(stop);
    recorder.Close();
  }
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_EQ(outcome.command_conflicts, 1);
  EXPECT_EQ(outcome.rejected_commands, 1);
  EXPECT_NEAR(world_.poses()[0].x_m, -1.0 + 6 * 0.033 * 0.1, 1e-12);  // the first command drove it
  std::vector<applied_commands_t> applied;
  for (const lcm::LogRecord& record : lcm::LogReader::ReadAll(log_path)) {
    if (record.channel != lcm::kAppliedChannel) continue;
    applied_commands_t message;
    ASSERT_TRUE(lcm::Decode(record.data.data(), static_cast<int>(record.data.size()), &message));
    applied.push_back(message);
  }
  ASSERT_EQ(applied.size(), 6U);  // one per step taken
  EXPECT_EQ(applied[3].step, 3);
  EXPECT_EQ(applied[3].run_id, outcome.run_id);
  EXPECT_EQ(applied[3].applied_agent_id, (std::vector<int64_t>{100, 101, 102}));
  EXPECT_DOUBLE_EQ(applied[3].commanded_v[0], 0.1);
  EXPECT_EQ(applied[3].conflicts, (std::vector<int32_t>{1, 0, 0}));
  EXPECT_EQ(applied[2].conflicts, (std::vector<int32_t>{0, 0, 0}));
}

TEST_F(SimNodeTest, SilentAgentIsMarkedLostItsRobotStopsAndItRejoins) {
  AddAgent(0, Forward());
  AddAgent(1, [](const robot_poses_t& poses, velocity_command_t* command) {
    command->v = 0.1;
    return poses.step < 5 || poses.step >= 8;  // silent on steps 5, 6, 7
  });
  AddAgent(2, Forward());
  const std::vector<std::vector<int32_t>>& lost_per_step = RecordLostRobotsPerStep();
  const RunOutcome outcome = Run(FastOptions(20));
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_EQ(outcome.robots_ever_lost, std::set<int>{1});
  // Robot 1 stood still on the three silent steps.
  EXPECT_NEAR(world_.poses()[1].x_m, 17 * 0.033 * 0.1, 1e-12);
  bool saw_lost = false;
  for (const auto& lost : lost_per_step) saw_lost = saw_lost || lost == std::vector<int32_t>{1};
  EXPECT_TRUE(saw_lost);
  EXPECT_TRUE(lost_per_step.back().empty());  // back by the end
}

// With every robot lost nothing holds a lockstep world back; it still reads
// the bus each step, so the agents are heard again when they speak.
TEST_F(SimNodeTest, WhenEveryRobotIsLostTheAgentsStillRejoin) {
  for (int id = 0; id < 3; ++id) {
    AddAgent(id, [](const robot_poses_t& poses, velocity_command_t* command) {
      command->v = 0.1;
      return poses.step < 5 || poses.step >= 8;  // all silent on steps 5, 6, 7
    });
  }
  const std::vector<std::vector<int32_t>>& lost_per_step = RecordLostRobotsPerStep();
  const RunOutcome outcome = Run(FastOptions(40));
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_EQ(outcome.robots_ever_lost, (std::set<int>{0, 1, 2}));
  ASSERT_FALSE(lost_per_step.empty());
  EXPECT_TRUE(lost_per_step.back().empty()) << "the robots never rejoined";
  EXPECT_GT(world_.poses()[0].x_m, -1.0 + 30 * 0.033 * 0.1);  // driving again after the silence
  EXPECT_EQ(outcome.rejected_commands, 0);
}

robot_fault_t Fault(int robot_id, int64_t agent_id, const std::string& detail, int64_t run_id) {
  robot_fault_t fault{};
  fault.run_id = run_id;
  fault.robot_id = robot_id;
  fault.agent_id = agent_id;
  fault.detail = detail;
  return fault;
}

TEST_F(SimNodeTest, FaultFromTheRobotsAgentLosesThatRobotAtOnceAndTheRunGoesOn) {
  AddAgent(0, Forward());
  // Robot 1's agent drives until step 5, then says its controller failed and falls silent.
  AddAgent(1, [this](const robot_poses_t& poses, velocity_command_t* command) {
    command->v = 0.1;
    if (poses.step < 5) return true;
    if (poses.step == 5)
      lcm::Publish(bus_, "DREAM_FAULT_1", Fault(1, 101, "my_robot.py:12: in update: KeyError: 'x'", poses.run_id));
    return false;
  });
  AddAgent(2, Forward());
  config::SimNodeOptions options = FastOptions(20);
  options.agent_timeout_s = 30.0;  // a silent robot alone would stall the run this long
  const RunOutcome outcome = Run(options);
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_EQ(outcome.steps, 20);
  EXPECT_EQ(outcome.robots_ever_lost, std::set<int>{1});
  ASSERT_EQ(outcome.robot_faults.size(), 1U);
  EXPECT_EQ(outcome.robot_faults.at(1), "step 5: my_robot.py:12: in update: KeyError: 'x'");
  EXPECT_NEAR(world_.poses()[1].x_m, 5 * 0.033 * 0.1, 1e-12);  // stopped at step 5
  EXPECT_NEAR(world_.poses()[0].x_m, -1.0 + 20 * 0.033 * 0.1, 1e-12);
}

TEST_F(SimNodeTest, ForgedFaultsAreCountedAndChangeNothing) {
  AddAgent(0, [this](const robot_poses_t& poses, velocity_command_t* command) {
    command->v = 0.1;
    if (poses.step == 3) {
      lcm::Publish(bus_, "DREAM_FAULT_1", Fault(1, 999, "not robot 1's agent", poses.run_id));
      lcm::Publish(bus_, "DREAM_FAULT_2", Fault(1, 101, "channel and payload disagree", poses.run_id));
      lcm::Publish(bus_, "DREAM_FAULT_7", Fault(7, 107, "no robot 7 in this run", poses.run_id));
      lcm::Publish(bus_, "DREAM_FAULT_1", Fault(1, 101, "robot 1's agent, but of another run", poses.run_id + 1));
      const uint8_t garbage[] = {1, 2, 3};
      bus_.Publish("DREAM_FAULT_0", garbage, sizeof(garbage));
    }
    return true;
  });
  AddAgent(1, Forward());
  AddAgent(2, Forward());
  const RunOutcome outcome = Run(FastOptions(10));
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_TRUE(outcome.robot_faults.empty());
  EXPECT_TRUE(outcome.robots_ever_lost.empty());
  EXPECT_EQ(outcome.bad_messages.at("DREAM_FAULT_1"), 2);
  EXPECT_EQ(outcome.bad_messages.at("DREAM_FAULT_2"), 1);
  EXPECT_EQ(outcome.bad_messages.at("DREAM_FAULT_7"), 1);
  EXPECT_EQ(outcome.bad_messages.at("DREAM_FAULT_0"), 1);
  EXPECT_NEAR(world_.poses()[1].x_m, 10 * 0.033 * 0.1, 1e-12);
}

TEST_F(SimNodeTest, MissingAgentAtStartEndsTheRunWithAClearReason) {
  AddAgent(0, Forward());
  AddAgent(1, Forward());
  const RunOutcome outcome = Run(FastOptions(10));
  EXPECT_EQ(outcome.end, RunOutcome::End::kStartTimeout);
  EXPECT_NE(outcome.reason.find("robot(s) 2"), std::string::npos) << outcome.reason;
  EXPECT_NE(outcome.reason.find("raise world.start_timeout_s"), std::string::npos) << outcome.reason;
  EXPECT_EQ(outcome.steps, 0);
}

TEST_F(SimNodeTest, CommandForAFutureStepIsRejected) {
  AddAgent(0, [](const robot_poses_t&, velocity_command_t* command) {
    command->step += 5;
    return true;
  });
  AddAgent(1, Forward());
  AddAgent(2, Forward());
  config::SimNodeOptions options = FastOptions(5);
  const RunOutcome outcome = Run(options);
  EXPECT_EQ(outcome.end, RunOutcome::End::kStartTimeout);
  EXPECT_GE(outcome.rejected_commands, 1);
}

TEST_F(SimNodeTest, StopFlagInterruptsTheRun) {
  for (int id = 0; id < 3; ++id) AddAgent(id, Forward());
  SimNode node(quiet_bus_, world_, nullptr, FastOptions(1000000));
  node.set_clock(quiet_bus_.clock());
  std::atomic<bool> stop{false};
  const lcm::Subscription stopper = bus_.Subscribe(lcm::kPosesChannel, [&](const std::string&, const void*, int) {
    if (world_.step() == 50) stop = true;
  });
  const RunOutcome outcome = node.Run(stop);
  EXPECT_EQ(outcome.end, RunOutcome::End::kInterrupted);
  EXPECT_EQ(outcome.steps, 50);
}

TEST_F(SimNodeTest, RealTimeModeUsesTheLatestCommands) {
  for (int id = 0; id < 3; ++id) AddAgent(id, Forward());
  config::SimNodeOptions options = FastOptions(6);
  options.mode = config::WorldMode::kRealTime;
  options.agent_timeout_s = 1.0;
  const RunOutcome outcome = Run(options);
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_EQ(outcome.steps, 6);
  EXPECT_NEAR(world_.poses()[2].x_m, 1.0 + 6 * 0.033 * 0.1, 1e-12);
}

// Real time paces by the world's own time step, not the Robotarium's 0.033 s:
// 5 steps of 0.1 s take at least 0.4 s of wall time after step 0 is answered.
TEST_F(SimNodeTest, RealTimeStepsAtTheWorldsTimeStep) {
  world::WorldParams slow;
  slow.time_step_s = 0.1;
  world::UnicycleWorld world(slow, ThreeRobots());
  for (int id = 0; id < 3; ++id) AddAgent(id, Forward());
  config::SimNodeOptions options = FastOptions(5);
  options.mode = config::WorldMode::kRealTime;
  options.agent_timeout_s = 1.0;
  SimNode node(bus_, world, nullptr, options);
  std::atomic<bool> stop{false};
  const auto start = std::chrono::steady_clock::now();
  const RunOutcome outcome = node.Run(stop);
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_EQ(outcome.steps, 5);
  EXPECT_GE(wall_s, 0.4);
}

// As on the lab (and UnicycleWorld's command timeout): in real time a robot
// whose agent goes quiet keeps its last command for 0.5 s of simulated time,
// 15 steps, then holds still; it is not marked lost before agent_timeout_s.
TEST_F(SimNodeTest, RealTimeRobotOfASilentAgentKeepsItsLastCommandFor15StepsThenStops) {
  constexpr int64_t kLastAnsweredStep = 5;
  int64_t last_command_world_step = -1;  // when robot 0's last command reached the world
  std::map<int64_t, std::vector<double>> x_by_step;
  lcm::BadMessageLog bad;
  const lcm::Subscription commands = lcm::Subscribe<velocity_command_t>(
      bus_, lcm::CommandChannel(0),
      [&](const std::string&, const velocity_command_t&) { last_command_world_step = world_.step(); }, bad);
  const lcm::Subscription poses = lcm::Subscribe<robot_poses_t>(
      bus_, lcm::kPosesChannel,
      [&](const std::string&, const robot_poses_t& message) { x_by_step[message.step] = message.x; }, bad);
  AddAgent(0, [](const robot_poses_t& seen, velocity_command_t* command) {
    command->v = 0.1;
    return seen.step <= kLastAnsweredStep;
  });
  AddAgent(1, Forward());
  AddAgent(2, Forward());
  config::SimNodeOptions options = FastOptions(28);  // 28 ticks of 33 ms: under a second
  options.mode = config::WorldMode::kRealTime;
  options.agent_timeout_s = 30.0;
  options.start_timeout_s = 5.0;
  const RunOutcome outcome = Run(options);
  ASSERT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_TRUE(outcome.robots_ever_lost.empty());
  // In real time the answer to step 5 is applied at step 5, or a tick later
  // on a busy machine; the hold is counted from where it actually landed.
  ASSERT_GE(last_command_world_step, kLastAnsweredStep);
  ASSERT_LE(last_command_world_step, kLastAnsweredStep + 2);
  const int64_t last_moving_step = last_command_world_step + 15;
  // The final poses (step 28) go out as the run ends, after these handlers ran.
  for (int64_t step = 1; step < 28; ++step) {
    ASSERT_EQ(x_by_step.count(step), 1u) << "no poses for step " << step;
    ASSERT_EQ(x_by_step.count(step - 1), 1u) << "no poses for step " << step - 1;
    // Poses of `step` are the result of the world step taken at step - 1.
    const double dx_m = x_by_step[step][0] - x_by_step[step - 1][0];
    if (step - 1 <= last_moving_step) {
      EXPECT_NEAR(dx_m, 0.033 * 0.1, 1e-12) << "robot 0 should still drive in step " << step - 1;
    } else {
      EXPECT_EQ(dx_m, 0.0) << "robot 0 should hold still in step " << step - 1;
    }
    // Robot 1's agent never went quiet: it drives all along.
    EXPECT_NEAR(x_by_step[step][1] - x_by_step[step - 1][1], 0.033 * 0.1, 1e-12);
  }
}

TEST_F(SimNodeTest, ProgressReporterFollowsTheStepsAndIsFinishedAtTheEnd) {
  for (int id = 0; id < 3; ++id) AddAgent(id, Forward());
  std::ostringstream out;
  ProgressReporter::Options progress_options;
  progress_options.interactive = true;
  progress_options.show_after_s = 0.0;       // draw from the first step
  progress_options.redraw_interval_s = 0.0;  // and at every one
  ProgressReporter progress(out, progress_options);
  SimNode node(quiet_bus_, world_, nullptr, FastOptions(40));
  node.set_clock(quiet_bus_.clock());
  node.set_progress_reporter(&progress);
  std::atomic<bool> stop{false};
  const RunOutcome outcome = node.Run(stop);
  ASSERT_EQ(outcome.steps, 40);
  const std::string text = out.str();
  EXPECT_NE(text.find("\rstep 1/40 ["), std::string::npos) << text;
  const std::string last = text.substr(text.rfind('\r') + 1);
  EXPECT_EQ(last.rfind("step 40/40 [", 0), 0u) << last;
  EXPECT_EQ(text.back(), '\n');
  EXPECT_FALSE(progress.line_on_screen());
}

TEST(SimNodeOptionsTest, InvalidOptionsNameTheField) {
  config::SimNodeOptions options;
  options.agent_timeout_s = 0.0;
  std::string error;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("agent_timeout_s"), std::string::npos) << error;
  options = config::SimNodeOptions{};
  options.max_steps = 0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("max_steps"), std::string::npos) << error;
  EXPECT_THROW(config::ParseWorldMode("fast"), std::invalid_argument);
  EXPECT_EQ(config::ParseWorldMode("realtime"), config::WorldMode::kRealTime);
}

TEST(SimNodeOptionsTest, PaceIsZeroOrAFactorUpToTheLimit) {
  config::SimNodeOptions options;
  std::string error;
  for (const double pace : {0.0, 0.25, 1.0, config::SimNodeOptions::kMaxPace}) {
    options.pace = pace;
    EXPECT_TRUE(options.IsValid(&error)) << pace << ": " << error;
  }
  for (const double pace : {-1.0, config::SimNodeOptions::kMaxPace * 2, std::nan(""), HUGE_VAL}) {
    options.pace = pace;
    EXPECT_FALSE(options.IsValid(&error)) << pace;
    EXPECT_NE(error.find("pace"), std::string::npos) << error;
  }
}

}  // namespace
}  // namespace dream::node
