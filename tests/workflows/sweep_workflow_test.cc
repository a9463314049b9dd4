// The whole sweep workflow (dream::workflows::SweepWorkflow) with a fake job
// runner and a fake Slurm: what each engine writes, the rows of failed,
// cancelled, pending and half-written runs, and what resume runs again.
#include "dream/workflows/sweep_workflow.h"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>

#include "dream/config_overrides/config_text.h"
#include "dream/files/stopped.h"
#include "dream/workflows/slurm_jobs.h"
#include "dream/workflows/sweep_folder.h"
#include "sweep_workflow_fixture.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;
using testing::FakeJobRunner;
using testing::FinishedSummary;
using testing::ReadText;
using testing::SweepWorkflowTest;

TEST_F(SweepWorkflowTest, LocalSweepWritesEveryRunItsExitRecordAndTheSameTableAsSweepTable) {
  const SweepOutcome outcome = Workflow().Start(settings_, Base());
  EXPECT_EQ(outcome.kind, SweepOutcome::Kind::kFinished);
  EXPECT_TRUE(outcome.AllRan()) << ReadText(out() / "sweep.csv");
  EXPECT_EQ(jobs_asked_, 2);  // one per core
  ASSERT_EQ(started_.size(), 4u);
  EXPECT_EQ(started_[0][0], "/opt/dream/bin/dream");
  EXPECT_EQ(started_[0][1], "run");
  const SweepFolder folder(out().string());
  const SweepPlan plan = folder.ReadPlan();
  for (const SweepPlan::Run& run : plan.runs()) {
    EXPECT_TRUE(fs::exists(folder.RunDir(run.name) + "/config.yaml")) << run.name;
    ASSERT_TRUE(folder.ReadRunExit(run.name)) << run.name;
  }
  const std::string csv = ReadText(out() / "sweep.csv");
  EXPECT_NE(ReadText(out() / "sweep.md").find("## By value"), std::string::npos);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
  // dream sweep table over the same folder: the same rows (the fake's wall times are equal).
  const SweepOutcome table = Workflow().Table(out().string());
  EXPECT_TRUE(table.AllRan());
  EXPECT_EQ(ReadText(out() / "sweep.csv"), csv);
  EXPECT_EQ(started_.size(), 4u);  // table runs nothing
}

TEST_F(SweepWorkflowTest, AFailedRunIsARowSayingWhyAndResumeRunsOnlyIt) {
  auto one_fails = [](const std::string& dir) {
    if (dir.find("seed2_max_speed_mps-0.2") != std::string::npos) return FakeJobRunner::Outcome{4, nullptr};
    return FakeJobRunner::Outcome{0, FinishedSummary(true, 30, 0.3)};
  };
  const SweepOutcome first = Workflow(one_fails).Start(settings_, Base());
  EXPECT_EQ(first.summary.failed, 1u);
  EXPECT_FALSE(first.AllRan());
  EXPECT_NE(ReadText(out() / "sweep.csv").find("failed,false,4,"), std::string::npos);
  EXPECT_NE(ReadText(out() / "sweep.md").find("exit 4: it broke"), std::string::npos);

  started_.clear();
  const SweepOutcome resumed = Workflow().Resume(out().string(), {});
  ASSERT_EQ(started_.size(), 1u);
  EXPECT_NE(started_[0][2].find("seed2_max_speed_mps-0.2"), std::string::npos);
  EXPECT_TRUE(resumed.AllRan());
  EXPECT_EQ(resumed.summary.ran, 4u);

  started_.clear();
  Workflow().Resume(out().string(), {});
  EXPECT_TRUE(started_.empty()) << "a sweep whose runs all ran has nothing to resume";
}

TEST_F(SweepWorkflowTest, AnInterruptedLocalSweepResumesTheRunsThatNeverStarted) {
  const SweepOutcome first = Workflow(nullptr, 1).Start(settings_, Base());
  EXPECT_EQ(first.kind, SweepOutcome::Kind::kInterrupted);
  EXPECT_EQ(first.summary.listed, 1u);
  const SweepFolder folder(out().string());
  const SweepPlan plan = folder.ReadPlan();
  EXPECT_FALSE(fs::exists(folder.RunDir(plan.runs()[3].name))) << "a run that never started has no folder";

  const SweepStatusReport status = Workflow().Status(out().string());
  EXPECT_EQ(status.finished, 1u);
  EXPECT_EQ(status.not_started, 3u);

  started_.clear();
  const SweepOutcome resumed = Workflow().Resume(out().string(), {});
  EXPECT_EQ(started_.size(), 3u);
  EXPECT_TRUE(resumed.AllRan());
  EXPECT_NE(ReadText(folder.RunDir(plan.runs()[3].name) + "/config.yaml").find("max_speed_mps: 0.2"),
            std::string::npos);
}

