// The one judge's exit codes (issue 33): one mapping from how a run ended and
// its verdict to the exit code every command returns.
#include <gtest/gtest.h>

#include "dream/session/run_exit_code.h"
#include "dream/world/verdict_reason.h"

namespace dream::session {
namespace {

world::RunJudgement JudgementWith(world::RunVerdict verdict) {
  world::RunJudgement judgement{world::RunReport{}};
  if (verdict != world::RunVerdict::kClean) judgement.Add({"goal", verdict, "a reason of this verdict", "here"});
  return judgement;
}

TEST(RunExitCode, AFinishedRunExitsAsItsVerdictSays) {
  node::RunOutcome finished;
  EXPECT_EQ(ExitCodeOf(finished, JudgementWith(world::RunVerdict::kClean)), kExitOk);
  EXPECT_EQ(ExitCodeOf(finished, JudgementWith(world::RunVerdict::kWarning)), kExitOk);
  EXPECT_EQ(ExitCodeOf(finished, JudgementWith(world::RunVerdict::kNotReady)), kExitNotReady);
  EXPECT_EQ(ExitCodeOf(finished, JudgementWith(world::RunVerdict::kRejected)), kExitRejected);
  EXPECT_EQ(ExitCodeOf(world::RunVerdict::kNotReady), 5);
  EXPECT_EQ(ExitCodeOf(world::RunVerdict::kRejected), 3);
}

TEST(RunExitCode, HowTheRunEndedComesBeforeItsVerdict) {
  node::RunOutcome interrupted;
  interrupted.end = node::RunOutcome::End::kInterrupted;
  EXPECT_EQ(ExitCodeOf(interrupted, JudgementWith(world::RunVerdict::kRejected)), kExitInterrupted);
  node::RunOutcome timed_out;
  timed_out.end = node::RunOutcome::End::kStartTimeout;
  EXPECT_EQ(ExitCodeOf(timed_out, JudgementWith(world::RunVerdict::kClean)), kExitRunFailed);
  node::RunOutcome faulted;
  faulted.robot_faults[2] = "step 5: KeyError";
  EXPECT_EQ(ExitCodeOf(faulted, JudgementWith(world::RunVerdict::kNotReady)), kExitRunFailed);

  RunResult unwritten;
  EXPECT_EQ(ExitCodeOf(unwritten), kExitRunFailed);  // no summary.json
  RunResult no_picture;
  no_picture.summary_written = true;
  no_picture.picture_failed = true;
  EXPECT_EQ(ExitCodeOf(no_picture), kExitRunFailed);
  no_picture.picture_failed = false;
  EXPECT_EQ(ExitCodeOf(no_picture), kExitOk);
}

// Sweeps read a run's exit code back: 0, 3 and 5 ran to a verdict (its
// summary.json says which), the rest did not.
TEST(RunExitCode, OnlyZeroThreeAndFiveRanToAVerdict) {
  for (int code : {0, 3, 5}) EXPECT_TRUE(RanToAVerdict(code)) << code;
  for (int code : {1, 2, 4, 130, 137, -1}) EXPECT_FALSE(RanToAVerdict(code)) << code;
}

}  // namespace
}  // namespace dream::session
