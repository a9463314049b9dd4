// The sweep folder's files read back: the plan, exit records, Slurm's words.
#include "dream/workflows/sweep_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../support/scratch_folder.h"
#include "dream/workflows/run_exit.h"
#include "dream/workflows/slurm_submission.h"
#include "dream/workflows/slurm_task_state.h"
#include "dream/workflows/sweep_value_stats.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;

TEST(RunExit, RoundTripsAndRefusesWhatIsNotARecord) {
  const RunExit exit{4, 1.25, true, "could not start: no such file"};
  const std::optional<RunExit> back = RunExit::Parse(exit.Text());
  ASSERT_TRUE(back);
  EXPECT_EQ(back->exit_code, 4);
  EXPECT_DOUBLE_EQ(back->wall_time_s, 1.25);
  EXPECT_TRUE(back->timed_out);
  EXPECT_EQ(back->problem, "could not start: no such file");
  EXPECT_TRUE(RunExit::Parse("0 0.181 0\n"));  // as run.sh writes it
  for (const char* bad : {"", "x 1 0\n", "0 1 2\n", "0 -1 0\n", "999 1 0\n", "0 nan 0\n", "0 1 0 extra\n"}) {
    EXPECT_FALSE(RunExit::Parse(bad)) << bad;
  }
  EXPECT_FALSE(RunExit::Parse(std::string(RunExit::kMaxBytes + 1, '1')));
}

class SweepFolderTest : public ::testing::Test {
 protected:
  SweepFolderTest() : scratch_("sweep_folder"), folder_(scratch_.path().string()) {}
  void WritePlanText(const std::string& text) { std::ofstream(folder_.Path("plan.tsv")) << text; }
  dream::testing::ScratchFolder scratch_;
  SweepFolder folder_;
};

TEST_F(SweepFolderTest, PlanRoundTripsValuesWithTabsAndNewlines) {
  std::vector<SweepPlan::Run> runs(2);
  runs[0] = {0, "seed1_a-x", 1, {{"controller.a", "x\ty\\z"}, {"b", "[1, 2]"}}};
  runs[1] = {1, "seed2_a-x", 2, {{"controller.a", "line\nbreak"}, {"b", "'q'"}}};
  folder_.WritePlan(SweepPlan::FromRuns({"controller.a", "b"}, runs));
  const SweepPlan back = folder_.ReadPlan();
  EXPECT_EQ(back.parameter_keys(), (std::vector<std::string>{"controller.a", "b"}));
  ASSERT_EQ(back.runs().size(), 2u);
  EXPECT_EQ(back.runs()[0].parameters, runs[0].parameters);
  EXPECT_EQ(back.runs()[1].parameters, runs[1].parameters);
  EXPECT_EQ(back.runs()[1].seed, 2u);
}

TEST_F(SweepFolderTest, ADamagedPlanIsRefusedNamingTheLine) {
  const std::string header = "index\trun\tseed\n";
  for (const std::string& rows :
       {std::string("0\t../escape\t1\n"), std::string("1\tseed1\t1\n"), std::string("0\tseed1\t-3\n"),
        std::string("0\tseed1\t1\textra\n"), std::string("0\tseed1\t1\n1\tseed1\t2\n")}) {
    WritePlanText(header + rows);
    try {
      folder_.ReadPlan();
      ADD_FAILURE() << "accepted: " << rows;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("plan.tsv:"), std::string::npos) << e.what();
    }
  }
  WritePlanText("no header\n");
  EXPECT_THROW(folder_.ReadPlan(), std::runtime_error);
}

TEST(SlurmTaskState, ReadsSlurmsWordsAndItsLogLines) {
  EXPECT_EQ(SlurmTaskState::FromSlurmWord("CANCELLED by 0")->state, SlurmTaskState::State::kCancelled);
  EXPECT_EQ(SlurmTaskState::FromSlurmWord("PENDING")->state, SlurmTaskState::State::kPending);
  EXPECT_EQ(SlurmTaskState::FromSlurmWord("NODE_FAIL")->state, SlurmTaskState::State::kFailed);
  EXPECT_FALSE(SlurmTaskState::FromSlurmWord(""));
  EXPECT_EQ(SlurmTaskState::FromTaskLog(
                "x\nslurmstepd: error: *** JOB 7 ON vm CANCELLED AT 2026-11-27T12:00:00 DUE TO TIME LIMIT ***\n")
                ->state,
            SlurmTaskState::State::kTimedOut);
  EXPECT_EQ(SlurmTaskState::FromTaskLog("*** JOB 7 ON vm CANCELLED AT 2026-11-27T12:00:00 ***")->state,
            SlurmTaskState::State::kCancelled);
  EXPECT_FALSE(SlurmTaskState::FromTaskLog("an ordinary run's output\n"));
}

