// Issue 34's attacks on sweeps, with the fake engines (no process): FIFOs in
// run folders, runs still running elsewhere, inputs changed before resume,
// symlinked run folders, and sweep folders whose names a shell or Slurm would
// reinterpret. run.sh itself and the real sbatch: tests/integration
// (sweep_hostile.py, sweep_slurm.py).
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "dream/workflows/sweep_folder.h"
#include "dream/workflows/sweep_workflow.h"
#include "sweep_workflow_fixture.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;
using testing::FakeJobRunner;
using testing::FinishedSummary;
using testing::ReadText;
using testing::SweepWorkflowTest;

void ReplaceWithFifo(const std::string& path) {
  fs::remove(path);
  ASSERT_EQ(::mkfifo(path.c_str(), 0644), 0) << path;
}

/// Holds a run folder's lock as its dream run (or run.sh) does while it runs.
class RunningRun {
 public:
  explicit RunningRun(const std::string& dir)
      : fd_(::open((dir + "/.dream.lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
    EXPECT_GE(fd_, 0);
    EXPECT_EQ(::flock(fd_, LOCK_EX | LOCK_NB), 0);
    std::ofstream(dir + "/output.txt") << "step 100\n";
    std::ofstream(dir + "/run.lcmlog.part") << "half a log";
  }
  ~RunningRun() { End(); }
  void End() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

 private:
  int fd_;
};

FakeJobRunner::OutcomeFn LastRunFails() {
  return [](const std::string& dir) {
    if (dir.find("seed2_max_speed_mps-0.2") != std::string::npos) return FakeJobRunner::Outcome{4, nullptr};
    return FakeJobRunner::Outcome{0, FinishedSummary(true, 30, 0.3)};
  };
}

TEST_F(SweepWorkflowTest, FifosInRunFoldersAreRowsSayingSoNotWaits) {
  Workflow(LastRunFails()).Start(settings_, Base());
  const SweepFolder folder(out().string());
  const SweepPlan plan = folder.ReadPlan();
  ReplaceWithFifo(folder.RunDir(plan.runs()[0].name) + "/exit.txt");
  ReplaceWithFifo(folder.RunDir(plan.runs()[1].name) + "/summary.json");
  ReplaceWithFifo(folder.RunDir(plan.runs()[3].name) + "/output.txt");  // the failed run's, read for its last error

  const SweepStatusReport status = Workflow().Status(out().string());
  EXPECT_EQ(status.finished, 1u);
  EXPECT_EQ(status.failed, 3u);
  const SweepOutcome table = Workflow().Table(out().string());
  EXPECT_EQ(table.summary.ran, 1u);
  const std::string md = ReadText(out() / "sweep.md");
  EXPECT_NE(md.find("no readable exit record"), std::string::npos) << md;
  EXPECT_NE(md.find("exit.txt"), std::string::npos) << md;
  EXPECT_NE(md.find("exit 4"), std::string::npos) << md;

  // Resume clears the FIFOs with the rest of the runs' outputs and runs the three again.
  started_.clear();
  EXPECT_TRUE(Workflow().Resume(out().string(), {}).AllRan());
  EXPECT_EQ(started_.size(), 3u);
}

TEST_F(SweepWorkflowTest, AFifoAsASweepFileIsRefusedNamingIt) {
  settings_.engine = SweepSettings::Engine::kSlurm;
  Workflow().Start(settings_, Base());
  for (const std::string file : {"slurm/jobs.txt", "sweep.json", "plan.tsv"}) {
    const std::string path = (out() / file).string();
    const std::string text = ReadText(path);
    ReplaceWithFifo(path);
    for (const bool status : {true, false}) {
      try {
        status ? static_cast<void>(Workflow().Status(out().string()))
               : static_cast<void>(Workflow().Table(out().string()));
        ADD_FAILURE() << "a FIFO as " << file << " was read";
      } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("is a FIFO"), std::string::npos) << e.what();
      }
    }
    fs::remove(path);
    std::ofstream(path) << text;
  }
  EXPECT_EQ(Workflow().Status(out().string()).not_started, 4u);
}

