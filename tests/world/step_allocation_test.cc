// Step() must not touch the heap once its event lists have grown to their
// working size. Its own binary, because it replaces the global operator new
// to count calls.
#include <atomic>
#include <cstdlib>
#include <new>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "dream/world/initial_pose_generator.h"
#include "dream/world/unicycle_world.h"

namespace {
std::atomic<long> allocation_count{0};
}  // namespace

void* operator new(std::size_t size) {
  allocation_count.fetch_add(1, std::memory_order_relaxed);
  if (void* memory = std::malloc(size == 0 ? 1 : size)) return memory;
  throw std::bad_alloc();
}
void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }

namespace dream::world {
namespace {

TEST(StepAllocationTest, SteadyStateStepDoesNotAllocate) {
  WorldParams params;
  params.arena = Arena{-5.0, 5.0, -5.0, 5.0};
  std::vector<Pose2> poses = InitialPoseGenerator(params, InitialPoseParams{}).Generate(500, 3);
  for (int i = 0; i < 100; ++i) poses.push_back({poses[i].x_m + 0.05, poses[i].y_m, 0.0});  // contacts
  poses.push_back({20.0, 0.0, 0.0});                                                        // out of bounds
  RectangleObstacleSpec box;
  box.width_m = 1.0;
  box.height_m = 1.0;
  box.path = ObstaclePath{{Eigen::Vector2d(2.0, 0.0)}, 0.5, ObstaclePathMode::kPingPong};
  const long before_construction = allocation_count.load();
  UnicycleWorld world(params, poses, {box});
  ASSERT_GT(allocation_count.load(), before_construction) << "the counting operator new is not in effect";

  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> v(-0.3, 0.3);
  std::uniform_real_distribution<double> w(-5.0, 5.0);
  auto run = [&](int steps) {
    for (int k = 0; k < steps; ++k) {
      for (int i = 0; i < world.num_robots(); i += 2) world.SetCommand(i, {v(rng), w(rng)});
      world.Step();
    }
  };
  run(20);  // warm-up: event lists reach their working capacity
  const long before = allocation_count.load();
  run(100);
  const long allocations = allocation_count.load() - before;
  EXPECT_EQ(allocations, 0);
  EXPECT_GT(world.violations().collision_errors, 0);
  EXPECT_GT(world.violations().boundary_errors, 0);
  EXPECT_GT(world.violations().actuator_errors, 0);
}

}  // namespace
}  // namespace dream::world