TEST_F(SweepWorkflowTest, AHalfWrittenRunFolderIsAFailedRowAndIsRunAgain) {
  Workflow().Start(settings_, Base());
  const SweepFolder folder(out().string());
  const std::string name = folder.ReadPlan().runs()[1].name;
  // A task killed half way: the log's .part, no summary of its own, no exit record.
  fs::remove(folder.RunDir(name) + "/exit.txt");
  fs::remove(folder.RunDir(name) + "/summary.json");
  std::ofstream(folder.RunDir(name) + "/run.lcmlog.part") << "half";
  const SweepOutcome table = Workflow().Table(out().string());
  EXPECT_EQ(table.summary.failed, 1u);
  EXPECT_EQ(table.summary.ran, 3u);
  EXPECT_NE(ReadText(out() / "sweep.md").find("killed before it ended"), std::string::npos);
  started_.clear();
  EXPECT_TRUE(Workflow().Resume(out().string(), {}).AllRan());
  ASSERT_EQ(started_.size(), 1u);
  EXPECT_FALSE(fs::exists(folder.RunDir(name) + "/run.lcmlog.part"));
}

TEST_F(SweepWorkflowTest, PlanEngineWritesOneShellCommandPerRunAndRunsNothing) {
  settings_.engine = SweepSettings::Engine::kPlan;
  const SweepOutcome outcome = Workflow().Start(settings_, Base());
  EXPECT_EQ(outcome.kind, SweepOutcome::Kind::kPlanned);
  EXPECT_TRUE(started_.empty());
  EXPECT_TRUE(slurm_.calls.empty());
  const SweepFolder folder(out().string());
  EXPECT_EQ(ReadText(out() / "commands.txt"), folder.RunCommand(0) + "\n" + folder.RunCommand(1) + "\n" +
                                                  folder.RunCommand(2) + "\n" + folder.RunCommand(3) + "\n");
  EXPECT_NE(ReadText(out() / "run.sh").find("dream=/opt/dream/bin/dream\n"), std::string::npos);
  const SweepPlan plan = folder.ReadPlan();
  for (const SweepPlan::Run& run : plan.runs()) {
    EXPECT_TRUE(fs::exists(folder.RunDir(run.name) + "/config.yaml")) << run.name;
  }
  // Nothing ran yet: every run is a row that says so.
  const SweepOutcome table = Workflow().Table(out().string());
  EXPECT_EQ(table.summary.not_run, 4u);
  EXPECT_NE(ReadText(out() / "sweep.md").find("not run (never started)"), std::string::npos);
}

TEST_F(SweepWorkflowTest, SlurmEngineSubmitsOneArrayAndATableJobAfterIt) {
  settings_.engine = SweepSettings::Engine::kSlurm;
  settings_.jobs = 3;
  settings_.slurm_options = {"--partition=short", "--account=lab"};
  const SweepOutcome outcome = Workflow().Start(settings_, Base());
  EXPECT_EQ(outcome.kind, SweepOutcome::Kind::kSubmitted);
  EXPECT_EQ(outcome.jobs, (std::vector<std::string>{"100", "101"}));
  EXPECT_TRUE(started_.empty());
  const auto sbatches = slurm_.Sbatches();
  ASSERT_EQ(sbatches.size(), 2u);
  const SweepFolder folder(out().string());
  const std::vector<std::string> array = {"sbatch",
                                          "--parsable",
                                          "--job-name=dream-sweep-demo",
                                          "--array=0-3%3",
                                          "--output=" + folder.Path("slurm/%A_%a.out"),
                                          "--time=11",  // 10 min + 0.1 s per step of 40
                                          "--partition=short",
                                          "--account=lab",
                                          folder.Path("slurm/array.sh"),
                                          "0"};
  EXPECT_EQ(sbatches[0], array);
  EXPECT_EQ(sbatches[1][3], "--dependency=afterany:100");
  EXPECT_EQ(sbatches[1].back(), folder.Path("slurm/table.sh"));
  EXPECT_NE(ReadText(folder.Path("slurm/table.sh")).find("/opt/dream/bin/dream sweep table"), std::string::npos);
  const SlurmJobs jobs(folder);
  ASSERT_EQ(jobs.arrays().size(), 1u);
  EXPECT_EQ(jobs.arrays()[0].job_id, "100");
  EXPECT_EQ(jobs.table_jobs(), (std::vector<std::string>{"101"}));
  const SweepPlan plan = folder.ReadPlan();
  for (const SweepPlan::Run& run : plan.runs()) {
    EXPECT_TRUE(fs::exists(folder.RunDir(run.name) + "/config.yaml")) << run.name;
  }
}