TEST(SlurmSubmission, ArraySpecsMergeRangesAndTimeLimitsGrowWithSteps) {
  EXPECT_EQ(SlurmSubmission::ArraySpec({0, 1, 2, 3}, 0, 4), "0-3%4");
  EXPECT_EQ(SlurmSubmission::ArraySpec({3, 7, 8, 9, 12}, 0, 0), "3,7-9,12");
  EXPECT_EQ(SlurmSubmission::ArraySpec({1003, 1004}, 1001, 0), "2-3");
  EXPECT_EQ(SlurmSubmission::DefaultTimeLimitMinutes(0), 10);
  EXPECT_EQ(SlurmSubmission::DefaultTimeLimitMinutes(4000), 17);  // 400 s of steps
  EXPECT_TRUE(SlurmSubmission::SetsTimeLimit({"--partition=x", "--time=30"}));
  EXPECT_TRUE(SlurmSubmission::SetsTimeLimit({"-t", "30"}));
  EXPECT_FALSE(SlurmSubmission::SetsTimeLimit({"--partition=x"}));
}

SweepRunResult Row(size_t index, const std::string& speed, const std::string& loss, bool success, long long completion,
                   double min_distance) {
  SweepRunResult r;
  r.run = {index, "run" + std::to_string(index), index, {{"speed", speed}, {"loss", loss}}};
  r.status = SweepRunResult::Status::kRan;
  r.success = success;
  r.goal.has_criterion = true;  // a kind with a goal: without one no run is a success
  r.goal.met = success;
  r.goal.completion_step = completion;
  r.min_distance_m = min_distance;
  return r;
}

TEST(SweepValueStats, JudgesEachValueAndEachCombinationApart) {
  std::vector<SweepRunResult> rows = {Row(0, "0.1", "0", true, 100, 0.30), Row(1, "0.1", "0.2", false, -1, 0.17),
                                      Row(2, "0.2", "0", true, 80, 0.25), Row(3, "0.2", "0.2", true, 90, 0.22)};
  rows.push_back(SweepRunResult::LostRun({4, "run4", 4, {{"speed", "0.2"}, {"loss", "0"}}}, "cancelled in Slurm"));
  const SweepValueStats stats({"speed", "loss"}, rows);
  ASSERT_EQ(stats.by_value().size(), 4u);
  const SweepValueStats::Group& slow = stats.by_value()[0];
  EXPECT_EQ(slow.label, "speed=0.1");
  EXPECT_EQ(slow.succeeded, 1u);
  EXPECT_EQ(slow.judged, 2u);
  EXPECT_EQ(slow.completion_min, 100);
  EXPECT_DOUBLE_EQ(slow.closest_m, 0.17);
  EXPECT_EQ(slow.closest_run, "run1");
  const SweepValueStats::Group& fast = stats.by_value()[1];
  EXPECT_EQ(fast.label, "speed=0.2");
  EXPECT_EQ(fast.judged, 3u);  // the cancelled run counts against its value
  EXPECT_EQ(fast.succeeded, 2u);
  EXPECT_DOUBLE_EQ(fast.completion_mean, 85.0);
  EXPECT_EQ(stats.by_value()[2].label, "loss=0");
  EXPECT_EQ(stats.by_value()[2].judged, 3u);
  ASSERT_EQ(stats.by_combination().size(), 4u);
  EXPECT_EQ(stats.by_combination()[2].label, "speed=0.2, loss=0");
  EXPECT_EQ(stats.by_combination()[2].runs, 2u);
  const std::string md = stats.Markdown(1);
  EXPECT_NE(md.find("| speed=0.1 | 2 | 1 of 2 (50.0 %) | mean 100, 100-100 (1 completed) | 0.1700 m (run1) |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("(3 more in sweep.md)"), std::string::npos);
  EXPECT_EQ(SweepValueStats({}, rows).Markdown(10), "");
}

}  // namespace
}  // namespace dream::workflows
