#include "dream/node/busy_intake.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/log_reader.h"
#include "dream/node/run_recorder.h"
#include "dream/node/sim_node.h"
#include "dream/robot_busy_t.hpp"
#include "quiet_bus.h"
#include "scripted_agent.h"

// A robot whose agent host says "busy" (DREAM_BUSY_<id>) while a long call
// holds its answer up: a lockstep world waits for it, on the world's clock
// (here the quiet bus's, which moves only while the world waits), as long as
// the notes keep coming, and no longer than BusyIntake::kMaxHoldFactor.
namespace dream::node {
namespace {

using testing::ScriptedAgent;

constexpr int64_t kStuckStep = 3;

robot_busy_t BusyNote(const robot_poses_t& poses, int robot_id, int64_t agent_id) {
  robot_busy_t busy{};
  busy.utime = poses.utime;
  busy.step = poses.step;
  busy.run_id = poses.run_id;
  busy.robot_id = robot_id;
  busy.agent_id = agent_id;
  busy.call_robot_id = robot_id;
  busy.call_s = 0.5;
  return busy;
}

class BusyIntakeTest : public ::testing::Test {
 protected:
  BusyIntakeTest() : bus_("memq://"), world_(world::WorldParams{}, {{-1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}}) {}
  ~BusyIntakeTest() override { std::remove(log_path_.c_str()); }

  /// Robot 0 always answers; robot 1's agent (id 101) hears step 3's poses
  /// (the world resends them every 0.2 s of its clock) and, the n-th time,
  /// does what `at_stuck_step(n, poses)` says: true answers the step.
  void AddAgents(std::function<bool(int heard, const robot_poses_t& poses)> at_stuck_step) {
    agents_.push_back(std::make_unique<ScriptedAgent>(bus_, 0, 100, [](const robot_poses_t&, velocity_command_t* c) {
      c->v = 0.1;
      return true;
    }));
    agents_.push_back(std::make_unique<ScriptedAgent>(
        bus_, 1, 101, [this, at_stuck_step](const robot_poses_t& poses, velocity_command_t* command) {
          command->v = 0.1;
          if (poses.step != kStuckStep) return true;
          return at_stuck_step(++stuck_step_heard_, poses);
        }));
  }

  void SayBusy(const robot_poses_t& poses, int64_t agent_id = 101, int robot_id = 1) {
    lcm::Publish(bus_, lcm::BusyChannel(robot_id), BusyNote(poses, robot_id, agent_id));
  }

  static config::SimNodeOptions Options() {
    config::SimNodeOptions options;
    options.max_steps = 8;
    options.stop_when_done = false;
    options.agent_timeout_s = 1.0;
    options.resend_interval_s = 0.2;
    options.start_timeout_s = 5.0;
    options.progress_interval_s = 0.0;
    return options;
  }

  RunOutcome Run() {
    RunRecorder recorder(log_path_);
    SimNode node(quiet_bus_, world_, &recorder, Options());
    node.set_clock(quiet_bus_.clock());
    std::atomic<bool> stop{false};
    const RunOutcome outcome = node.Run(stop);
    recorder.Close();
    return outcome;
  }

  int LoggedOn(const std::string& channel) const {
    int count = 0;
    for (const lcm::LogRecord& record : lcm::LogReader::ReadAll(log_path_)) count += record.channel == channel;
    return count;
  }

