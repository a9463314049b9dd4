// RunLog's commands: DREAM_CMD_<id>, DREAM_LAB_CMD_<id> and DREAM_APPLIED of
// the run, and what a hostile log (bad ids, wrong steps, lying counts, floods)
// cannot make it keep.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "dream/applied_commands_t.hpp"
#include "dream/run_log/run_log.h"
#include "dream/velocity_command_t.hpp"
#include "synthetic_run_log.h"
#include "temp_folder.h"

namespace dream::run_log {
namespace {

using dream::testing::SyntheticRunLog;
using dream::testing::TempFolder;

/// A step's time, or 0 for the steps no run has (the test's hostile ones).
int64_t UtimeOf(int64_t step) { return step >= 0 && step < 1000000 ? step * 33000 : 0; }

velocity_command_t Command(int64_t step, int32_t robot, double v, int64_t run_id = 0) {
  velocity_command_t command{};
  command.utime = UtimeOf(step);
  command.step = step;
  command.run_id = run_id;
  command.robot_id = robot;
  command.agent_id = 100 + robot;
  command.v = v;
  command.w = -v;
  command.done = false;
  return command;
}

applied_commands_t Applied(int64_t step, int32_t robots, double v, int64_t run_id = 0) {
  applied_commands_t applied{};
  applied.utime = UtimeOf(step);
  applied.step = step;
  applied.run_id = run_id;
  applied.num_robots = robots;
  applied.applied_agent_id.assign(static_cast<size_t>(robots), 7);
  applied.commanded_v.assign(static_cast<size_t>(robots), v);
  applied.commanded_w.assign(static_cast<size_t>(robots), 0.0);
  applied.conflicts.assign(static_cast<size_t>(robots), 0);
  return applied;
}

/// A two-robot run of steps 0..2 (run id 0, as SyntheticRunLog's poses carry).
SyntheticRunLog ThreeSteps(const std::string& path) {
  SyntheticRunLog log(path);
  log.Poses(0, {{0, 0, 0}, {1, 0, 0}}).Poses(1, {{0, 0, 0}, {1, 0, 0}}).Poses(2, {{0, 0, 0}, {1, 0, 0}});
  return log;
}

TEST(RunLogCommandsTest, CommandsAreTheRunsByStepThenRobot) {
  TempFolder dir;
  SyntheticRunLog log = ThreeSteps(dir / "run.lcmlog");
  log.MessageOn("DREAM_CMD_1", Command(1, 1, 0.11))
      .MessageOn("DREAM_CMD_0", Command(1, 0, 0.10))
      .MessageOn("DREAM_CMD_0", Command(0, 0, 0.00))
      .MessageOn("DREAM_APPLIED", Applied(0, 2, 0.05));
  const RunLog run = RunLog::Read(log.Write());
  ASSERT_EQ(run.commands().size(), 3u);
  EXPECT_EQ(run.commands()[0].step, 0);
  EXPECT_EQ(run.commands()[1].step, 1);
  EXPECT_EQ(run.commands()[1].robot_id, 0);
  EXPECT_DOUBLE_EQ(run.commands()[1].v_mps, 0.10);
  EXPECT_EQ(run.commands()[2].robot_id, 1);
  EXPECT_DOUBLE_EQ(run.commands()[2].w_radps, -0.11);
  EXPECT_EQ(run.commands()[2].agent_id, 101);
  ASSERT_EQ(run.applied().size(), 1u);
  EXPECT_DOUBLE_EQ(run.applied()[0].commanded_v.at(1), 0.05);
  EXPECT_TRUE(run.lab_commands().empty());
  EXPECT_FALSE(run.Flaw(false).has_value());  // commands never make a log less whole
}

TEST(RunLogCommandsTest, LabCommandsAreTheLabsWithRunIdZeroOrTheRuns) {
  TempFolder dir;
  SyntheticRunLog log = ThreeSteps(dir / "run.lcmlog");
  log.MessageOn("DREAM_LAB_CMD_0", Command(0, 0, 0.2)).MessageOn("DREAM_LAB_CMD_1", Command(1, 1, 0.1, 55));
  const RunLog run = RunLog::Read(log.Write());
  ASSERT_EQ(run.lab_commands().size(), 1u);  // run id 55 is no world of this log
  EXPECT_DOUBLE_EQ(run.lab_commands()[0].v_mps, 0.2);
  EXPECT_TRUE(run.commands().empty());  // the lab's are not the agents'
}

TEST(RunLogCommandsTest, CommandsWithBadIdsAreLeftOut) {
  TempFolder dir;
  SyntheticRunLog log = ThreeSteps(dir / "run.lcmlog");
  log.MessageOn("DREAM_CMD_1", Command(0, 0, 1.0))                 // payload robot 0 on robot 1's channel
      .MessageOn("DREAM_CMD_2", Command(0, 2, 1.0))                // no robot 2 in a run of two
      .MessageOn("DREAM_CMD_-1", Command(0, -1, 1.0))              // no number
      .MessageOn("DREAM_CMD_01x", Command(0, 1, 1.0))              // not a number
      .MessageOn("DREAM_CMD_99999999", Command(0, 99999999, 1.0))  // past 6 digits
      .MessageOn("DREAM_CMD_0", Command(0, 0, 1.0, 77))            // another run's
      .MessageOn("DREAM_CMD_0", Command(2, 0, 0.3));               // the one of this run
  const RunLog run = RunLog::Read(log.Write());
  ASSERT_EQ(run.commands().size(), 1u);
  EXPECT_EQ(run.commands()[0].step, 2);
  EXPECT_DOUBLE_EQ(run.commands()[0].v_mps, 0.3);
}

TEST(RunLogCommandsTest, CommandsForStepsTheLogHasNoPosesForAreLeftOut) {
  TempFolder dir;
  SyntheticRunLog log = ThreeSteps(dir / "run.lcmlog");
  log.MessageOn("DREAM_CMD_0", Command(-1, 0, 1.0))
      .MessageOn("DREAM_CMD_0", Command(3, 0, 1.0))
      .MessageOn("DREAM_CMD_0", Command(int64_t{1} << 62, 0, 1.0))
      .MessageOn("DREAM_APPLIED", Applied(-5, 2, 1.0))
      .MessageOn("DREAM_APPLIED", Applied(int64_t{1} << 62, 2, 1.0))
      .MessageOn("DREAM_LAB_CMD_1", Command(7, 1, 1.0));
  const RunLog run = RunLog::Read(log.Write());
  EXPECT_TRUE(run.commands().empty());
  EXPECT_TRUE(run.applied().empty());
  EXPECT_TRUE(run.lab_commands().empty());
}

TEST(RunLogCommandsTest, AFloodKeepsOneCommandPerRobotAndStepTheFirst) {
  TempFolder dir;
  SyntheticRunLog log = ThreeSteps(dir / "run.lcmlog");
  log.MessageOn("DREAM_CMD_1", Command(1, 1, 0.5));
  for (int i = 0; i < 5000; ++i) log.MessageOn("DREAM_CMD_1", Command(1, 1, 9.0));
  for (int i = 0; i < 500; ++i) log.MessageOn("DREAM_APPLIED", Applied(2, 2, static_cast<double>(i)));
  const RunLog run = RunLog::Read(log.Write());
  ASSERT_EQ(run.commands().size(), 1u);  // at most steps x robots, whatever the log holds
  EXPECT_DOUBLE_EQ(run.commands()[0].v_mps, 0.5);
  ASSERT_EQ(run.applied().size(), 1u);
  EXPECT_DOUBLE_EQ(run.applied()[0].commanded_v.at(0), 0.0);
}

TEST(RunLogCommandsTest, AppliedWithALyingOrWrongRobotCountIsLeftOut) {
  TempFolder dir;
  applied_commands_t lying = Applied(1, 2, 1.0);
  SyntheticRunLog log = ThreeSteps(dir / "run.lcmlog");
  log.MessageOn("DREAM_APPLIED", Applied(0, 3, 1.0));  // three robots in a run of two
  std::vector<uint8_t> bytes(static_cast<size_t>(lying.getEncodedSize()));
  lying.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  // num_robots after the fingerprint, utime, step and run_id: 2^28 robots in a few dozen bytes.
  const int32_t claimed = 1 << 28;
  for (size_t i = 0; i < 4; ++i) bytes.at(32 + i) = static_cast<uint8_t>(claimed >> (24 - 8 * i));
  log.Bytes("DREAM_APPLIED", 33000, bytes).MessageOn("DREAM_CMD_0", Command(1, 0, 0.1));
  const RunLog run = RunLog::Read(log.Write());
  EXPECT_TRUE(run.applied().empty());
  ASSERT_EQ(run.commands().size(), 1u);  // what comes after a lie is still read
  EXPECT_FALSE(run.Flaw(true).has_value());
}

TEST(RunLogCommandsTest, ALogWithoutPosesHasNoCommands) {
  TempFolder dir;
  SyntheticRunLog log(dir / "run.lcmlog");
  log.MessageOn("DREAM_CMD_0", Command(0, 0, 0.1)).MessageOn("DREAM_APPLIED", Applied(0, 1, 0.1));
  const RunLog run = RunLog::Read(log.Write());
  EXPECT_TRUE(run.commands().empty());
  EXPECT_TRUE(run.applied().empty());
  EXPECT_TRUE(run.Flaw(false).has_value());
}

}  // namespace
}  // namespace dream::run_log
