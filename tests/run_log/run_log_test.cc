#include "dream/run_log/run_log.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "dream/radio_message_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/run_verdict_t.hpp"
#include "synthetic_run_log.h"
#include "temp_folder.h"

namespace dream::run_log {
namespace {

using dream::testing::Box;
using dream::testing::SyntheticRunLog;
using dream::testing::TempFolder;

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// The error RunLog::Read throws on `path`, or "" when it reads.
std::string ReadError(const std::string& path) {
  try {
    RunLog::Read(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(RunLogTest, ReadsPosesObstaclesByStepAndRadioSends) {
  TempFolder dir;
  SyntheticRunLog log(dir / "run.lcmlog");
  // The world may publish a step's obstacles before or after its poses.
  log.Poses(0, {{0, 0, 0}, {0.3, 0.4, 0}})
      .Obstacles(0, {Box(0, 1.0, 0.0, 0.2, 0.2)})
      .Obstacles(1, {Box(0, 1.1, 0.0, 0.2, 0.2)})
      .Poses(1, {{0, 0, 0}, {0.6, 0.8, 0}})
      .Radio(1, 1)
      .Other("SOMETHING_ELSE")
      .Radio(0, 0)
      .Poses(2, {{0, 0, 0}, {0.0, 0.2, 0}});
  const RunLog run = RunLog::Read(log.Write());

  EXPECT_EQ(run.path(), dir / "run.lcmlog");
  ASSERT_EQ(run.poses().size(), 3u);
  EXPECT_EQ(run.num_robots(), 2);
  EXPECT_EQ(run.first_step(), 0);
  EXPECT_EQ(run.last_step(), 2);
  EXPECT_DOUBLE_EQ(run.poses()[1].y[1], 0.8);
  ASSERT_EQ(run.obstacles().size(), 2u);
  EXPECT_DOUBLE_EQ(run.obstacles_at(0).obstacles.at(0).center_x, 1.0);
  EXPECT_DOUBLE_EQ(run.obstacles_at(1).obstacles.at(0).center_x, 1.1);
  EXPECT_DOUBLE_EQ(run.obstacles_at(2).obstacles.at(0).center_x, 1.1);  // no message for step 2: the last one holds
  ASSERT_EQ(run.radio_sends().size(), 2u);
  EXPECT_EQ(run.radio_sends()[0].step, 0);  // sorted by step
  EXPECT_EQ(run.radio_sends()[0].sender_id, 0);
  EXPECT_EQ(run.radio_sends()[1].sender_id, 1);
  EXPECT_FALSE(run.last_status());
  EXPECT_EQ(run.Flaw(true), std::nullopt);  // a whole run log
}

TEST(RunLogTest, PoseIndexAtStepFindsTheLastPoseNotAfterIt) {
  TempFolder dir;
  SyntheticRunLog log(dir / "lab.lcmlog");
  log.Poses(10, {{0, 0, 0}}).Poses(12, {{0, 0, 0}}).Poses(13, {{0, 0, 0}});  // a lab log may skip steps
  const RunLog run = RunLog::Read(log.Write());
  EXPECT_EQ(run.PoseIndexAtStep(0), 0u);
  EXPECT_EQ(run.PoseIndexAtStep(11), 0u);
  EXPECT_EQ(run.PoseIndexAtStep(12), 1u);
  EXPECT_EQ(run.PoseIndexAtStep(99), 2u);
  EXPECT_TRUE(run.obstacles().empty());
  EXPECT_TRUE(run.obstacles_at(2).obstacles.empty());
  // Drawn as it is, but not a whole run: steps must go 0, 1, 2, ...
  EXPECT_EQ(run.Flaw(false),
            run.path() + ": DREAM_POSES jumps from step -1 to step 10; a run log has every step once, in order");
}

// The world judges a step's poses before it steps on: never the last ones.
TEST(RunLogTest, ThePosesTheWorldJudgedAreAllButTheLast) {
  TempFolder dir;
  SyntheticRunLog three(dir / "three.lcmlog");
  three.Poses(0, {{0, 0, 0}}).Poses(1, {{0, 0, 0}}).Poses(2, {{0, 0, 0}});
  EXPECT_EQ(RunLog::Read(three.Write()).judged_poses(), 2u);
  SyntheticRunLog none(dir / "none.lcmlog");
  EXPECT_EQ(RunLog::Read(none.Write()).judged_poses(), 0u);
}

TEST(RunLogTest, TheEndIsTheLastStatusWithTheFaultsOfRobotsLostThen) {
  TempFolder dir;
  SyntheticRunLog log(dir / "run.lcmlog");
  log.Poses(0, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}})
      .Status(0, run_status_t::RUNNING, {}, "running")
      .Fault(2, 2, 0, "controller.py:3: in update: ValueError: first")
      .Fault(2, 2, 1, "a second fault of robot 2 is not the reason")
      .Fault(1, 0, 1, "robot_id 0 on DREAM_FAULT_1: not robot 1's")
      .Fault(0, 0, 1, "robot 0 drove on: not lost at the end")
      .Poses(1, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}})
      .Status(1, run_status_t::FINISHED, {1, 2}, "every robot is done");
  const RunLog run = RunLog::Read(log.Write());
  ASSERT_TRUE(run.last_status());
  EXPECT_EQ(run.last_status()->state, run_status_t::FINISHED);
  EXPECT_EQ(run.last_status()->detail, "every robot is done");
  EXPECT_EQ(run.last_status()->step, 1);
  const std::map<int, std::string> faults = {{2, "step 0: controller.py:3: in update: ValueError: first"}};
  EXPECT_EQ(run.robot_faults(), faults);
  EXPECT_EQ(run.Flaw(true), std::nullopt);
}

// Issue 23: a forged DREAM_FAULT of another run, in the log of a run from
// before the world kept refused messages out of it, was quoted by `dream
// export` as the robot's failure.
TEST(RunLogTest, FaultsAndRadioOfAnotherRunOrAnotherRobotAreNoneOfThisRuns) {
  TempFolder dir;
  robot_fault_t forged{};
  forged.step = 0;
  forged.run_id = 77;  // the synthetic run's poses carry run id 0
  forged.robot_id = 1;
  forged.detail = "forged: another run's";
  radio_message_t radio{};
  radio.run_id = 77;
  radio.sender_id = 0;
  SyntheticRunLog log(dir / "run.lcmlog");
  log.Poses(0, {{0, 0, 0}, {1, 0, 0}})
      .MessageOn("DREAM_FAULT_1", forged)
      .MessageOn("DREAM_RADIO_0", radio)
      .Radio(0, 5)  // a sender outside the run's two robots
      .Radio(0, 1)
      .Fault(1, 1, 1, "controller.py:3: in update: ValueError: the real one")
      .Poses(1, {{0, 0, 0}, {1, 0, 0}})
      .Status(1, run_status_t::FINISHED, {1}, "done");
  const RunLog run = RunLog::Read(log.Write());
  const std::map<int, std::string> faults = {{1, "step 1: controller.py:3: in update: ValueError: the real one"}};
  EXPECT_EQ(run.robot_faults(), faults);
  ASSERT_EQ(run.radio_sends().size(), 1u);
  EXPECT_EQ(run.radio_sends()[0].sender_id, 1);
}

// Issue 33: the run's DREAM_VERDICT, appended once summary.json was written: another run's is none of it.
TEST(RunLogTest, TheVerdictIsTheRunsOwnLastOne) {
  TempFolder dir;
  run_verdict_t other{};
  other.run_id = 77;  // the synthetic run's poses carry run id 0
  other.verdict = run_verdict_t::CLEAN;
  run_verdict_t own{};
  own.step = 1;
  own.verdict = run_verdict_t::NOT_READY;
  own.goal_text = "missed (not all at their goals)";
  SyntheticRunLog log(dir / "run.lcmlog");
  log.Poses(0, {{0, 0, 0}, {1, 0, 0}})
      .Poses(1, {{0, 0, 0}, {1, 0, 0}})
      .Status(1, run_status_t::FINISHED, {}, "done")
      .MessageOn("DREAM_VERDICT", own)
      .MessageOn("DREAM_VERDICT", other);
  const RunLog run = RunLog::Read(log.Write());
  ASSERT_TRUE(run.verdict().has_value());
  EXPECT_EQ(run.verdict()->verdict, run_verdict_t::NOT_READY);
  EXPECT_EQ(run.verdict()->goal_text, own.goal_text);
  EXPECT_FALSE(run.Flaw(false).has_value());

  SyntheticRunLog without(dir / "without.lcmlog");
  without.Poses(0, {{0, 0, 0}}).MessageOn("DREAM_VERDICT", other);
  EXPECT_FALSE(RunLog::Read(without.Write()).verdict().has_value());
}

TEST(RunLogTest, ACutLogIsAnErrorNamingTheFileAndByte) {
  TempFolder dir;
  const std::string path = SyntheticRunLog::TwoRobots(dir / "cut.lcmlog", 5).Write();
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 7);
  const std::string error = ReadError(path);
  EXPECT_TRUE(Contains(error, path)) << error;
  EXPECT_TRUE(Contains(error, "at byte ")) << error;
  EXPECT_TRUE(Contains(error, "cut short")) << error;
}