  lcm::LcmBus bus_;
  testing::QuietBus quiet_bus_{bus_};
  world::UnicycleWorld world_;
  // One file per process: ctest runs each of these tests in a process of its own, in parallel.
  std::string log_path_ = ::testing::TempDir() + "/busy_intake_" + std::to_string(::getpid()) + ".lcmlog";
  int stuck_step_heard_ = 0;
  std::vector<std::unique_ptr<ScriptedAgent>> agents_;
};

TEST_F(BusyIntakeTest, ARobotWhoseHostSaysBusyIsWaitedForPastTheTimeout) {
  // Busy at every resend (0.2 s apart) for 15 resends (3 s, three times the
  // agent timeout), then the answer.
  AddAgents([this](int heard, const robot_poses_t& poses) {
    if (heard <= 15) SayBusy(poses);
    return heard > 15;
  });
  const RunOutcome outcome = Run();
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_EQ(outcome.steps, 8);
  EXPECT_TRUE(outcome.robots_ever_lost.empty()) << "robot 1 was called silent while its host said busy";
  EXPECT_GT(stuck_step_heard_, 15);
  EXPECT_TRUE(outcome.bad_messages.empty());
  EXPECT_EQ(LoggedOn("DREAM_BUSY_1"), 1) << "the first note of a robot and step is the log's";
}

TEST_F(BusyIntakeTest, WhenTheNotesStopTheRobotIsLostATimeoutAfterTheLast) {
  // One note at the first hearing, then nothing until the 12th resend.
  AddAgents([this](int heard, const robot_poses_t& poses) {
    if (heard == 1) SayBusy(poses);
    return heard >= 12;
  });
  const RunOutcome outcome = Run();
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_EQ(outcome.robots_ever_lost, std::set<int>{1});
  // Lost a timeout after the note, so the world moved on before the 12th
  // resend (about the 6th): robot 1 missed step 3 and later ones answered.
  EXPECT_LT(stuck_step_heard_, 12);
}

TEST_F(BusyIntakeTest, AHostThatSaysBusyForEverIsNotBelievedPastTheCap) {
  AddAgents([this](int, const robot_poses_t& poses) {
    SayBusy(poses);
    return false;
  });
  const RunOutcome outcome = Run();
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished);
  EXPECT_EQ(outcome.robots_ever_lost, std::set<int>{1});
  // Held about kMaxHoldFactor x 1 s at 0.2 s a resend: far past the plain
  // timeout's 5 resends, and not for ever.
  const double held_s = stuck_step_heard_ * Options().resend_interval_s;
  EXPECT_GT(held_s, BusyIntake::kMaxHoldFactor * Options().agent_timeout_s - 1.0);
  EXPECT_LT(held_s, BusyIntake::kMaxHoldFactor * Options().agent_timeout_s + 1.0);
}

TEST_F(BusyIntakeTest, NotesFromAnotherAgentAnotherRunOrAFutureStepAreRefused) {
  AddAgents([this](int heard, const robot_poses_t& poses) {
    if (heard == 1) {
      SayBusy(poses, 999);  // not robot 1's agent
      robot_poses_t other_run = poses;
      other_run.run_id = poses.run_id + 1;
      SayBusy(other_run);
      robot_poses_t future = poses;
      future.step = poses.step + 5;
      SayBusy(future);
      SayBusy(poses, 101, 7);  // a robot this run does not have
      robot_busy_t not_a_time = BusyNote(poses, 1, 101);
      not_a_time.call_s = std::numeric_limits<double>::quiet_NaN();
      lcm::Publish(bus_, lcm::BusyChannel(1), not_a_time);
    }
    return false;
  });
  const RunOutcome outcome = Run();
  EXPECT_EQ(outcome.robots_ever_lost, std::set<int>{1}) << "a refused note held the robot";
  EXPECT_EQ(outcome.bad_messages.at("DREAM_BUSY_1"), 4);
  EXPECT_EQ(outcome.bad_messages.at("DREAM_BUSY_7"), 1);
  EXPECT_EQ(LoggedOn("DREAM_BUSY_1"), 0);
  EXPECT_LT(stuck_step_heard_, 10) << "held past the timeout";
}

TEST_F(BusyIntakeTest, AHostStillSettingARobotUpHoldsTheStart) {
  // Robot 1's host is busy through step 0's first 30 sends (6 s: past the
  // start's 5 s), saying so at each, then answers: the run starts and ends.
  int first_step_heard = 0;
  agents_.push_back(
      std::make_unique<ScriptedAgent>(bus_, 0, 100, [](const robot_poses_t&, velocity_command_t*) { return true; }));
  agents_.push_back(std::make_unique<ScriptedAgent>(
      bus_, 1, 101, [this, &first_step_heard](const robot_poses_t& poses, velocity_command_t*) {
        if (poses.step > 0 || ++first_step_heard > 30) return true;
        SayBusy(poses);
        return false;
      }));
  const RunOutcome outcome = Run();
  EXPECT_EQ(outcome.end, RunOutcome::End::kFinished) << outcome.reason;
  EXPECT_EQ(outcome.steps, 8);
  EXPECT_GT(first_step_heard * Options().resend_interval_s, Options().start_timeout_s);
  EXPECT_EQ(LoggedOn("DREAM_BUSY_1"), 0) << "a start's notes are routine, not the log's";
}

TEST_F(BusyIntakeTest, WithoutNotesTheStartEndsAtItsTimeout) {
  agents_.push_back(
      std::make_unique<ScriptedAgent>(bus_, 0, 100, [](const robot_poses_t&, velocity_command_t*) { return true; }));
  const RunOutcome outcome = Run();
  EXPECT_EQ(outcome.end, RunOutcome::End::kStartTimeout);
}

}  // namespace
}  // namespace dream::node
