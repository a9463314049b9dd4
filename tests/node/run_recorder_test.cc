#include "dream/sim/run_recorder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/log_reader.h"
#include "dream/robot_poses_t.hpp"
#include "dream/sim/atomic_file.h"
#include "dream/sim/sim_node.h"
#include "scripted_agent.h"

namespace dream::sim {
namespace {

namespace fs = std::filesystem;

class RunRecorderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("dream_recorder_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(RunRecorderTest, LogAppearsOnlyWhenClosedAndHoldsEveryEvent) {
  const std::string path = (dir_ / "run.lcmlog").string();
  {
    RunRecorder recorder(path, 2);
    const char data[] = "abc";
    for (int i = 0; i < 5; ++i) recorder.Write("CH", 33000 * i, data, 3);
    EXPECT_FALSE(fs::exists(path));
    EXPECT_TRUE(fs::exists(path + ".part"));
    recorder.Close();
  }
  EXPECT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".part"));
  const auto records = lcm::LogReader::ReadAll(path);
  ASSERT_EQ(records.size(), 5u);
  EXPECT_EQ(records[4].utime, 4 * 33000);
}

TEST_F(RunRecorderTest, UnwritableFolderIsAClearError) {
  try {
    RunRecorder recorder((dir_ / "missing" / "run.lcmlog").string());
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing/run.lcmlog"), std::string::npos) << e.what();
  }
}

TEST_F(RunRecorderTest, SimNodeRecordsEveryStepInSimulatedTime) {
  lcm::LcmBus bus("memq://");
  UnicycleWorld world(WorldParams{}, {{0.0, 0.0, 0.0}, {0.5, 0.5, 1.0}});
  std::vector<std::unique_ptr<testing::ScriptedAgent>> agents;
  for (int id = 0; id < 2; ++id) {
    agents.push_back(std::make_unique<testing::ScriptedAgent>(
        bus, id, 10 + id, [](const robot_poses_t&, velocity_command_t* c) {
          c->v = 0.05;
          return true;
        }));
  }
  const std::string path = (dir_ / "run.lcmlog").string();
  SimNodeOptions options;
  options.max_steps = 20;
  options.progress_interval_s = 0;
  {
    RunRecorder recorder(path);
    SimNode node(bus, world, &recorder, options);
    std::atomic<bool> stop{false};
    ASSERT_TRUE(node.Run(stop).ok());
    recorder.Close();
  }
  int64_t expected_step = 0;
  int commands = 0;
  for (const lcm::LogRecord& record : lcm::LogReader::ReadAll(path)) {
    if (record.channel == "DREAM_POSES") {
      robot_poses_t poses;
      ASSERT_EQ(poses.decode(record.data.data(), 0, static_cast<int>(record.data.size())),
                static_cast<int>(record.data.size()));
      EXPECT_EQ(poses.step, expected_step);
      EXPECT_EQ(record.utime, 33000 * expected_step);
      ++expected_step;
    }
    if (record.channel.rfind("DREAM_CMD_", 0) == 0) ++commands;
  }
  EXPECT_EQ(expected_step, 21);  // steps 0..20: the final poses are recorded too
  EXPECT_EQ(commands, 2 * 20);
}

TEST_F(RunRecorderTest, AtomicFileReplacesWholeContent) {
  const std::string path = (dir_ / "summary.json").string();
  WriteFileAtomically(path, "first");
  WriteFileAtomically(path, "second");
  std::ifstream in(path);
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(content, "second");
  EXPECT_THROW(WriteFileAtomically((dir_ / "no" / "x.json").string(), "x"), std::runtime_error);
}

}  // namespace
}  // namespace dream::sim
