#pragma once
// The fixture of the whole-sweep tests (sweep_workflow_test.cc, sweep_hostile_test.cc): a base
// config in a scratch folder, a sweep of 2 seeds x 2 speeds, a fake job runner and a fake Slurm.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "../support/scratch_folder.h"
#include "dream/config/config_node.h"
#include "dream/run_config/run_config.h"
#include "dream/workflows/sweep_workflow.h"
#include "fake_engines.h"

namespace dream::workflows::testing {

namespace fs = std::filesystem;
inline const char* kBase = R"(name: demo
seed: 1
robots: 2
steps: 40
initial_poses: [[0.5, 0, 3.14], [-0.5, 0, 0]]
controller:
  kind: go_to_goal
  max_speed_mps: 0.15
  goals: [[0.2, 0.2], [-0.2, -0.2]]
)";

inline std::string ReadText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

class SweepWorkflowTest : public ::testing::Test {
 protected:
  SweepWorkflowTest() : scratch_("sweep_workflow") {
    std::ofstream(scratch_.path() / "base.yaml") << kBase;
    settings_.config_path = (scratch_.path() / "base.yaml").string();
    settings_.seeds = "1-2";
    settings_.sets = {"controller.max_speed_mps=0.1,0.2"};
    settings_.out_dir = out().string();
  }

  fs::path out() const { return scratch_.path() / "sweep"; }
  run_config::RunConfig Base() const {
    return run_config::LoadRunConfig(config::ConfigNode::LoadFile(settings_.config_path));
  }

  /// A workflow whose local runs end as `outcome` says.
  SweepWorkflow Workflow(FakeJobRunner::OutcomeFn outcome = nullptr, size_t stop_after = SIZE_MAX) {
    if (!outcome)
      outcome = [](const std::string&) { return FakeJobRunner::Outcome{0, FinishedSummary(true, 30, 0.3)}; };
    SweepWorkflow::Environment env;
    env.make_job_runner = [this, outcome, stop_after](int jobs, double) -> std::unique_ptr<JobRunner> {
      jobs_asked_ = jobs;
      return std::make_unique<FakeJobRunner>(outcome, &started_, stop_after);
    };
    env.commands = &slurm_;
    env.out = &printed_;
    env.dream_path = "/opt/dream/bin/dream";
    env.cores = 2;
    return SweepWorkflow(std::move(env));
  }

  dream::testing::ScratchFolder scratch_;
  SweepSettings settings_;
  FakeSlurm slurm_;
  std::vector<std::vector<std::string>> started_;
  std::ostringstream printed_;
  int jobs_asked_ = 0;
};

}  // namespace dream::workflows::testing
