// Closed-loop HRVO in the Robotarium-faithful world (hrvo_swap_harness):
// head-on pairs, the thesis's 10-robot circle swap and random crossings, for
// both variants.
// HrvoExact must never collide, never come closer than 0.2 m, and always
// finish; HrvoThesis is held to what it does (no collisions, finishes).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "dream/agents/hrvo/hrvo_exact.h"
#include "dream/agents/hrvo/hrvo_thesis.h"
#include "hrvo_swap_harness.h"

namespace dream::agents {
namespace {

HrvoFactory Exact() {
  return [] { return std::make_unique<HrvoExact>(); };
}
HrvoFactory Thesis() {
  return [] { return std::make_unique<HrvoThesis>(); };
}

std::string Describe(const HrvoSwapResult& r) {
  return "completed " + std::to_string(r.completed) + " at step " + std::to_string(r.completion_steps) +
         ", collisions " + std::to_string(r.collision_errors) + ", boundary errors " +
         std::to_string(r.boundary_errors) + ", near-miss steps " + std::to_string(r.near_miss_steps) +
         ", min distance " + std::to_string(r.min_distance_m) + " m";
}

// Pairs 1.2 m apart facing each other, swapping places; optionally offset
// sideways by `offset_m` (so the pair is not exactly symmetric), one pair
// per entry of `ys`.
void HeadOnPairs(const std::vector<double>& ys, double offset_m, std::vector<world::Pose2>* start,
                 std::vector<Eigen::Vector2d>* goals) {
  for (const double y : ys) {
    start->push_back({-0.6, y, 0.0});
    start->push_back({0.6, y + offset_m, M_PI});
    goals->emplace_back(0.6, y + offset_m);
    goals->emplace_back(-0.6, y);
  }
}

struct PairCase {
  std::vector<double> ys;
  double offset_m;
};

TEST(HrvoScenarioTest, HeadOnPairsPassWithoutCollision) {
  const std::vector<PairCase> cases = {{{0.0}, 0.0}, {{0.0}, 0.03},           {{0.0}, -0.1},
                                       {{0.3}, 0.0}, {{-0.5, 0.0, 0.5}, 0.0}, {{-0.35, 0.35}, 0.02}};
  for (const bool thesis_timing : {false, true}) {
    for (size_t c = 0; c < cases.size(); ++c) {
      std::vector<world::Pose2> start;
      std::vector<Eigen::Vector2d> goals;
      HeadOnPairs(cases[c].ys, cases[c].offset_m, &start, &goals);
      HrvoSwapOptions options;
      options.thesis_timing = thesis_timing;
      options.max_steps = 1500;
      const HrvoSwapResult exact = RunHrvoSwap(start, goals, Exact(), options);
      SCOPED_TRACE("case " + std::to_string(c) + (thesis_timing ? ", thesis timers" : ", every step"));
      EXPECT_TRUE(exact.completed) << Describe(exact);
      EXPECT_EQ(exact.collision_errors, 0) << Describe(exact);
      EXPECT_EQ(exact.boundary_errors, 0) << Describe(exact);
      EXPECT_EQ(exact.near_miss_steps, 0) << Describe(exact);
      const HrvoSwapResult thesis = RunHrvoSwap(start, goals, Thesis(), options);
      EXPECT_TRUE(thesis.completed) << Describe(thesis);
      EXPECT_EQ(thesis.collision_errors, 0) << Describe(thesis);
    }
  }
}

// The thesis's Appendix B circle: 10 robots at radius 0.85 m, each to the
// diametrically opposite point; seed 0 is the exact circle, others perturb
// the start by up to 3 cm and 0.3 rad.
TEST(HrvoScenarioTest, CircleSwapOfTenRobots) {
  constexpr int kRobots = 10;
  constexpr double kRadius = 0.85;
  const std::vector<Eigen::Vector2d> goals = AntipodalGoals(kRobots, kRadius);
  for (const bool thesis_timing : {false, true}) {
    double exact_steps = 0.0, thesis_steps = 0.0;
    int64_t exact_near = 0, thesis_near = 0;
    constexpr int kSeeds = 5;
    for (int seed = 0; seed < kSeeds; ++seed) {
      const std::vector<world::Pose2> start =
          CirclePoses(kRobots, kRadius, seed == 0 ? 0.0 : 0.03, seed == 0 ? 0.0 : 0.3, static_cast<uint64_t>(seed));
      HrvoSwapOptions options;
      options.thesis_timing = thesis_timing;
      SCOPED_TRACE("seed " + std::to_string(seed) + (thesis_timing ? ", thesis timers" : ", every step"));
      const HrvoSwapResult exact = RunHrvoSwap(start, goals, Exact(), options);
      EXPECT_TRUE(exact.completed) << Describe(exact);
      EXPECT_EQ(exact.collision_errors, 0) << Describe(exact);
      EXPECT_EQ(exact.boundary_errors, 0) << Describe(exact);
      EXPECT_EQ(exact.near_miss_steps, 0) << Describe(exact);
      const HrvoSwapResult thesis = RunHrvoSwap(start, goals, Thesis(), options);
      EXPECT_TRUE(thesis.completed) << Describe(thesis);
      EXPECT_EQ(thesis.collision_errors, 0) << Describe(thesis);
      EXPECT_EQ(thesis.boundary_errors, 0) << Describe(thesis);
      exact_steps += static_cast<double>(exact.completion_steps);
      thesis_steps += static_cast<double>(thesis.completion_steps);
      exact_near += exact.near_miss_steps;
      thesis_near += thesis.near_miss_steps;
    }
    // The improvement is at least as good as the thesis on both counts.
    EXPECT_LE(exact_steps, thesis_steps);
    EXPECT_LE(exact_near, thesis_near);
  }
}

// Random crossings of 12 robots: HrvoExact finishes every one without a
// collision or boundary error. (HrvoThesis does not collide either, but some
// runs never finish: docs/hrvo.md.)
TEST(HrvoScenarioTest, RandomCrossingsOfTwelveRobots) {
  for (const bool thesis_timing : {false, true}) {
    for (uint64_t seed = 1; seed <= 5; ++seed) {
      std::vector<world::Pose2> start;
      std::vector<Eigen::Vector2d> goals;
      RandomCrossing(12, seed, &start, &goals);
      HrvoSwapOptions options;
      options.thesis_timing = thesis_timing;
      SCOPED_TRACE("seed " + std::to_string(seed) + (thesis_timing ? ", thesis timers" : ", every step"));
      const HrvoSwapResult exact = RunHrvoSwap(start, goals, Exact(), options);
      EXPECT_TRUE(exact.completed) << Describe(exact);
      EXPECT_EQ(exact.collision_errors, 0) << Describe(exact);
      EXPECT_EQ(exact.boundary_errors, 0) << Describe(exact);
      const HrvoSwapResult thesis = RunHrvoSwap(start, goals, Thesis(), options);
      EXPECT_EQ(thesis.collision_errors, 0) << Describe(thesis);
    }
  }
}

}  // namespace
}  // namespace dream::agents
