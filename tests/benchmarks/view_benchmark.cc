// What dream view costs a run: the bus handler a run pays for on every step
// (BusFrameCollector::OnMessage for one step's DREAM_OBSTACLES, DREAM_STATUS
// and DREAM_POSES), and what the view's own thread does per frame it draws
// (TakeFrame and FrameJson, at most 30 a second). docs/performance.md.
//
//   build/tests/benchmarks/view_benchmark --benchmark_repetitions=5 --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "dream/lcm/lcm_bus.h"
#include "dream/obstacles_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/view/bus_frame_collector.h"
#include "dream/view/frame_json.h"
#include "../support/encoded_message.h"

namespace {

using dream::testing::Encoded;

dream::robot_poses_t PosesOf(int robots, int64_t step) {
  dream::robot_poses_t poses{};
  poses.run_id = 7;
  poses.step = step;
  poses.num_robots = robots;
  for (int i = 0; i < robots; ++i) {
    const double angle = 2 * M_PI * i / robots + 0.001 * static_cast<double>(step);
    poses.x.push_back(0.8 * std::cos(angle));
    poses.y.push_back(0.8 * std::sin(angle));
    poses.theta.push_back(angle + M_PI / 2);
    poses.v.push_back(0.1);
    poses.w.push_back(0.1);
  }
  return poses;
}

/// One lockstep step as the world publishes it, through the view's handler.
void BM_HandlerStep(benchmark::State& state) {
  const int robots = static_cast<int>(state.range(0));
  dream::lcm::LcmBus bus("memq://");
  dream::view::BusFrameCollector collector(bus, dream::world::WorldParams());
  dream::obstacles_t obstacles{};
  obstacles.run_id = 7;
  obstacles.num_obstacles = 2;
  obstacles.obstacles = {{0, 0.0, 0.0, 0.3, 0.2, 0.0, 0.0}, {1, -1.3, 0.9, 0.3, 0.1, 0.1, 0.0}};
  dream::run_status_t status{};
  status.run_id = 7;
  status.state = dream::run_status_t::RUNNING;
  status.num_robots = robots;
  status.detail = "running";
  std::vector<std::vector<uint8_t>> steps[3];
  for (int64_t step = 0; step < 64; ++step) {
    obstacles.step = status.step = step;
    steps[0].push_back(Encoded(obstacles));
    steps[1].push_back(Encoded(status));
    steps[2].push_back(Encoded(PosesOf(robots, step)));
  }
  size_t k = 0;
  for (auto _ : state) {
    collector.OnMessage("DREAM_OBSTACLES", steps[0][k].data(), static_cast<int>(steps[0][k].size()));
    collector.OnMessage("DREAM_STATUS", steps[1][k].data(), static_cast<int>(steps[1][k].size()));
    collector.OnMessage("DREAM_POSES", steps[2][k].data(), static_cast<int>(steps[2][k].size()));
    k = (k + 1) % steps[0].size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_HandlerStep)->Arg(20)->Arg(50);

/// What the view's thread does for one frame: take the newest state and write its JSON.
void BM_FrameJson(benchmark::State& state) {
  const int robots = static_cast<int>(state.range(0));
  const dream::robot_poses_t poses = PosesOf(robots, 10);
  dream::view::ViewFrame frame;
  frame.run_id = 7;
  frame.step = 10;
  frame.x_m = poses.x;
  frame.y_m = poses.y;
  frame.theta_rad = poses.theta;
  frame.obstacles.push_back({0, 0.0, 0.0, 0.3, 0.2, 0.0, 0.0});
  frame.status.seen = true;
  size_t bytes = 0;
  for (auto _ : state) {
    const std::string json = dream::view::FrameJson(frame);
    bytes = json.size();
    benchmark::DoNotOptimize(json.data());
  }
  state.counters["frame_bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_FrameJson)->Arg(20)->Arg(50)->Arg(100);

}  // namespace

BENCHMARK_MAIN();