TEST(RunLogTest, AMessageWhoseCountLiesIsLeftOutAndNamedWithItsEventAndByte) {
  TempFolder dir;
  SyntheticRunLog log(dir / "run.lcmlog");
  log.Poses(0, {{0, 0, 0}}).LyingPoses(1, 1 << 28).Poses(1, {{0.1, 0, 0}}).Poses(2, {{0.2, 0, 0}});
  const RunLog run = RunLog::Read(log.Write());
  ASSERT_EQ(run.poses().size(), 3u);  // drawn and measured without the forged message
  EXPECT_EQ(run.last_step(), 2);
  const std::optional<std::string> flaw = run.Flaw(false);
  ASSERT_TRUE(flaw);
  EXPECT_TRUE(Contains(*flaw, run.path() + ": event 1 at byte ")) << *flaw;
  EXPECT_TRUE(Contains(*flaw, "a DREAM_POSES message cannot be decoded; in the message: count 268435456")) << *flaw;
}

TEST(RunLogTest, ForeignTypesOnTheRunsChannelsAreLeftOutAndOtherChannelsIgnored) {
  TempFolder dir;
  run_status_t status{};
  status.detail = "a status where poses belong";
  SyntheticRunLog log(dir / "run.lcmlog");
  log.Poses(0, {{0, 0, 0}})
      .Other("DREAM_CMD_0")              // not read at all
      .Other("DREAM_RADIO_0")            // a radio message that does not decode: no broadcast
      .Other("DREAM_FAULT_0")            // nor a fault
      .Other("DREAM_STATUS")             // a status that does not decode
      .MessageOn("DREAM_POSES", status)  // a foreign type
      .Other("DREAM_OBSTACLES")          // obstacles that do not decode
      .Poses(1, {{0, 0, 0}});
  const RunLog run = RunLog::Read(log.Write());
  EXPECT_EQ(run.poses().size(), 2u);
  EXPECT_TRUE(run.radio_sends().empty());
  EXPECT_TRUE(run.obstacles().empty());
  EXPECT_FALSE(run.last_status());
  // The first flaw in the log: the status (event 4) when it counts, else the foreign poses (event 5).
  const std::optional<std::string> with_status = run.Flaw(true);
  const std::optional<std::string> without = run.Flaw(false);
  ASSERT_TRUE(with_status && without);
  EXPECT_TRUE(Contains(*with_status, ": event 4 at byte ")) << *with_status;
  EXPECT_TRUE(Contains(*with_status, "a DREAM_STATUS message cannot be decoded")) << *with_status;
  EXPECT_TRUE(Contains(*without, ": event 5 at byte ")) << *without;
  EXPECT_TRUE(Contains(*without, "a DREAM_POSES message cannot be decoded")) << *without;
}

