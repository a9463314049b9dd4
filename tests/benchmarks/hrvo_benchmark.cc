// SafeVelocity CPU time of HrvoThesis and HrvoExact with 1, 5 and 9
// neighbours (a 10-robot swarm's worst case). The situations are those of
// the circle swap's crowded middle: neighbours all round within 1 m, every
// one of them moving, the preferred velocity blocked.
//
//   build/tests/benchmarks/hrvo_benchmark --benchmark_repetitions=5
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "dream/agents/hrvo/hrvo_exact.h"
#include "dream/agents/hrvo/hrvo_thesis.h"

namespace dream::agents {
namespace {

struct Situation {
  Eigen::Vector2d position;
  Eigen::Vector2d current;
  Eigen::Vector2d preferred;
  std::vector<HrvoNeighbour> neighbours;
};

// 64 seeded situations per neighbour count, cycled through.
std::vector<Situation> MakeSituations(int num_neighbours) {
  std::mt19937_64 rng(static_cast<uint64_t>(num_neighbours));
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Situation> out;
  for (int k = 0; k < 64; ++k) {
    Situation s;
    s.position = {0.3 * unit(rng), 0.3 * unit(rng)};
    const double heading = M_PI * unit(rng);
    s.preferred = 0.2 * Eigen::Vector2d(std::cos(heading), std::sin(heading));
    s.current = 0.15 * Eigen::Vector2d(std::cos(heading + 0.3 * unit(rng)), std::sin(heading + 0.3 * unit(rng)));
    for (int i = 0; i < num_neighbours; ++i) {
      // The first neighbour sits ahead, so the preferred velocity is blocked.
      const double bearing = i == 0 ? heading + 0.1 * unit(rng) : M_PI * unit(rng);
      const double distance = 0.3 + 0.65 * std::abs(unit(rng));
      s.neighbours.push_back({distance * Eigen::Vector2d(std::cos(bearing), std::sin(bearing)),
                              0.15 * Eigen::Vector2d(unit(rng), unit(rng))});
    }
    out.push_back(std::move(s));
  }
  return out;
}

template <typename Hrvo>
void BM_SafeVelocity(benchmark::State& state) {
  const std::vector<Situation> situations = MakeSituations(static_cast<int>(state.range(0)));
  Hrvo hrvo;
  size_t k = 0;
  for (auto _ : state) {
    const Situation& s = situations[k];
    benchmark::DoNotOptimize(hrvo.SafeVelocity(s.position, s.current, s.preferred, s.neighbours));
    k = (k + 1) % situations.size();
  }
}

BENCHMARK_TEMPLATE(BM_SafeVelocity, HrvoThesis)->Arg(1)->Arg(5)->Arg(9);
BENCHMARK_TEMPLATE(BM_SafeVelocity, HrvoExact)->Arg(1)->Arg(5)->Arg(9);

}  // namespace
}  // namespace dream::agents

BENCHMARK_MAIN();
