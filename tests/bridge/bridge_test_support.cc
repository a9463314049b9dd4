#include "bridge_test_support.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "dream/agent_host/agent_host.h"
#include "dream/agent_host/controller_factory.h"
#include "dream/bridge/submission_format.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/node/run_recorder.h"
#include "dream/node/sim_node.h"
#include "dream/world/unicycle_world.h"
#include "../support/source_tree.h"

namespace dream::bridge::testing {

namespace fs = std::filesystem;

std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

namespace {

/// This process's folder; removed at exit unless DREAM_TEST_KEEP=1.
struct ProcessFolder {
  fs::path path = fs::path(::testing::TempDir()) / ("dream_bridge_" + std::to_string(::getpid()));
  ~ProcessFolder() {
    const char* keep = std::getenv("DREAM_TEST_KEEP");
    std::error_code ignored;
    if (keep == nullptr || std::string(keep) != "1") fs::remove_all(path, ignored);
  }
};

}  // namespace

std::string NewFolder(const std::string& name) {
  // ctest runs each test case in its own process, in parallel: one folder set per process.
  static const ProcessFolder process_folder;
  const fs::path dir = process_folder.path / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string ShippedConfig(const std::string& name) {
  return ReadText(dream::testing::SourceDir() + "/config/" + name + ".yaml");
}

run_config::RunConfig LoadConfigText(const std::string& text, const std::string& source) {
  return run_config::LoadRunConfig(config::ConfigNode::LoadString(text, source));
}

node::RunOutcome RunAgainst(world::World& world, const run_config::RunConfig& config, const std::string& log_path) {
  lcm::LcmBus bus("memq://");
  const agent_host::ControllerFactory factory(config.controller, config.num_robots, config.seed);
  std::vector<std::unique_ptr<agents::RobotAgent>> robots;
  for (int id = 0; id < config.num_robots; ++id) robots.push_back(factory.Make(id));
  agent_host::AgentHost host(bus, std::move(robots), 7);
  config::SimNodeOptions options = config.sim;
  options.progress_interval_s = 0.0;
  node::RunRecorder recorder(log_path);
  node::SimNode node(bus, world, &recorder, options);
  const std::atomic<bool> stop{false};
  node::RunOutcome outcome = node.Run(stop);
  recorder.Close();
  return outcome;
}

std::string MakeRunFolder(const std::string& name, const std::string& config_text) {
  const std::string dir = NewFolder(name);
  const run_config::RunConfig config = LoadConfigText(config_text, dir + "/config.yaml");
  WriteText(dir + "/config.yaml", config_text);
  world::UnicycleWorld world(config.world, config.initial_poses, config.obstacles);
  const node::RunOutcome outcome = RunAgainst(world, config, dir + "/run.lcmlog");
  EXPECT_EQ(outcome.end, node::RunOutcome::End::kFinished) << outcome.reason;
  return dir;
}

formats::NpyArray PerfectLabResult(const std::string& export_dir,
                                   const std::function<void(int64_t, double*)>& perturb) {
  const std::string upload = export_dir + "/upload/";
  const formats::NpyArray poses = formats::ReadNpyFile(upload + SubmissionFiles::kReferencePoses);
  const formats::NpyArray commands = formats::ReadNpyFile(upload + SubmissionFiles::kReferenceCommands);
  const int64_t steps = commands.shape[0];
  const int64_t n = commands.shape[2];
  formats::NpyArray rows;
  const int64_t columns = ResultLayout::Columns(static_cast<int>(n));
  rows.shape = {steps + 1, columns};
  rows.values.assign(static_cast<size_t>((steps + 1) * columns), 0.0);
  for (int64_t k = 0; k <= steps; ++k) {
    double* row = &rows.values[static_cast<size_t>(k * columns)];
    row[ResultLayout::kPhaseColumn] = k < steps ? ResultLayout::kPhaseExperiment : ResultLayout::kPhaseFinal;
    row[ResultLayout::kStepColumn] = static_cast<double>(k);
    row[ResultLayout::kWallTimeColumn] = 1.7e9 + 0.033 * static_cast<double>(k);
    for (int64_t q = 0; q < 3 * n; ++q)
      row[ResultLayout::kFixedColumns + q] = poses.values[static_cast<size_t>(k * 3 * n + q)];
    if (k < steps) {
      for (int64_t q = 0; q < 2 * n; ++q) {
        row[ResultLayout::kFixedColumns + 3 * n + q] = commands.values[static_cast<size_t>(k * 2 * n + q)];
      }
    }
    if (perturb) perturb(k, row);
  }
  return rows;
}

std::vector<std::string> FilesIn(const std::string& dir) {
  std::vector<std::string> names;
  if (!fs::exists(dir)) return names;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    names.push_back(fs::relative(entry.path(), dir).string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace dream::bridge::testing
