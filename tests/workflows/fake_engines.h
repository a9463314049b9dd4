#pragma once

#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "dream/workflows/command_runner.h"
#include "dream/workflows/job_runner.h"

namespace dream::workflows::testing {

/// A summary.json as dream run writes it (the fields the sweep reads).
inline nlohmann::json FinishedSummary(bool goal_met, long long completion_step, double min_distance_m) {
  return {{"end", "finished"},
          {"verdict", "clean"},
          {"steps", 40},
          {"violations",
           {{"boundary_errors", 0}, {"collision_errors", 0}, {"actuator_errors", 0}, {"obstacle_collisions", 0}}},
          {"metrics",
           {{"kind", "go_to_goal"},
            {"min_pairwise_distance_m", min_distance_m},
            {"goal",
             {{"met", goal_met},
              {"completion_step", completion_step},
              {"detail", goal_met ? "all arrived" : "not all"}}}}}};
}

/// `summary` with what dream run adds of its own where the test left it out:
/// the seed and name of the run folder's config, and a run id of its own.
inline nlohmann::json AsDreamRunWrites(const std::string& run_dir, nlohmann::json summary) {
  if (!summary.is_object()) return summary;
  const YAML::Node config = YAML::LoadFile(run_dir + "/config.yaml");
  if (!summary.contains("seed")) summary["seed"] = config["seed"].as<uint64_t>();
  if (!summary.contains("run")) summary["run"] = config["name"].as<std::string>();
  // Unique across the runners of one test (a resume's runs are new runs).
  static int next_run_id = 0;
  if (!summary.contains("run_id")) summary["run_id"] = "fa4e" + std::to_string(1000000 + next_run_id++);
  return summary;
}

/// The local engine without processes: each "run" writes the summary
/// `outcome` gives for its folder and "exits" with the code it gives.
class FakeJobRunner : public JobRunner {
 public:
  struct Outcome {
    int exit_code = 0;
    nlohmann::json summary;  ///< null: none written
  };
  using OutcomeFn = std::function<Outcome(const std::string& run_dir)>;

  FakeJobRunner(OutcomeFn outcome, std::vector<std::vector<std::string>>* started, size_t stop_after = SIZE_MAX)
      : outcome_(std::move(outcome)), started_(started), stop_after_(stop_after) {}

  bool Run(size_t count, const std::atomic<bool>& stop, const PrepareFn& prepare, const FinishedFn& finished) override {
    for (size_t i = 0; i < count; ++i) {
      if (stop.load() || i >= stop_after_) return false;
      const Job job = prepare(i);
      started_->push_back(job.argv);
      const std::string dir = job.argv.at(4);  // dream run CONFIG --out DIR
      const Outcome outcome = outcome_(dir);
      std::ofstream(job.output_path) << (outcome.exit_code == 0 ? "done\n" : "[12:00:00.000] [error] it broke\n");
      if (!outcome.summary.is_null())
        std::ofstream(dir + "/summary.json") << AsDreamRunWrites(dir, outcome.summary).dump();
      Finished done;
      done.index = i;
      done.exit_code = outcome.exit_code;
      done.wall_time_s = 1.0;
      finished(done);
    }
    return true;
  }

 private:
  OutcomeFn outcome_;
  std::vector<std::vector<std::string>>* started_;
  size_t stop_after_;
};

/// Slurm's client commands without a cluster: sbatch hands out job ids
/// from 100, squeue prints `queue`, sacct fails as on a cluster without
/// accounting, scontrol reports `max_array_size`.
class FakeSlurm : public CommandRunner {
 public:
  Result Run(const std::vector<std::string>& argv) override {
    calls.push_back(argv);
    const std::string& program = argv.at(0);
    if (program == "sbatch") {
      if (refuse_sbatch) return {1, "sbatch: error: Invalid partition name specified\n"};
      return {0, std::to_string(next_job++) + "\n"};
    }
    if (program == "squeue") return {0, queue};
    if (program == "sacct") return {1, "Slurm accounting storage is disabled\n"};
    if (program == "scontrol") return {0, "MaxArraySize            = " + std::to_string(max_array_size) + "\n"};
    return {-1, "no such program"};
  }
  std::vector<std::vector<std::string>> Sbatches() const {
    std::vector<std::vector<std::string>> found;
    for (const auto& call : calls) {
      if (call.at(0) == "sbatch") found.push_back(call);
    }
    return found;
  }

  std::vector<std::vector<std::string>> calls;
  std::string queue;
  int next_job = 100;
  size_t max_array_size = 1001;
  bool refuse_sbatch = false;
};

}  // namespace dream::workflows::testing
