#include "workflow_test_support.h"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "../bridge/bridge_test_support.h"
#include "dream/agent_host/agent_host.h"
#include "dream/bridge/submission_exporter.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/session/run_session.h"

namespace dream::workflows::testing {

const std::string& SimulatedRun() {
  static const std::string dir = [] {
    const std::string run_dir = bridge::testing::NewFolder("workflows_run");
    const std::string text = bridge::testing::ShippedConfig("go_to_goal");
    bridge::testing::WriteText(run_dir + "/config.yaml", text);
    std::ostream quiet(nullptr);
    session::RunSession::Options options;
    options.report = &quiet;
    session::RunSession session(bridge::testing::LoadConfigText(text, run_dir + "/config.yaml"), options);
    lcm::LcmBus bus("memq://");
    std::vector<std::unique_ptr<agents::RobotAgent>> robots;
    for (int id = 0; id < session.config().num_robots; ++id) robots.push_back(session.factory()->Make(id));
    agent_host::AgentHost host(bus, std::move(robots), 71);
    const session::RunResult result = session.Run(bus, {run_dir, text});
    EXPECT_TRUE(result.summary_written);
    EXPECT_EQ(result.judgement.verdict(), world::RunVerdict::kClean);
    return run_dir;
  }();
  return dir;
}

const std::string& SimulatedExport() {
  static const std::string dir = [] {
    const std::string export_dir = bridge::testing::NewFolder("workflows_export");
    bridge::ExportSubmission(SimulatedRun(), export_dir, bridge::ExportOptions{});
    return export_dir;
  }();
  return dir;
}

}  // namespace dream::workflows::testing