TEST(RunLogTest, ARunMustKeepItsRobots) {
  TempFolder dir;
  SyntheticRunLog none(dir / "none.lcmlog");
  none.Poses(0, {});
  EXPECT_EQ(RunLog::Read(none.Write()).Flaw(false), dir / "none.lcmlog" + ": DREAM_POSES at step 0 has no robots");
  SyntheticRunLog changing(dir / "changing.lcmlog");
  changing.Poses(0, {{0, 0, 0}}).Poses(1, {{0, 0, 0}, {1, 0, 0}});
  const RunLog run = RunLog::Read(changing.Write());
  EXPECT_EQ(run.num_robots(), 2);  // the most any step has
  EXPECT_EQ(run.Flaw(false), run.path() + ": DREAM_POSES at step 1 has 2 robots, earlier steps 1");
  // The same step again, changed, is no resend (those are the same message).
  SyntheticRunLog repeated(dir / "repeated.lcmlog");
  repeated.Poses(0, {{0, 0, 0}}).Poses(0, {{0, 0, 1}});
  EXPECT_EQ(RunLog::Read(repeated.Write()).Flaw(false),
            dir / "repeated.lcmlog" +
                ": two different DREAM_POSES for step 0 of one run; a run log has every step once (a resend is "
                "the same message again)");
  SyntheticRunLog backwards(dir / "backwards.lcmlog");
  backwards.Poses(0, {{0, 0, 0}}).Poses(1, {{0, 0, 0}}).Poses(0, {{0, 0, 0}});
  EXPECT_EQ(
      RunLog::Read(backwards.Write()).Flaw(false),
      dir / "backwards.lcmlog" + ": DREAM_POSES jumps from step 1 to step 0; a run log has every step once, in order");
}

