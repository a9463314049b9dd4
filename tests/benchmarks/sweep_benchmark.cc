// dream sweep's overhead at scale (issue 26, docs/performance.md): planning
// and writing a Slurm submission of 10,000 runs (every run's config
// generated, checked as dream run checks it, and written; the plan, run.sh
// and job scripts; sbatch replaced by a stand-in that hands out job ids),
// and `dream sweep table` over 10,000 finished runs. Targets: under 10 s and
// under 5 s. Run: build/tests/benchmarks/sweep_benchmark
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "dream/config/config_node.h"
#include "dream/run_config/run_config.h"
#include "dream/workflows/sweep_folder.h"
#include "dream/workflows/sweep_workflow.h"
#include "../support/source_tree.h"

namespace {

namespace fs = std::filesystem;
using dream::workflows::CommandRunner;
using dream::workflows::SweepFolder;
using dream::workflows::SweepSettings;
using dream::workflows::SweepWorkflow;

const char* kBase = R"(name: bench
seed: 1
robots: 10
steps: 2000
initial_poses: {generate: {min_spacing_m: 0.3}}
controller:
  kind: hrvo_circle
)";

/// sbatch, scontrol, squeue, sacct without a cluster: job ids, nothing queued.
class StandInSlurm : public CommandRunner {
 public:
  Result Run(const std::vector<std::string>& argv) override {
    if (argv.at(0) == "sbatch") return {0, std::to_string(next_++) + "\n"};
    if (argv.at(0) == "scontrol") return {0, "MaxArraySize = 100001\n"};
    if (argv.at(0) == "squeue") return {0, ""};
    return {1, "Slurm accounting storage is disabled\n"};
  }

 private:
  int next_ = 1000;
};

fs::path Scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("sweep_benchmark_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

SweepWorkflow Workflow(StandInSlurm& slurm) {
  SweepWorkflow::Environment env;
  env.commands = &slurm;
  env.dream_path = "/opt/dream/bin/dream";
  return SweepWorkflow(std::move(env));
}

/// 100 seeds x 100 values: the 10,000-run sweep of the issue.
SweepSettings TenThousandRuns(const fs::path& dir) {
  std::ofstream(dir / "base.yaml") << kBase;
  SweepSettings settings;
  settings.config_path = (dir / "base.yaml").string();
  settings.seeds = "1-100";
  std::string speeds;
  for (int i = 1; i <= 100; ++i) speeds += (i > 1 ? "," : "") + std::to_string(0.1 + 0.001 * i);
  settings.sets = {"controller.max_speed_mps=" + speeds};
  settings.engine = SweepSettings::Engine::kSlurm;
  settings.jobs = 64;
  return settings;
}

void BM_PlanAndSubmit10000Runs(benchmark::State& state) {
  const fs::path dir = Scratch("submit");
  SweepSettings settings = TenThousandRuns(dir);
  const dream::run_config::RunConfig base =
      dream::run_config::LoadRunConfig(dream::config::ConfigNode::LoadFile(settings.config_path));
  int attempt = 0;
  for (auto _ : state) {
    settings.out_dir = (dir / ("sweep" + std::to_string(attempt++))).string();
    StandInSlurm slurm;
    const auto outcome = Workflow(slurm).Start(settings, base);
    benchmark::DoNotOptimize(outcome.runs);
  }
  fs::remove_all(dir);
}
BENCHMARK(BM_PlanAndSubmit10000Runs)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

/// 10,000 seeds of a shipped config, planned (--engine plan): every run's
/// config generated from the whole file, checked and written (issue 37: under
/// 10 s for any shipped config). Argument: the config's file in config/.
void BM_PlanShippedConfig10000Seeds(benchmark::State& state, const std::string& config_file) {
  const fs::path dir = Scratch("shipped");
  SweepSettings settings;
  settings.config_path = dream::testing::SourceDir() + "/config/" + config_file;
  settings.seeds = "1-10000";
  settings.engine = SweepSettings::Engine::kPlan;
  const dream::run_config::RunConfig base =
      dream::run_config::LoadRunConfig(dream::config::ConfigNode::LoadFile(settings.config_path));
  int attempt = 0;
  for (auto _ : state) {
    settings.out_dir = (dir / ("sweep" + std::to_string(attempt++))).string();
    StandInSlurm never_called;
    const auto outcome = Workflow(never_called).Start(settings, base);
    benchmark::DoNotOptimize(outcome.runs);
  }
  fs::remove_all(dir);
}
BENCHMARK_CAPTURE(BM_PlanShippedConfig10000Seeds, hrvo_circle, std::string("hrvo_circle.yaml"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(BM_PlanShippedConfig10000Seeds, voronoi_coverage, std::string("voronoi_coverage.yaml"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

void BM_Table10000FinishedRuns(benchmark::State& state) {
  const fs::path dir = Scratch("table");
  SweepSettings settings = TenThousandRuns(dir);
  settings.out_dir = (dir / "sweep").string();
  const dream::run_config::RunConfig base =
      dream::run_config::LoadRunConfig(dream::config::ConfigNode::LoadFile(settings.config_path));
  StandInSlurm slurm;
  Workflow(slurm).Start(settings, base);
  // Every run finished: its exit record and a summary.json as dream run writes it.
  std::ifstream in(dream::testing::SourceDir() + "/tests/data/sweep_run_summary.json");
  std::stringstream summary;
  summary << in.rdbuf();
  const SweepFolder folder(settings.out_dir);
  const dream::workflows::SweepPlan plan = folder.ReadPlan();
  for (const auto& run : plan.runs()) {
    std::ofstream(folder.RunDir(run.name) + "/summary.json") << summary.str();
    folder.WriteRunExit(run.name, {0, 1.5, false, ""});
  }
  for (auto _ : state) {
    const auto outcome = Workflow(slurm).Table(settings.out_dir);
    if (outcome.summary.ran != 10000) state.SkipWithError("not every run was read as finished");
  }
  fs::remove_all(dir);
}
BENCHMARK(BM_Table10000FinishedRuns)->Unit(benchmark::kSecond)->Iterations(1)->Repetitions(3)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