TEST_F(SweepWorkflowTest, ARunStillRunningIsRunningInStatusAndResumeLeavesItAlone) {
  settings_.engine = SweepSettings::Engine::kPlan;
  Workflow().Start(settings_, Base());
  const SweepFolder folder(out().string());
  const std::string busy = folder.RunDir(folder.ReadPlan().runs()[0].name);
  RunningRun running(busy);  // `sh run.sh 0` from commands.txt, still going

  const SweepStatusReport status = Workflow().Status(out().string());
  EXPECT_EQ(status.running, 1u) << status.Text();
  EXPECT_EQ(status.not_started, 3u);
  EXPECT_EQ(status.failed, 0u) << "a running run is no run killed before it ended: " << status.Text();

  const SweepOutcome resumed = Workflow().Resume(out().string(), {});
  EXPECT_EQ(started_.size(), 3u);
  for (const auto& argv : started_) EXPECT_NE(argv.at(4), busy) << "the running run was started again";
  EXPECT_EQ(ReadText(busy + "/run.lcmlog.part"), "half a log") << "the running run's log was touched";
  EXPECT_EQ(ReadText(busy + "/output.txt"), "step 100\n");
  EXPECT_FALSE(fs::exists(busy + "/exit.txt"));
  EXPECT_EQ(resumed.summary.ran, 3u);
  EXPECT_NE(ReadText(out() / "sweep.md").find(SweepFolder::kRunningReason), std::string::npos);
  EXPECT_THROW(folder.ClearRun(folder.ReadPlan().runs()[0].name), std::runtime_error);

  // Killed without its exit record: once its lock is gone it is a run to redo.
  running.End();
  started_.clear();
  EXPECT_TRUE(Workflow().Resume(out().string(), {}).AllRan());
  ASSERT_EQ(started_.size(), 1u);
  EXPECT_EQ(started_[0].at(4), busy);
}

TEST_F(SweepWorkflowTest, ACancelledSlurmTaskWhoseRunIsStillEndingIsCancelledAndLeftAloneByResume) {
  settings_.engine = SweepSettings::Engine::kSlurm;
  Workflow().Start(settings_, Base());
  const SweepFolder folder(out().string());
  const std::string ending = folder.RunDir(folder.ReadPlan().runs()[1].name);
  std::ofstream(folder.Path("slurm/100_1.out"))
      << "slurmstepd: error: *** JOB 102 ON vm CANCELLED AT 2026-11-27T12:00:00 ***\n";
  RunningRun still_writing(ending);  // its dream run, past Slurm's notice, still writing its log

  EXPECT_EQ(Workflow().Table(out().string()).summary.failed, 1u);
  EXPECT_NE(ReadText(out() / "sweep.md").find("failed to run (cancelled in Slurm"), std::string::npos);
  const size_t before = slurm_.Sbatches().size();
  Workflow().Resume(out().string(), {});
  const auto sbatches = slurm_.Sbatches();
  ASSERT_EQ(sbatches.size(), before + 2);
  EXPECT_EQ(sbatches[before][3], "--array=0,2-3") << "the run still ending was submitted again";
  EXPECT_EQ(ReadText(ending + "/run.lcmlog.part"), "half a log");
}

