// The grid collision count must equal the official O(N^2) loop
// exactly, pair for pair, on dense, degenerate and far-flung configurations.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "dream/world/unicycle_world.h"

namespace dream::world {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The official _validate loop, written out: offset centres, then every pair.
std::vector<StepEvents::RobotPair> BruteForcePairs(const std::vector<Pose2>& poses, const WorldParams& params) {
  std::vector<double> cx(poses.size());
  std::vector<double> cy(poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    cx[i] = poses[i].x_m + params.collision_offset_m * std::cos(poses[i].theta_rad);
    cy[i] = poses[i].y_m + params.collision_offset_m * std::sin(poses[i].theta_rad);
  }
  std::vector<StepEvents::RobotPair> pairs;
  for (std::size_t i = 0; i + 1 < poses.size(); ++i) {
    for (std::size_t j = i + 1; j < poses.size(); ++j) {
      const double dx = cx[i] - cx[j];
      const double dy = cy[i] - cy[j];
      if (std::sqrt(dx * dx + dy * dy) <= params.collision_diameter_m) {
        pairs.push_back({static_cast<int>(i), static_cast<int>(j)});
      }
    }
  }
  return pairs;
}

void ExpectGridMatchesBruteForce(const std::vector<Pose2>& poses, const WorldParams& params = WorldParams{}) {
  UnicycleWorld world(params, poses);
  const std::vector<StepEvents::RobotPair> expected = BruteForcePairs(poses, params);
  world.Step();
  EXPECT_EQ(world.violations().collision_errors, static_cast<int64_t>(expected.size()));
  EXPECT_TRUE(world.last_step_events().colliding_pairs == expected)
      << "grid found " << world.last_step_events().colliding_pairs.size() << " pairs, brute force " << expected.size();
}

std::vector<Pose2> RandomPoses(std::mt19937_64& rng, int count, double half_width_m, double half_height_m) {
  std::uniform_real_distribution<double> x(-half_width_m, half_width_m);
  std::uniform_real_distribution<double> y(-half_height_m, half_height_m);
  std::uniform_real_distribution<double> theta(-kPi, kPi);
  std::vector<Pose2> poses(static_cast<std::size_t>(count));
  for (Pose2& pose : poses) pose = {x(rng), y(rng), theta(rng)};
  return poses;
}

TEST(CollisionGridEquivalenceTest, RandomDenseConfigurations) {
  std::mt19937_64 rng(12345);
  for (int trial = 0; trial < 40; ++trial) {
    const int count = 2 + trial * 37;
    // From sparse to packed far beyond the 0.135 m diameter.
    const double half_side_m = 0.1 + 0.02 * std::sqrt(static_cast<double>(count)) * (1 + trial % 4);
    SCOPED_TRACE(testing::Message() << "trial " << trial << ", " << count << " robots");
    ExpectGridMatchesBruteForce(RandomPoses(rng, count, half_side_m, half_side_m));
  }
}

TEST(CollisionGridEquivalenceTest, ThousandsOfRobotsInTheRobotariumArena) {
  std::mt19937_64 rng(99);
  ExpectGridMatchesBruteForce(RandomPoses(rng, 3000, 1.7, 1.1));
}

TEST(CollisionGridEquivalenceTest, LatticesOnCellBoundariesAndAtTheExactDiameter) {
  // Centres exactly 0.135 apart along both axes (heading pi/2 offsets y only),
  // on and around multiples of the cell size.
  std::vector<Pose2> lattice;
  for (int i = -6; i <= 6; ++i) {
    for (int j = -6; j <= 6; ++j) {
      lattice.push_back({0.135 * i, 0.135 * j - 0.025, kPi / 2});
    }
  }
  ExpectGridMatchesBruteForce(lattice);
  std::vector<Pose2> diagonal;
  for (int i = 0; i < 200; ++i) diagonal.push_back({0.0954 * i - 9.0, 0.0954 * i - 9.0, 0.0});
  ExpectGridMatchesBruteForce(diagonal);
}

TEST(CollisionGridEquivalenceTest, StackedAndFarAwayRobots) {
  std::vector<Pose2> poses;
  for (int i = 0; i < 150; ++i) poses.push_back({0.3, -0.2, 0.0});  // all on one spot
  poses.push_back({1e9, 1e9, 0.0});
  poses.push_back({1e9 + 0.1, 1e9, 0.0});
  poses.push_back({-1e300, 5.0, 0.0});
  poses.push_back({-1e300, 5.05, 0.0});
  poses.push_back({-3e9, 1e12, 1.0});
  ExpectGridMatchesBruteForce(poses);
}

TEST(CollisionGridEquivalenceTest, OtherDiametersAndOffsets) {
  std::mt19937_64 rng(7);
  WorldParams params;
  params.collision_diameter_m = 0.5;
  params.collision_offset_m = 0.2;
  ExpectGridMatchesBruteForce(RandomPoses(rng, 500, 3.0, 3.0), params);
  params.collision_diameter_m = 0.01;
  params.collision_offset_m = 0.0;
  ExpectGridMatchesBruteForce(RandomPoses(rng, 500, 0.3, 0.3), params);
}

TEST(CollisionGridEquivalenceTest, StaysEqualWhileRobotsMove) {
  std::mt19937_64 rng(2024);
  std::vector<Pose2> poses = RandomPoses(rng, 400, 1.2, 0.8);
  WorldParams params;
  UnicycleWorld world(params, poses);
  std::uniform_real_distribution<double> v(-0.3, 0.3);
  std::uniform_real_distribution<double> w(-5.0, 5.0);
  for (int k = 0; k < 60; ++k) {
    for (int i = 0; i < world.num_robots(); i += 3) world.SetCommand(i, {v(rng), w(rng)});
    const std::vector<StepEvents::RobotPair> expected = BruteForcePairs(world.poses(), params);
    world.Step();
    ASSERT_TRUE(world.last_step_events().colliding_pairs == expected) << "step " << k;
  }
}

}  // namespace
}  // namespace dream::world