TEST_F(SweepWorkflowTest, SlurmArraysAreCutAtTheClustersMaxArraySize) {
  settings_.engine = SweepSettings::Engine::kSlurm;
  settings_.seeds = "1-7";
  settings_.sets.clear();
  settings_.slurm_options = {"--time=5"};
  slurm_.max_array_size = 3;
  Workflow().Start(settings_, Base());
  const auto sbatches = slurm_.Sbatches();
  ASSERT_EQ(sbatches.size(), 4u);
  EXPECT_EQ(sbatches[0][3], "--array=0-2");
  EXPECT_EQ(sbatches[1][3], "--array=0-2");
  EXPECT_EQ(sbatches[1].back(), "3");  // the offset: task T runs run 3 + T
  EXPECT_EQ(sbatches[2][3], "--array=0");
  EXPECT_EQ(sbatches[2].back(), "6");
  EXPECT_EQ(sbatches[3][3], "--dependency=afterany:100:101:102");
  for (const auto& sbatch : sbatches) {
    EXPECT_EQ(
        std::count_if(sbatch.begin(), sbatch.end(), [](const std::string& w) { return w.rfind("--time", 0) == 0; }), 1)
        << "the user's --time replaces the default";
  }
}

TEST_F(SweepWorkflowTest, SlurmRowsSayCancelledPendingAndRunningAndResumeWaitsThenRedoesThem) {
  settings_.engine = SweepSettings::Engine::kSlurm;
  Workflow().Start(settings_, Base());
  const SweepFolder folder(out().string());
  const SweepPlan plan = folder.ReadPlan();
  // Run 0 finished on a node; run 1's task was cancelled while it ran; 2 pending, 3 running.
  folder.WriteRunExit(plan.runs()[0].name, {0, 2.5, false, ""});
  std::ofstream(folder.RunDir(plan.runs()[0].name) + "/summary.json")
      << testing::AsDreamRunWrites(folder.RunDir(plan.runs()[0].name), FinishedSummary(true, 30, 0.3)).dump();
  std::ofstream(folder.Path("slurm/100_1.out"))
      << "slurmstepd: error: *** JOB 102 ON vm CANCELLED AT 2026-11-27T12:00:00 ***\n";
  slurm_.queue = "100_2|PENDING\n100_3|RUNNING\n";

  const SweepStatusReport status = Workflow().Status(out().string());
  EXPECT_EQ(status.finished, 1u);
  EXPECT_EQ(status.failed, 1u);
  EXPECT_EQ(status.pending, 1u);
  EXPECT_EQ(status.running, 1u);
  EXPECT_NE(status.Text().find("cancelled in Slurm (CANCELLED)"), std::string::npos) << status.Text();

  const SweepOutcome table = Workflow().Table(out().string());
  EXPECT_EQ(table.summary.failed, 1u);
  EXPECT_EQ(table.summary.not_run, 2u);
  const std::string md = ReadText(out() / "sweep.md");
  EXPECT_NE(md.find("not run (pending in Slurm)"), std::string::npos);
  EXPECT_NE(md.find("failed to run (cancelled in Slurm (CANCELLED))"), std::string::npos);

  EXPECT_THROW(Workflow().Resume(out().string(), {}), std::runtime_error) << "runs are still queued";
  slurm_.queue.clear();  // the rest cancelled before they started
  const size_t before = slurm_.Sbatches().size();
  const SweepOutcome resumed = Workflow().Resume(out().string(), {});
  EXPECT_EQ(resumed.kind, SweepOutcome::Kind::kSubmitted);
  const auto sbatches = slurm_.Sbatches();
  ASSERT_EQ(sbatches.size(), before + 2);
  EXPECT_EQ(sbatches[before][3], "--array=1-3");
  EXPECT_EQ(SlurmJobs(folder).arrays().size(), 2u);
}