TEST_F(SweepWorkflowTest, ResumeRefusesASweepWhoseConfigSweepJsonOrPlanChangedNamingWhat) {
  Workflow(nullptr, 1).Start(settings_, Base());  // interrupted: three runs to resume, from the base config
  const std::string config = settings_.config_path;
  const std::string sweep_json = (out() / "sweep.json").string();
  const std::string plan_tsv = (out() / "plan.tsv").string();
  const std::string other = (scratch_.path() / "other.yaml").string();
  std::ofstream(other) << std::string(testing::kBase) + "world:\n  realism: lab\n";
  auto refused = [&](const std::vector<std::string>& named) {
    started_.clear();
    try {
      Workflow().Resume(out().string(), {});
      ADD_FAILURE() << "resumed";
    } catch (const std::runtime_error& e) {
      for (const std::string& name : named) EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("changed since the sweep was planned"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(started_.empty());
    EXPECT_NE(Workflow().Status(out().string()).note.find("changed since the sweep was planned"), std::string::npos);
  };
  auto edited = [&](const std::string& path, const std::string& from, const std::string& to) {
    const std::string text = ReadText(path);
    EXPECT_NE(text.find(from), std::string::npos) << path;
    std::string changed = text;  // every occurrence: sweep.json names the config in its command and title too
    for (size_t at = changed.find(from); at != std::string::npos; at = changed.find(from, at + to.size())) {
      changed.replace(at, from.size(), to);
    }
    std::ofstream(path) << changed;
    return text;
  };

  const std::string config_text = edited(config, "max_speed_mps: 0.15", "max_speed_mps: 0.12");
  refused({"the base config " + config});
  std::ofstream(config) << config_text;

  const std::string json_text = edited(sweep_json, config, other);
  refused({"the base config " + other, "sweep.json"});
  std::ofstream(sweep_json) << json_text;

  const std::string plan_text = edited(plan_tsv, "\t2\t0.2", "\t2\t0.1");
  refused({"plan.tsv"});
  std::ofstream(plan_tsv) << plan_text;

  started_.clear();
  EXPECT_TRUE(Workflow().Resume(out().string(), {}).AllRan()) << "with every input put back";
  EXPECT_EQ(started_.size(), 3u);
}

TEST_F(SweepWorkflowTest, ASymlinkedRunFolderIsRefusedAndTheRunBehindItUntouched) {
  Workflow(LastRunFails()).Start(settings_, Base());
  const SweepFolder folder(out().string());
  const SweepPlan plan = folder.ReadPlan();
  const std::string victim = folder.RunDir(plan.runs()[0].name);
  const std::string failed = folder.RunDir(plan.runs()[3].name);
  fs::remove_all(failed);
  fs::create_directory_symlink(victim, failed);
  const std::string exit_before = ReadText(victim + "/exit.txt");
  const std::string summary_before = ReadText(victim + "/summary.json");

  const SweepOutcome table = Workflow().Table(out().string());
  EXPECT_EQ(table.summary.failed, 1u);
  EXPECT_NE(ReadText(out() / "sweep.md").find("is a symbolic link"), std::string::npos);
  started_.clear();
  try {
    Workflow().Resume(out().string(), {});
    ADD_FAILURE() << "resumed through a symlinked run folder";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(failed + " is a symbolic link"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(started_.empty());
  EXPECT_EQ(ReadText(victim + "/exit.txt"), exit_before);
  EXPECT_EQ(ReadText(victim + "/summary.json"), summary_before);
  EXPECT_THROW(folder.ClearRun(plan.runs()[3].name), std::runtime_error);
  EXPECT_TRUE(fs::exists(victim + "/summary.json"));
}

TEST_F(SweepWorkflowTest, NoPathMadeFromARunNameLeavesRuns) {
  const SweepFolder folder(out().string());
  for (const char* name : {"../../victim", "..", "a/b", "", "seed1\n", "$(touch x)"}) {
    EXPECT_THROW(folder.RunDir(name), std::invalid_argument) << name;
  }
  EXPECT_EQ(folder.RunDir("seed07_max_speed_mps-0.1"), folder.dir() + "/runs/seed07_max_speed_mps-0.1");
}

TEST_F(SweepWorkflowTest, AFolderNameWithANewlineIsRefusedBeforeAnythingIsWritten) {
  settings_.engine = SweepSettings::Engine::kPlan;
  for (const char* name : {"two\nlines", "carriage\rreturn", "tab\there"}) {
    settings_.out_dir = (scratch_.path() / name).string();
    try {
      Workflow().Start(settings_, Base());
      ADD_FAILURE() << "accepted " << name;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("control character"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(settings_.out_dir));
  }
}

TEST_F(SweepWorkflowTest, SlurmLogsOfAFolderWithPercentAreQuotedAndABackslashIsRefused) {
  settings_.engine = SweepSettings::Engine::kSlurm;
  settings_.out_dir = (scratch_.path() / "100%_%A").string();
  Workflow().Start(settings_, Base());
  const SweepFolder folder(settings_.out_dir);
  const auto sbatches = slurm_.Sbatches();
  ASSERT_EQ(sbatches.size(), 2u);
  const std::string quoted = (scratch_.path() / "100%%_%%A").string();
  EXPECT_EQ(sbatches[0][4], "--output=" + quoted + "/slurm/%A_%a.out");
  EXPECT_EQ(sbatches[1][4], "--output=" + quoted + "/slurm/table_%j.out");

  settings_.out_dir = (scratch_.path() / "back\\slash").string();
  EXPECT_THROW(Workflow().Start(settings_, Base()), std::invalid_argument);
  EXPECT_FALSE(fs::exists(settings_.out_dir));
}

}  // namespace
}  // namespace dream::workflows
