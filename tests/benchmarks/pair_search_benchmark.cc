// The world's fixed-radius pair search (CollisionGrid: every pair of robots
// within the collision diameter, each step) against nanoflann's kd-tree doing
// the same, on the same points. nanoflann is the Debian library for
// neighbour search; this is the measurement behind keeping the grid
// (docs/dependencies.md). The nanoflann half is built only where its header
// is installed (apt-get install libnanoflann-dev); the project needs it nowhere else.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "collision_grid.h"  // sim/world/src: the world's own, not a public header
#include "dream/world/arena.h"
#include "dream/robotarium/robotarium_constants.h"
#include "dream/world/step_events.h"

#if __has_include(<nanoflann.hpp>)
#include <nanoflann.hpp>
#define DREAM_HAVE_NANOFLANN 1
#endif

namespace dream::world {
namespace {

// Uniform points at the density of 50 robots in the Robotarium's arena (the
// arena grows with the count, as in world_benchmark).
struct PointCloud {
  Arena arena;
  std::vector<double> x_m;
  std::vector<double> y_m;

  // nanoflann's dataset interface.
  std::size_t kdtree_get_point_count() const { return x_m.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const { return dim == 0 ? x_m[i] : y_m[i]; }
  template <typename Box>
  bool kdtree_get_bbox(Box& /*box*/) const {
    return false;
  }
};

PointCloud UniformPoints(int64_t count) {
  const double scale = std::sqrt(static_cast<double>(count) / 50.0);
  PointCloud cloud;
  cloud.arena = Arena{-1.6 * scale, 1.6 * scale, -1.0 * scale, 1.0 * scale};
  std::mt19937 random(1);
  std::uniform_real_distribution<double> x(cloud.arena.x_min_m, cloud.arena.x_max_m);
  std::uniform_real_distribution<double> y(cloud.arena.y_min_m, cloud.arena.y_max_m);
  for (int64_t i = 0; i < count; ++i) {
    cloud.x_m.push_back(x(random));
    cloud.y_m.push_back(y(random));
  }
  return cloud;
}

constexpr double kDistanceM = robotarium::RobotariumConstants::kCollisionDiameterMeters;

void BM_CollisionGrid(benchmark::State& state) {
  const PointCloud cloud = UniformPoints(state.range(0));
  CollisionGrid grid(cloud.x_m.size(), kDistanceM, cloud.arena);
  std::vector<StepEvents::RobotPair> pairs;
  for (auto _ : state) {
    pairs.clear();
    grid.FindPairs(cloud.x_m.data(), cloud.y_m.data(), &pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs.size());
}
BENCHMARK(BM_CollisionGrid)->Arg(50)->Arg(1000)->Arg(10000);

#ifdef DREAM_HAVE_NANOFLANN
// Robots move every step, so the tree is built every step, then one radius
// query per robot keeps the partners after it (each pair once).
void BM_NanoflannKdTree(benchmark::State& state) {
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>, PointCloud, 2>;
  const PointCloud cloud = UniformPoints(state.range(0));
  std::vector<StepEvents::RobotPair> pairs;
  std::vector<std::pair<uint32_t, double>> found;
  nanoflann::SearchParams search;
  search.sorted = false;
  for (auto _ : state) {
    pairs.clear();
    Tree tree(2, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    for (std::size_t i = 0; i < cloud.x_m.size(); ++i) {
      const double query[2] = {cloud.x_m[i], cloud.y_m[i]};
      found.clear();
      tree.radiusSearch(query, kDistanceM * kDistanceM, found, search);  // squared for L2_Simple
      for (const auto& [j, squared_m2] : found) {
        if (j > i) pairs.push_back({static_cast<int>(i), static_cast<int>(j)});
      }
    }
    benchmark::DoNotOptimize(pairs.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs.size());
}
BENCHMARK(BM_NanoflannKdTree)->Arg(50)->Arg(1000)->Arg(10000);
#endif

}  // namespace
}  // namespace dream::world

BENCHMARK_MAIN();
