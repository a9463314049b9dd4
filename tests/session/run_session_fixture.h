#pragma once
// What the RunSession tests share: a fresh folder per test with a config of
// the counting plugin's kind (counting_plugin.cc), and a run with its agents
// on one memq bus, as dream run.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "../support/scratch_folder.h"
#include "dream/agent_host/agent_host.h"
#include "dream/files/file_text.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/session/run_session.h"

namespace dream::session {

// A fresh folder per test, holding the config and the run folder "out".
class RunSessionTest : public ::testing::Test {
 protected:
  void SetUp() override { std::filesystem::create_directories(dir_ / "out"); }

  // Two robots of the counting plugin's kind; `x_m` is robot 0's start.
  // `world_extra`: more keys of world: (", realism: lab").
  std::string WriteConfig(double speed_mps, double x_m, int steps, double start_timeout_s = 10.0,
                          const std::string& world_extra = "") {
    std::ostringstream yaml;
    yaml << "name: session_test\nseed: 3\nrobots: 2\nsteps: " << steps << "\nstop_when_done: false\n"
         << "world: {mode: lockstep, start_timeout_s: " << start_timeout_s << world_extra << "}\n"
         << "plugins: [" << SESSION_TEST_PLUGIN_PATH << "]\n"
         << "initial_poses:\n  - [" << x_m << ", 0.0, 0.0]\n  - [-1.0, 0.5, 0.0]\n"
         << "controller: {kind: session_test_drive, speed_mps: " << speed_mps << "}\n";
    const std::filesystem::path path = dir_ / "config.yaml";
    std::ofstream(path) << yaml.str();
    return path.string();
  }

  // How many factories the plugin's kind was built for, in this whole process.
  static int FactoriesBuilt() { return PluginCount("session_test_factories_built"); }
  // How many robots (agents) the plugin's kind made, in this whole process.
  static int RobotsMade() { return PluginCount("session_test_robots_made"); }

  // A count the plugin keeps (0 when it is not loaded: nothing counted, -1 without the symbol).
  static int PluginCount(const char* symbol) {
    void* plugin = dlopen(SESSION_TEST_PLUGIN_PATH, RTLD_NOW | RTLD_NOLOAD);
    if (plugin == nullptr) return 0;
    const auto count = reinterpret_cast<int (*)()>(dlsym(plugin, symbol));
    const int counted = count != nullptr ? count() : -1;
    dlclose(plugin);
    return counted;
  }

  // Every robot's agent of `session` on `bus`, as dream run hosts them.
  static std::unique_ptr<agent_host::AgentHost> HostAgents(RunSession& session, lcm::LcmBus& bus) {
    std::vector<std::unique_ptr<agents::RobotAgent>> robots;
    for (int id = 0; id < session.config().num_robots; ++id) robots.push_back(session.factory()->Make(id));
    return std::make_unique<agent_host::AgentHost>(bus, std::move(robots), 77);
  }

  // Runs `session` with every robot's agent on the same memq bus (as dream run).
  RunResult RunWithAgents(RunSession& session) {
    lcm::LcmBus bus("memq://");
    const std::unique_ptr<agent_host::AgentHost> host = HostAgents(session, bus);
    return session.Run(bus, {out(), "the folder's config\n"});
  }

  std::string out() const { return (dir_ / "out").string(); }
  nlohmann::json Summary() const { return nlohmann::json::parse(files::ReadFileText(out() + "/summary.json")); }

  dream::testing::ScratchFolder folder_{"dream_run_session_test"};
  const std::filesystem::path dir_ = folder_.path();
  std::ostringstream report_;
};

}  // namespace dream::session
