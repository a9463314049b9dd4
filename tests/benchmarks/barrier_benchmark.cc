// One barrier-certificate step (dream::barriers::UnicycleBarrier with rps's
// boundary defaults) at 2 to 50 robots: the budget is 200 us at 20 robots
// (issue 33; docs/performance.md). The robots stand on a circle of 0.7 m and
// drive at full speed towards the opposite side, so at the circle's centre
// every pair's constraint is close to binding, as in the thesis's circle swap;
// "crowded" takes the step where they are 0.05 m further in each time.
//   build/tests/benchmarks/barrier_benchmark --benchmark_repetitions=5
#include <cmath>

#include <benchmark/benchmark.h>

#include "dream/barriers/unicycle_barrier.h"

namespace dream::barriers {
namespace {

void CircleSwapState(int n, double radius_m, Eigen::Matrix3Xd* poses, Eigen::Matrix2Xd* commands) {
  poses->resize(3, n);
  commands->resize(2, n);
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * M_PI * i / n;
    (*poses)(0, i) = radius_m * std::cos(angle);
    (*poses)(1, i) = radius_m * std::sin(angle);
    (*poses)(2, i) = angle + M_PI + 0.3 * std::sin(3.0 * i);  // roughly inwards
    (*commands)(0, i) = 0.2;
    (*commands)(1, i) = 0.5 * std::cos(2.0 * i);
  }
}

void BM_UnicycleBarrierStep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const double radius_m = static_cast<double>(state.range(1)) / 100.0;
  Eigen::Matrix3Xd poses;
  Eigen::Matrix2Xd commands;
  CircleSwapState(n, radius_m, &poses, &commands);
  UnicycleBarrier barrier(UnicycleBarrierParams::RpsWithBoundary());
  int iterations = 0;
  bool failed = false;
  for (auto _ : state) {
    const BarrierResult result = barrier.Apply(commands, poses);
    iterations = result.qp_iterations;
    failed = result.qp_failed;
    benchmark::DoNotOptimize(result.commands.data());
  }
  state.counters["qp_iterations"] = iterations;
  state.counters["qp_failed"] = failed ? 1 : 0;
  state.SetLabel(std::to_string(n) + " robots on a " + std::to_string(radius_m) + " m circle");
}
BENCHMARK(BM_UnicycleBarrierStep)
    ->Args({2, 70})
    ->Args({10, 70})
    ->Args({20, 70})
    ->Args({20, 45})
    ->Args({50, 120})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace dream::barriers

BENCHMARK_MAIN();
