#include "parallel_runner.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace dream::cli {
namespace {

std::string TempPath(const std::string& name) {
  return ::testing::TempDir() + "parallel_runner_" + std::to_string(::getpid()) + "_" + name;
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

ParallelRunner::Job Shell(const std::string& script, const std::string& output_path) {
  return {{"/bin/sh", "-c", script}, output_path};
}

TEST(ParallelRunner, RunsEveryJobAtMostMaxParallelAtOnceWithItsOutputInItsFile) {
  ParallelRunner runner(2, 30.0, 5.0);
  std::atomic<bool> stop{false};
  int running = 0;
  int most_running = 0;
  std::map<size_t, ParallelRunner::Finished> ended;
  const bool completed = runner.Run(
      5, stop,
      [&](size_t index) {
        most_running = std::max(most_running, ++running);
        return Shell("echo job " + std::to_string(index) + "; sleep 0.1; exit " + std::to_string(index),
                     TempPath("out" + std::to_string(index)));
      },
      [&](const ParallelRunner::Finished& done) {
        --running;
        ended[done.index] = done;
      });
  EXPECT_TRUE(completed);
  EXPECT_EQ(most_running, 2);
  ASSERT_EQ(ended.size(), 5u);
  for (size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(ended[i].exit_code, static_cast<int>(i));
    EXPECT_FALSE(ended[i].timed_out);
    EXPECT_GE(ended[i].wall_time_s, 0.1);
    EXPECT_EQ(ReadFile(TempPath("out" + std::to_string(i))), "job " + std::to_string(i) + "\n");
  }
}

TEST(ParallelRunner, AJobPastItsTimeoutGetsSigintAndOneIgnoringItSigkill) {
  ParallelRunner runner(2, 0.2, 0.3);
  std::atomic<bool> stop{false};
  std::map<size_t, ParallelRunner::Finished> ended;
  runner.Run(
      2, stop,
      [&](size_t index) {
        // Job 0 dies of SIGINT; job 1 ignores it (exec keeps the ignored disposition).
        return Shell(index == 0 ? "exec sleep 20" : "trap '' INT; exec sleep 20", TempPath("timeout"));
      },
      [&](const ParallelRunner::Finished& done) { ended[done.index] = done; });
  ASSERT_EQ(ended.size(), 2u);
  EXPECT_TRUE(ended[0].timed_out);
  EXPECT_EQ(ended[0].exit_code, 128 + SIGINT);
  EXPECT_LT(ended[0].wall_time_s, 5.0);
  EXPECT_TRUE(ended[1].timed_out);
  EXPECT_EQ(ended[1].exit_code, 128 + SIGKILL);
  EXPECT_GE(ended[1].wall_time_s, 0.5);
  EXPECT_LT(ended[1].wall_time_s, 5.0);
}

TEST(ParallelRunner, StopInterruptsTheRunningJobsAndStartsNoMore) {
  ParallelRunner runner(2, 30.0, 5.0);
  std::atomic<bool> stop{false};
  std::vector<size_t> prepared;
  std::vector<ParallelRunner::Finished> ended;
  const bool completed = runner.Run(
      4, stop,
      [&](size_t index) {
        prepared.push_back(index);
        if (index == 1) stop.store(true);  // as if Ctrl-C came while the second job starts
        return Shell("exec sleep 20", TempPath("stop"));
      },
      [&](const ParallelRunner::Finished& done) { ended.push_back(done); });
  EXPECT_FALSE(completed);
  EXPECT_EQ(prepared, (std::vector<size_t>{0, 1}));
  ASSERT_EQ(ended.size(), 2u);
  for (const auto& done : ended) {
    EXPECT_EQ(done.exit_code, 128 + SIGINT);
    EXPECT_FALSE(done.timed_out);
  }
}

TEST(ParallelRunner, AJobThatCannotStartIsReportedAndTheOthersRun) {
  ParallelRunner runner(1, 30.0, 5.0);
  std::atomic<bool> stop{false};
  std::map<size_t, ParallelRunner::Finished> ended;
  runner.Run(
      3, stop,
      [&](size_t index) -> ParallelRunner::Job {
        if (index == 0) throw std::runtime_error("disk full");
        if (index == 1) return {{"/nonexistent/dream"}, TempPath("missing")};
        return Shell("exit 0", TempPath("fine"));
      },
      [&](const ParallelRunner::Finished& done) { ended[done.index] = done; });
  ASSERT_EQ(ended.size(), 3u);
  EXPECT_EQ(ended[0].exit_code, -1);
  EXPECT_EQ(ended[0].start_error, "disk full");
  // posix_spawnp reports a missing program as a start error, or the child exits 127.
  EXPECT_TRUE(ended[1].exit_code == -1 || ended[1].exit_code == 127) << ended[1].exit_code;
  EXPECT_EQ(ended[2].exit_code, 0);
}

TEST(ParallelRunner, RefusesNonsenseLimits) {
  EXPECT_THROW(ParallelRunner(0, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(ParallelRunner(1, 0.0, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace dream::cli