TEST(RunLogTest, AnEmptyLogHasNoPosesAndIsNoRun) {
  TempFolder dir;
  const std::string path = dir / "empty.lcmlog";
  std::ofstream(path).close();
  const RunLog run = RunLog::Read(path);
  EXPECT_TRUE(run.poses().empty());
  EXPECT_EQ(run.num_robots(), 0);
  EXPECT_EQ(run.first_step(), -1);
  EXPECT_EQ(run.last_step(), -1);
  EXPECT_EQ(run.Flaw(true), path + ": the log holds no DREAM_POSES messages: it is not a run log");
}

TEST(RunLogTest, AMissingOrForeignFileIsAnErrorNamingIt) {
  TempFolder dir;
  EXPECT_TRUE(Contains(ReadError(dir / "nope.lcmlog"), dir / "nope.lcmlog"));
  const std::string text = dir / "config.yaml";
  std::ofstream(text) << "name: not a log\n";
  const std::string error = ReadError(text);
  EXPECT_TRUE(Contains(error, text)) << error;
  EXPECT_TRUE(Contains(error, "not an LCM log")) << error;
}

// Issue 37 item 8: lcm-logger's recording of a live lockstep run holds the
// world's resends of a step (the same message again while it waits for
// answers); they are that step, once, as in the run's own log.
TEST(RunLogTest, ARecordingsResendsAreTheStepOnce) {
  TempFolder dir;
  SyntheticRunLog log(dir / "recorded.lcmlog");
  log.Status(0, run_status_t::WAITING_FOR_AGENTS, {}, "")
      .Poses(0, {{0, 0, 0}})
      .Poses(0, {{0, 0, 0}})  // resent: an agent was late
      .Poses(0, {{0, 0, 0}})
      .Poses(1, {{0.1, 0, 0}})
      .Poses(1, {{0.1, 0, 0}})
      .Poses(2, {{0.2, 0, 0}})
      .Status(2, run_status_t::FINISHED, {}, "done");
  const RunLog run = RunLog::Read(log.Write());
  EXPECT_FALSE(run.Flaw(true).has_value()) << *run.Flaw(true);
  ASSERT_EQ(run.poses().size(), 3u);
  EXPECT_EQ(run.last_step(), 2);
  EXPECT_EQ(run.resends(), 3);
  EXPECT_TRUE(run.other_run_ids().empty());
}

