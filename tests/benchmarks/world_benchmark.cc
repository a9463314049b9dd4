// UnicycleWorld::Step cost at 20, 50, 1,000 and 10,000 robots. Large worlds use
// an arena scaled so the density stays that of 50 robots in the Robotarium's
// 3.2 x 2 m (the simulator's maximum), every robot drives a small circle
// (so the crowd stays put and keeps interacting) with some commands over the
// wheel limit, and one robot in ten has a partner 0.1 m away driving the same
// circle, so the collision path reports pairs at every step.
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "dream/world/initial_pose_generator.h"
#include "dream/world/realistic_world.h"
#include "dream/world/unicycle_world.h"

namespace dream::world {
namespace {

UnicycleWorld MakeBusyWorld(int num_robots) {
  WorldParams params;
  const double scale = std::sqrt(static_cast<double>(num_robots) / 50.0);
  if (scale > 1.0) {
    params.arena = Arena{-1.6 * scale, 1.6 * scale, -1.0 * scale, 1.0 * scale};
  }
  const int num_leaders = num_robots - num_robots / 10;
  InitialPoseParams pose_params;
  pose_params.min_spacing_m = 0.25;
  std::vector<Pose2> poses = InitialPoseGenerator(params, pose_params).Generate(num_leaders, 1);
  const std::size_t num_partners = static_cast<std::size_t>(num_robots - num_leaders);
  for (std::size_t i = 0; i < num_partners; ++i) {
    Pose2 partner = poses[i];
    partner.x_m += 0.1;
    poses.push_back(partner);
  }
  UnicycleWorld world(params, poses);
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> speed(0.02, 0.22);  // a few over the limit
  std::uniform_real_distribution<double> turn(-4.0, 4.0);
  for (int i = 0; i < num_leaders; ++i) {
    const UnicycleCommand command{speed(rng), turn(rng)};
    world.SetCommand(i, command);
    if (static_cast<std::size_t>(i) < num_partners) world.SetCommand(num_leaders + i, command);
  }
  return world;
}

void BM_UnicycleWorldStep(benchmark::State& state) {
  UnicycleWorld world = MakeBusyWorld(static_cast<int>(state.range(0)));
  // Keep commands fresh so the 0.5 s timeout never stops the robots.
  std::vector<UnicycleCommand> commands = world.velocities();
  int64_t colliding_pairs = 0;
  for (auto _ : state) {
    if (world.step() % 10 == 0) {
      state.PauseTiming();
      for (int i = 0; i < world.num_robots(); ++i) world.SetCommand(i, commands[static_cast<std::size_t>(i)]);
      state.ResumeTiming();
    }
    world.Step();
    colliding_pairs += static_cast<int64_t>(world.last_step_events().colliding_pairs.size());
    benchmark::DoNotOptimize(world.poses().data());
  }
  state.counters["robots"] = static_cast<double>(world.num_robots());
  state.counters["pairs_per_step"] =
      static_cast<double>(colliding_pairs) / static_cast<double>(std::max<int64_t>(state.iterations(), 1));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_UnicycleWorldStep)->Arg(20)->Arg(50)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

// Start poses for 10,000 robots in a 50 m x 40 m arena (InitialPoseGeneratorTest checks them; target under 2 s).
void BM_InitialPoses(benchmark::State& state) {
  WorldParams params;
  params.arena = Arena{-25.0, 25.0, -20.0, 20.0};
  for (auto _ : state) {
    const std::vector<Pose2> poses =
        InitialPoseGenerator(params, InitialPoseParams{}).Generate(static_cast<int>(state.range(0)), 5);
    benchmark::DoNotOptimize(poses.data());
  }
}
BENCHMARK(BM_InitialPoses)->Arg(10000)->Unit(benchmark::kMillisecond);

// The step with world.realism on, 20 robots driving circles: arg 0 the
// official world (ideal), 1 the lab preset of before issue 22 (1 + 1 steps,
// wheel acceleration limit, noise, dropouts: `lab_v1`), 2 today's lab preset (the
// wheels' lag and start-up, gains, drift, late steps and stalls as well).
// docs/performance.md reports what the lab model costs a step.
void BM_RealismStep(benchmark::State& state) {
  const UnicycleWorld layout = MakeBusyWorld(20);
  std::vector<Pose2> poses = layout.poses();
  std::vector<UnicycleCommand> commands = layout.velocities();
  std::unique_ptr<World> world;
  if (state.range(0) == 0) {
    world = std::make_unique<UnicycleWorld>(WorldParams{}, poses);
  } else {
    world = std::make_unique<RealisticWorld>(
        WorldParams{}, state.range(0) == 1 ? RealismParams::LabV1() : RealismParams::Lab(), 1, poses);
  }
  for (auto _ : state) {
    // Commands every step, as agents send them.
    for (int i = 0; i < world->num_robots(); ++i) world->SetCommand(i, commands[static_cast<size_t>(i)]);
    world->Step();
    benchmark::DoNotOptimize(world->poses().data());
  }
  state.SetItemsProcessed(state.iterations() * 20);
}
BENCHMARK(BM_RealismStep)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace dream::world

BENCHMARK_MAIN();
