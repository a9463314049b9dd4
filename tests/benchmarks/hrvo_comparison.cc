// Side-by-side comparison of HrvoThesis (the thesis's sampled HRVO) and
// HrvoExact, closed loop in the Robotarium-faithful world: the thesis's HRVO
// experiment (10 robots on a 0.85 m circle swap to the antipodal points,
// start poses perturbed per seed) and random crossings of 12 robots. Prints
// Markdown tables (docs/hrvo.md).
//
//   build/tests/benchmarks/hrvo_comparison [seeds=20]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "../agents/hrvo_swap_harness.h"
#include "dream/agents/hrvo/hrvo_exact.h"
#include "dream/agents/hrvo/hrvo_thesis.h"

namespace dream::agents {
namespace {

struct Row {
  int runs = 0;
  int completed = 0;
  double sum_steps = 0.0;
  int64_t max_steps = 0;
  int64_t collisions = 0;
  int64_t boundary = 0;
  int64_t near_miss_steps = 0;
  int runs_with_near_miss = 0;
  double min_distance = 1e9;
  double sum_ns = 0.0;
};

struct Variant {
  const char* name;
  HrvoFactory make;
};

using Problem = std::function<void(uint64_t seed, std::vector<world::Pose2>*, std::vector<Eigen::Vector2d>*)>;

void Table(const char* title, const Problem& problem, const std::vector<Variant>& variants, int seeds) {
  std::printf("%s, %d seeds\n\n", title, seeds);
  std::printf(
      "| variant | timing | completed | mean steps | max steps | collisions | boundary errors |"
      " near-miss steps (<0.2 m): total (runs with any) | min centre distance, m | CPU per call, us |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const bool thesis_timing : {false, true}) {
    for (const Variant& v : variants) {
      Row row;
      for (int seed = 1; seed <= seeds; ++seed) {
        std::vector<world::Pose2> start;
        std::vector<Eigen::Vector2d> goals;
        problem(static_cast<uint64_t>(seed), &start, &goals);
        HrvoSwapOptions options;
        options.thesis_timing = thesis_timing;
        const HrvoSwapResult r = RunHrvoSwap(start, goals, v.make, options);
        ++row.runs;
        if (r.completed) {
          ++row.completed;
          row.sum_steps += static_cast<double>(r.completion_steps);
          row.max_steps = std::max(row.max_steps, r.completion_steps);
        }
        row.collisions += r.collision_errors;
        row.boundary += r.boundary_errors;
        row.near_miss_steps += r.near_miss_steps;
        if (r.near_miss_steps > 0) ++row.runs_with_near_miss;
        row.min_distance = std::min(row.min_distance, r.min_distance_m);
        row.sum_ns += r.ns_per_call;
      }
      std::printf("| %s | %s | %d/%d | %.0f | %lld | %lld | %lld | %lld (%d) | %.3f | %.2f |\n", v.name,
                  thesis_timing ? "thesis timers" : "every step", row.completed, row.runs,
                  row.completed > 0 ? row.sum_steps / row.completed : 0.0, static_cast<long long>(row.max_steps),
                  static_cast<long long>(row.collisions), static_cast<long long>(row.boundary),
                  static_cast<long long>(row.near_miss_steps), row.runs_with_near_miss, row.min_distance,
                  row.sum_ns / row.runs / 1000.0);
    }
  }
  std::printf("\n");
}

int Main(int argc, char** argv) {
  const int seeds = argc > 1 ? std::atoi(argv[1]) : 20;
  // HrvoExact without its keep-right rule: the plain nearest safe velocity.
  HrvoExactTuning plain;
  plain.keep_right_rad = 0.0;
  const std::vector<Variant> variants = {
      {"HrvoThesis", [] { return std::make_unique<HrvoThesis>(); }},
      {"HrvoExact", [] { return std::make_unique<HrvoExact>(); }},
      {"HrvoExact, keep_right_rad = 0", [plain] { return std::make_unique<HrvoExact>(HrvoParams{}, plain); }},
  };
  Table(
      "10-robot circle swap (radius 0.85 m, start jitter +/-0.03 m, +/-0.3 rad)",
      [](uint64_t seed, std::vector<world::Pose2>* start, std::vector<Eigen::Vector2d>* goals) {
        *start = CirclePoses(10, 0.85, 0.03, 0.3, seed);
        *goals = AntipodalGoals(10, 0.85);
      },
      variants, seeds);
  Table(
      "12-robot random crossings (starts and goals >= 0.35 m apart)",
      [](uint64_t seed, std::vector<world::Pose2>* start, std::vector<Eigen::Vector2d>* goals) {
        RandomCrossing(12, seed, start, goals);
      },
      variants, seeds);
  return 0;
}

}  // namespace
}  // namespace dream::agents

int main(int argc, char** argv) { return dream::agents::Main(argc, argv); }
