#include "dream/lcm/world_follower.h"

#include <gtest/gtest.h>

namespace dream::lcm {
namespace {

using Decision = WorldFollower::StepDecision;
constexpr int64_t kRun = 0x7e57;
constexpr int64_t kOtherRun = 0xbad;

TEST(WorldFollowerTest, JoinsTheFirstRunAndTakesItsNextStepsAndResends) {
  WorldFollower follower;
  EXPECT_FALSE(follower.InRun(kRun));  // nothing joined yet
  EXPECT_EQ(follower.OnPoses(kRun, 4), Decision::kNewStep);
  EXPECT_EQ(follower.run_id(), kRun);
  EXPECT_EQ(follower.OnPoses(kRun, 4), Decision::kResend);
  EXPECT_EQ(follower.OnPoses(kRun, 5), Decision::kNewStep);
  EXPECT_EQ(follower.OnPoses(kRun, 4), Decision::kIgnore);  // late duplicate
  EXPECT_EQ(follower.step(), 5);
  EXPECT_EQ(follower.steps_out_of_sequence(), 0);
}

TEST(WorldFollowerTest, RunIdZeroAndNegativeStepsNeverJoin) {
  WorldFollower follower;
  EXPECT_EQ(follower.OnPoses(0, 1), Decision::kIgnore);
  EXPECT_EQ(follower.OnPoses(kRun, -3), Decision::kIgnore);
  EXPECT_FALSE(follower.joined());
  EXPECT_EQ(follower.steps_out_of_sequence(), 2);
}

TEST(WorldFollowerTest, AnotherRunIsIgnoredAndRemembered) {
  WorldFollower follower;
  follower.OnPoses(kRun, 0);
  EXPECT_EQ(follower.OnPoses(kOtherRun, 1), Decision::kIgnore);
  EXPECT_FALSE(follower.InRun(kOtherRun));
  EXPECT_FALSE(follower.EndsRun(kOtherRun, 100));
  EXPECT_EQ(follower.other_runs(), std::set<int64_t>{kOtherRun});
  EXPECT_EQ(follower.step(), 0);
}

TEST(WorldFollowerTest, OtherRunsKeptAreBounded) {
  WorldFollower follower;
  follower.OnPoses(kRun, 0);
  for (int64_t id = 1; id < 1000; ++id) follower.OnPoses(kRun + id, 1);
  EXPECT_EQ(follower.other_runs().size(), WorldFollower::kMaxOtherRuns);
}

TEST(WorldFollowerTest, AShortGapIsTakenAFarJumpOnlyOnceTheNextStepConfirmsIt) {
  WorldFollower follower;
  follower.OnPoses(kRun, 10);
  EXPECT_EQ(follower.OnPoses(kRun, 10 + WorldFollower::kMaxStepGap), Decision::kNewStep);  // lost datagrams
  const int64_t at = follower.step();
  EXPECT_EQ(follower.OnPoses(kRun, int64_t{1} << 62), Decision::kIgnore);  // a forged step
  EXPECT_EQ(follower.OnPoses(kRun, at + 1), Decision::kNewStep);           // the real world goes on
  EXPECT_EQ(follower.OnPoses(kRun, at + 500), Decision::kIgnore);
  EXPECT_EQ(follower.OnPoses(kRun, at + 501), Decision::kNewStep);  // confirmed: the world did move on
  EXPECT_EQ(follower.step(), at + 501);
  EXPECT_EQ(follower.OnPoses(kRun, 3), Decision::kIgnore);  // backwards, unconfirmed
  EXPECT_EQ(follower.steps_out_of_sequence(), 3);
}

TEST(WorldFollowerTest, OnlyTheFollowedRunsEndAtOrAfterItsStepEndsIt) {
  WorldFollower follower;
  EXPECT_FALSE(follower.EndsRun(kRun, 0));  // not joined: a stale FINISHED of an earlier run
  follower.OnPoses(kRun, 7);
  EXPECT_FALSE(follower.EndsRun(kRun, 6));
  EXPECT_TRUE(follower.EndsRun(kRun, 7));
}

}  // namespace
}  // namespace dream::lcm
