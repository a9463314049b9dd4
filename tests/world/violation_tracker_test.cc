#include "dream/world/violation_tracker.h"

#include <gtest/gtest.h>

#include <vector>

#include "dream/world/violation_checker.h"
#include "dream/world/world_params.h"

namespace dream::world {
namespace {

using Kind = LocatedViolation::Kind;

StepEvents Events(int64_t step) {
  StepEvents events;
  events.Reset(step);
  return events;
}

const std::vector<Pose2> kPoses = {{0.0, 0.0, 0.0}, {0.1, 0.0, 0.0}, {1.7, 0.9, 0.0}};

TEST(ViolationTrackerTest, ConsecutiveStepsOfOneViolationAreOneEntryFromItsFirstToItsLastStep) {
  ViolationTracker tracker;
  for (int64_t step = 10; step <= 14; ++step) {
    StepEvents events = Events(step);
    events.colliding_pairs.push_back({0, 1});
    tracker.Add(events, kPoses);
  }
  tracker.Add(Events(15), kPoses);
  StepEvents again = Events(16);  // the same pair again after a clean step: a new entry
  again.colliding_pairs.push_back({0, 1});
  tracker.Add(again, kPoses);
  const LocatedViolations& located = tracker.located();
  ASSERT_EQ(located.listed.size(), 2u);
  EXPECT_EQ(located.listed[0].kind, Kind::kCollision);
  EXPECT_EQ(located.listed[0].robot, 0);
  EXPECT_EQ(located.listed[0].other, 1);
  EXPECT_EQ(located.listed[0].first_step, 10);
  EXPECT_EQ(located.listed[0].last_step, 14);
  EXPECT_DOUBLE_EQ(located.listed[0].x_m, 0.05);  // the middle of the pair
  EXPECT_DOUBLE_EQ(located.listed[0].y_m, 0.0);
  EXPECT_EQ(located.listed[1].first_step, 16);
  EXPECT_EQ(located.listed[1].last_step, 16);
  EXPECT_EQ(located.unlisted, 0);
}

// An episode keeps the worst of its steps: the farthest outside, the closest pair.
TEST(ViolationTrackerTest, AnEpisodeKeepsTheWorstOfItsSteps) {
  ViolationTracker tracker;
  const std::vector<double> outside = {0.05, 0.2, 0.1}, apart = {0.12, 0.09, 0.11};
  for (size_t i = 0; i < outside.size(); ++i) {
    LocatedViolation boundary{Kind::kBoundary, 2, -1, 0, 0, 1.7, 0.9};
    boundary.worst_m = outside[i];
    LocatedViolation collision{Kind::kCollision, 0, 1, 0, 0, 0.05, 0.0};
    collision.worst_m = apart[i];
    tracker.AddPlaced(static_cast<int64_t>(20 + i), {boundary, collision});
  }
  const LocatedViolations& located = tracker.located();
  ASSERT_EQ(located.listed.size(), 2u);
  EXPECT_EQ(located.listed[0].first_step, 20);
  EXPECT_EQ(located.listed[0].last_step, 22);
  EXPECT_DOUBLE_EQ(located.listed[0].worst_m, 0.2);   // boundary: the largest
  EXPECT_DOUBLE_EQ(located.listed[1].worst_m, 0.09);  // collision: the smallest
  EXPECT_DOUBLE_EQ(located.listed[0].x_m, 1.7);       // placed where it started
}

TEST(ViolationTrackerTest, EachRobotAndObstacleIsItsOwnEntryPlacedAtTheRobot) {
  ViolationTracker tracker;
  StepEvents events = Events(3);
  events.out_of_bounds_robot_ids = {2};
  events.obstacle_contacts.push_back({0, 7});
  events.obstacle_contacts.push_back({0, 8});
  events.obstacle_contacts.push_back({0, 8});  // named twice: still one
  tracker.Add(events, kPoses);
  const LocatedViolations& located = tracker.located();
  ASSERT_EQ(located.listed.size(), 3u);
  EXPECT_EQ(located.listed[0].kind, Kind::kBoundary);
  EXPECT_EQ(located.listed[0].robot, 2);
  EXPECT_EQ(located.listed[0].other, -1);
  EXPECT_DOUBLE_EQ(located.listed[0].x_m, 1.7);
  EXPECT_EQ(located.listed[1].kind, Kind::kObstacle);
  EXPECT_EQ(located.listed[1].other, 7);
  EXPECT_EQ(located.listed[2].other, 8);
  EXPECT_STREQ(LocatedViolationKindName(Kind::kObstacle), "obstacle");
}

TEST(ViolationTrackerTest, PastTheBoundEntriesAreCountedNotListedAndGoingOnCountsOnce) {
  ViolationTracker tracker(2);
  for (int64_t step = 0; step < 20; ++step) {
    StepEvents events = Events(step);
    // Robot 2 outside every other step (10 entries); robot 0 on an obstacle throughout (1 entry).
    if (step % 2 == 0) events.out_of_bounds_robot_ids = {2};
    events.obstacle_contacts.push_back({0, 1});
    tracker.Add(events, kPoses);
  }
  const LocatedViolations& located = tracker.located();
  ASSERT_EQ(located.listed.size(), 2u);
  EXPECT_EQ(located.listed[0].kind, Kind::kBoundary);
  EXPECT_EQ(located.listed[1].kind, Kind::kObstacle);
  EXPECT_EQ(located.listed[1].last_step, 19);
  EXPECT_EQ(located.unlisted, 9);
  EXPECT_EQ(located.total(), 11);
}

TEST(ViolationTrackerTest, AnEventNamingARobotItHasNoPoseForIsIgnored) {
  ViolationTracker tracker;
  StepEvents events = Events(0);
  events.out_of_bounds_robot_ids = {5, -1};
  events.colliding_pairs.push_back({1, 9});
  tracker.Add(events, kPoses);
  EXPECT_EQ(tracker.located().total(), 0);
}

TEST(ViolationTrackerTest, TheCheckersEventsAreLocatedAtTheRobotsOfThatStep) {
  ViolationChecker checker(WorldParams{}, 3);
  ViolationTracker tracker;
  // Robots 0 and 1 touching, robot 2 outside the arena (x > 1.6).
  checker.Check(4, kPoses, nullptr, {});
  tracker.Add(checker.last_step_events(), kPoses);
  const LocatedViolations& located = tracker.located();
  ASSERT_EQ(located.listed.size(), 2u);
  EXPECT_EQ(located.listed[0].kind, Kind::kBoundary);
  EXPECT_EQ(located.listed[0].first_step, 4);
  EXPECT_EQ(located.listed[1].kind, Kind::kCollision);
  EXPECT_EQ(checker.counts().hard_errors(), 2);
}

}  // namespace
}  // namespace dream::world