TEST(RunLogTest, TwoDifferentPosesForOneStepAreAFlawNotAResend) {
  TempFolder dir;
  SyntheticRunLog log(dir / "forged.lcmlog");
  log.Poses(0, {{0, 0, 0}}).Poses(1, {{0.1, 0, 0}}).Poses(1, {{0.5, 0, 0}}).Poses(2, {{0.2, 0, 0}});
  const RunLog run = RunLog::Read(log.Write());
  ASSERT_TRUE(run.Flaw(false).has_value());
  EXPECT_TRUE(Contains(*run.Flaw(false), "two different DREAM_POSES for step 1")) << *run.Flaw(false);
  EXPECT_TRUE(Contains(*run.Flaw(false), "recorded.lcmlog") || Contains(*run.Flaw(false), "forged.lcmlog"));
}

// A second world on the bus while it was recorded (a `dream sim` waiting for
// agents, resending its step 0): the log is of the run, the other world's
// poses, obstacles and status are left out and named.
TEST(RunLogTest, ASecondWorldInARecordingIsLeftOutAndNamed) {
  constexpr int64_t kRun = 11;
  constexpr int64_t kIdle = 22;
  auto poses = [](int64_t run_id, int64_t step, double x) {
    robot_poses_t message{};
    message.utime = step * 33000;
    message.step = step;
    message.run_id = run_id;
    message.num_robots = 1;
    message.x = {x};
    message.y = {0.0};
    message.theta = {0.0};
    message.v = {0.0};
    message.w = {0.0};
    return message;
  };
  auto status = [](int64_t run_id, int64_t step, int8_t state) {
    run_status_t message{};
    message.step = step;
    message.run_id = run_id;
    message.state = state;
    return message;
  };
  obstacles_t idle_obstacles{};
  idle_obstacles.run_id = kIdle;
  idle_obstacles.num_obstacles = 1;
  idle_obstacles.obstacles = {Box(0, 1.0, 1.0, 0.1, 0.1)};
  TempFolder dir;
  SyntheticRunLog log(dir / "two_worlds.lcmlog");
  log.MessageOn("DREAM_POSES", poses(kIdle, 0, -1.0)).MessageOn("DREAM_OBSTACLES", idle_obstacles);
  for (int64_t step = 0; step < 5; ++step) {
    log.MessageOn("DREAM_POSES", poses(kRun, step, 0.1 * static_cast<double>(step)));
    log.MessageOn("DREAM_POSES", poses(kIdle, 0, -1.0));  // the idle world resends its step 0
    log.MessageOn("DREAM_STATUS", status(kIdle, 0, run_status_t::WAITING_FOR_AGENTS));
  }
  log.MessageOn("DREAM_STATUS", status(kRun, 4, run_status_t::FINISHED));
  log.MessageOn("DREAM_STATUS", status(kIdle, 0, run_status_t::WAITING_FOR_AGENTS));
  const RunLog run = RunLog::Read(log.Write());
  EXPECT_FALSE(run.Flaw(true).has_value()) << *run.Flaw(true);
  EXPECT_EQ(run.run_id(), kRun);
  ASSERT_EQ(run.poses().size(), 5u);
  EXPECT_DOUBLE_EQ(run.poses().back().x[0], 0.4);
  EXPECT_EQ(run.other_run_ids(), std::vector<int64_t>{kIdle});
  EXPECT_TRUE(run.obstacles().empty());
  ASSERT_TRUE(run.last_status().has_value());
  EXPECT_EQ(run.last_status()->state, run_status_t::FINISHED);
}

}  // namespace
}  // namespace dream::run_log