TEST_F(SweepWorkflowTest, SbatchRefusingTheArrayQuotesIt) {
  settings_.engine = SweepSettings::Engine::kSlurm;
  slurm_.refuse_sbatch = true;
  try {
    Workflow().Start(settings_, Base());
    FAIL() << "expected sbatch's refusal";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("Invalid partition name"), std::string::npos) << e.what();
  }
}

// Planning parses the base config once and copies it per run (YAML::Clone,
// which keeps no lines); a run whose config is bad is checked again on a fresh
// parse, so the error still names the run and the key's line in the base file.
TEST_F(SweepWorkflowTest, ABadRunConfigNamesItsRunAndTheBaseFilesLine) {
  settings_.sets = {"robots=2,3"};  // 3 robots, 2 initial poses (line 5)
  try {
    Workflow().Start(settings_, Base());
    FAIL() << "a run with 3 robots and 2 initial poses was planned";
  } catch (const std::exception& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("run seed1_robots-3"), std::string::npos) << message;
    EXPECT_NE(message.find("base.yaml:5"), std::string::npos) << message;
  }
  EXPECT_FALSE(fs::exists(out() / "runs" / "seed1_robots-2" / "config.yaml"));
}

// Each run's config.yaml is written from the text kept per parameter value
// (only seed and name emitted afresh): it must be exactly what emitting the
// whole config gives.
TEST_F(SweepWorkflowTest, EveryRunsConfigIsTheWholeConfigsText) {
  settings_.seeds = "1-3";
  settings_.sets = {"controller.max_speed_mps=0.1,0.2",
                    "controller.goals=[[0.3, 0.3], [-0.3, -0.3]],[[0.1, 0.1], [0, 0]]"};
  Workflow().Start(settings_, Base());
  const SweepPlan plan = SweepFolder(out().string()).ReadPlan();
  ASSERT_EQ(plan.runs().size(), 12u);
  const std::string base_text = ReadText(settings_.config_path);
  for (const SweepPlan::Run& run : plan.runs()) {
    const std::string written = ReadText(SweepFolder(out().string()).RunDir(run.name) + "/config.yaml");
    const std::string header_end = "--overwrite\n";
    const size_t body = written.find(header_end);
    ASSERT_NE(body, std::string::npos) << written;
    const std::string whole =
        config_overrides::ConfigText(SweepPlan::MakeRunConfig(base_text, settings_.config_path, run), "");
    EXPECT_EQ(written.substr(body + header_end.size()), whole) << run.name;
    EXPECT_NE(written.find("seed: " + std::to_string(run.seed) + "\n"), std::string::npos) << written;
  }
}

TEST_F(SweepWorkflowTest, BadInputWritesNothing) {
  settings_.sets = {"controller.max_speed_mps=0.1,5"};
  EXPECT_ANY_THROW(Workflow().Start(settings_, Base()));
  settings_.sets = {};
  settings_.engine = SweepSettings::Engine::kLocal;
  settings_.slurm_options = {"--partition=x"};
  EXPECT_THROW(Workflow().Start(settings_, Base()), std::invalid_argument);
  EXPECT_FALSE(fs::exists(out()));
  EXPECT_THROW(Workflow().Table((scratch_.path() / "nothing").string()), std::runtime_error);
}

}  // namespace
// Issue 34: Ctrl-C stops `dream sweep table` (and status, resume) while it
// reads thousands of runs' files, before it writes anything (exit 130).
TEST_F(SweepWorkflowTest, CtrlCStopsTheTableBeforeItWritesAnything) {
  Workflow().Start(settings_, Base());
  fs::remove(out() / "sweep.csv");
  fs::remove(out() / "sweep.md");
  std::atomic<bool> stop{true};
  SweepWorkflow::Environment env;
  env.commands = &slurm_;
  env.out = &printed_;
  env.stop = &stop;
  SweepWorkflow stopped(std::move(env));
  EXPECT_THROW(stopped.Table(out().string()), files::Stopped);
  EXPECT_FALSE(fs::exists(out() / "sweep.csv"));
  EXPECT_FALSE(fs::exists(out() / "sweep.md"));
  EXPECT_THROW(stopped.Status(out().string()), files::Stopped);
  stop = false;
  EXPECT_TRUE(stopped.Table(out().string()).AllRan());
  EXPECT_TRUE(fs::exists(out() / "sweep.csv"));
}

}  // namespace dream::workflows
