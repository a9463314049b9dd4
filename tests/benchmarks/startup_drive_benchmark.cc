// The Robotarium's start-up drive in C++ (world::StartupDrive): one whole drive
// from a random charger placement onto start poses spread as the shipped
// configs' are (10, 15 and 20 robots at least 0.4 m apart; the 20 at 0.35 m),
// and the five placements `dream run` tries (StartupDriveTrials). Reported in
// docs/performance.md.
//   build/tests/benchmarks/startup_drive_benchmark --benchmark_repetitions=3
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "dream/run_config/startup_drive_cache.h"
#include "dream/world/initial_pose_generator.h"
#include "dream/world/startup_drive.h"
#include "dream/world/startup_drive_trials.h"

namespace dream::world {
namespace {

std::vector<Pose2> SpreadPoses(int n) {
  InitialPoseParams params;
  params.min_spacing_m = n >= 20 ? 0.35 : 0.4;
  params.wall_margin_m = 0.15;
  return InitialPoseGenerator(WorldParams{}, params).Generate(n, 5);
}

void BM_StartupDrive(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const StartupDrive drive(WorldParams{}, SpreadPoses(n));
  StartupDriveResult result;
  for (auto _ : state) {
    result = drive.Run(7);
    benchmark::DoNotOptimize(result.final_poses.data());
  }
  state.counters["steps"] = result.steps;
  state.counters["settled"] = result.settled ? 1 : 0;
}
BENCHMARK(BM_StartupDrive)->Arg(10)->Arg(15)->Arg(20)->Unit(benchmark::kMillisecond);

void BM_StartupDriveTrials(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const std::vector<Pose2> poses = SpreadPoses(n);
  int settled = 0;
  for (auto _ : state) {
    const StartupDriveTrials trials = StartupDriveTrials::Try(WorldParams{}, poses, 7);
    settled = trials.settled();
    benchmark::DoNotOptimize(settled);
  }
  state.counters["settled"] = settled;
}
BENCHMARK(BM_StartupDriveTrials)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);

// Issue 33 item 3: what a repeat `dream run` or `export` of the same start poses and seed pays
// once the first stored its five placements (run_config::StartupDriveCache): a file read.
void BM_StartupDriveTrialsCached(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const std::vector<Pose2> poses = SpreadPoses(n);
  const std::string folder =
      (std::filesystem::temp_directory_path() / ("dream_startup_drive_benchmark_" + std::to_string(::getpid())))
          .string();
  const run_config::StartupDriveCache cache(folder);
  (void)cache.Trials(WorldParams{}, poses, 7);  // the first run: drives and stores
  int settled = 0;
  for (auto _ : state) {
    settled = cache.Trials(WorldParams{}, poses, 7).settled();
    benchmark::DoNotOptimize(settled);
  }
  state.counters["settled"] = settled;
  std::filesystem::remove_all(folder);
}
BENCHMARK(BM_StartupDriveTrialsCached)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace dream::world

BENCHMARK_MAIN();
