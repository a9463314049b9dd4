#include "dream/view/bus_frame_collector.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>

#include <cstdint>
#include <string>
#include <vector>

#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/radio_message_t.hpp"
#include "dream/run_verdict_t.hpp"

namespace dream::view {
namespace {

robot_poses_t Poses(int64_t run_id, int64_t step, const std::vector<std::array<double, 3>>& robots) {
  robot_poses_t poses{};
  poses.run_id = run_id;
  poses.step = step;
  poses.utime = step * 33000;
  poses.num_robots = static_cast<int32_t>(robots.size());
  for (const auto& [x, y, theta] : robots) {
    poses.x.push_back(x);
    poses.y.push_back(y);
    poses.theta.push_back(theta);
    poses.v.push_back(0.0);
    poses.w.push_back(0.0);
  }
  return poses;
}

run_status_t Status(int64_t run_id, int64_t step, int64_t collisions, int64_t boundary = 0,
                    int8_t state = run_status_t::RUNNING) {
  run_status_t status{};
  status.run_id = run_id;
  status.step = step;
  status.state = state;
  status.num_robots = 2;
  status.collision_errors = collisions;
  status.boundary_errors = boundary;
  status.detail = "running";
  return status;
}

obstacles_t NoObstacles(int64_t run_id, int64_t step) {
  obstacles_t obstacles{};
  obstacles.run_id = run_id;
  obstacles.step = step;
  return obstacles;
}

/// One step as the world publishes it: obstacles, status, then poses.
void PublishStep(lcm::LcmBus& bus, int64_t run_id, int64_t step, const std::vector<std::array<double, 3>>& robots,
                 int64_t collisions, int64_t boundary = 0, int8_t state = run_status_t::RUNNING) {
  lcm::Publish(bus, "DREAM_OBSTACLES", NoObstacles(run_id, step));
  lcm::Publish(bus, "DREAM_STATUS", Status(run_id, step, collisions, boundary, state));
  lcm::Publish(bus, "DREAM_POSES", Poses(run_id, step, robots));
  while (bus.HandleSubscriptions(0) > 0) {
  }
}

/// One message on the bus, handled.
template <typename Message>
void PublishOne(lcm::LcmBus& bus, const std::string& channel, const Message& message) {
  lcm::Publish(bus, channel, message);
  while (bus.HandleSubscriptions(0) > 0) {
  }
}

run_verdict_t Verdict(int64_t run_id, int64_t step, int8_t verdict) {
  run_verdict_t message{};
  message.run_id = run_id;
  message.step = step;
  message.verdict = verdict;
  message.goal = run_verdict_t::GOAL_MISSED;
  message.exit_code = 3;
  message.goal_completion_step = -1;
  message.goal_text = "missed (1 of 2 robots arrived)";
  message.reasons = "collision: robots 0 and 1 collided\ngoal: the go_to_goal experiment missed its goal";
  return message;
}

class BusFrameCollectorTest : public ::testing::Test {
 protected:
  /// Run 5's steps 0..2, robots 0 and 1 too close from step 1 on: one collision located.
  void RunWithACollision() {
    PublishStep(bus_, 5, 0, {{0.0, 0.0, 0.0}, {1.0, 0.0, M_PI}}, 0);
    PublishStep(bus_, 5, 1, {{0.0, 0.0, 0.0}, {0.1, 0.0, M_PI}}, 0);
    PublishStep(bus_, 5, 2, {{0.0, 0.0, 0.0}, {0.1, 0.0, M_PI}}, 1);
  }
  /// The run's FINISHED status, after its last step.
  void Finish(int64_t run_id, int64_t step, int64_t collisions) {
    PublishOne(bus_, "DREAM_STATUS", Status(run_id, step, collisions, 0, run_status_t::FINISHED));
  }

  RunChoice::Clock::time_point now_{};
  lcm::LcmBus bus_{"memq://"};
  BusFrameCollector collector_{bus_, world::WorldParams(), [this] { return now_; }};
  uint64_t version_ = 0;
  ViewFrame frame_;
};

TEST_F(BusFrameCollectorTest, KeepsOnlyTheNewestStep) {
  for (int64_t step = 0; step < 5; ++step)
    PublishStep(bus_, 77, step, {{0.1 * static_cast<double>(step), 0.0, 0.0}, {1.0, 0.5, 1.0}}, 0);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.run_id, 77);
  EXPECT_EQ(frame_.step, 4);
  EXPECT_DOUBLE_EQ(frame_.x_m[0], 0.4);
  EXPECT_DOUBLE_EQ(frame_.theta_rad[1], 1.0);
  EXPECT_TRUE(frame_.status.seen);
  EXPECT_TRUE(frame_.violations.empty());
  EXPECT_FALSE(collector_.TakeFrame(&frame_, &version_));  // nothing new since
}

TEST_F(BusFrameCollectorTest, LocatesACollisionWhenTheStatusCountsIt) {
  PublishStep(bus_, 5, 0, {{0.0, 0.0, 0.0}, {1.0, 0.0, M_PI}}, 0);
  PublishStep(bus_, 5, 1, {{0.0, 0.0, 0.0}, {0.1, 0.0, M_PI}}, 0);  // too close at step 1 ...
  PublishStep(bus_, 5, 2, {{0.0, 0.0, 0.0}, {0.1, 0.0, M_PI}}, 1);  // ... which step 2's status counts
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  ASSERT_EQ(frame_.violations.size(), 1u);
  const ViolationMark& mark = frame_.violations[0];
  EXPECT_EQ(mark.kind, ViolationMark::Kind::kCollision);
  EXPECT_EQ(mark.step, 1);
  EXPECT_EQ(mark.robot, 0);
  EXPECT_EQ(mark.other, 1);
  EXPECT_NEAR(mark.x_m, 0.05, 1e-12);  // between the two
  EXPECT_EQ(frame_.violations_located, 1);
}

TEST_F(BusFrameCollectorTest, LocatesOnlyTheKindsTheStatusCounted) {
  // Robot 1 is outside the arena at step 0, but the status counts only a boundary error:
  // the pair that happens to be close is not reported as a collision the world did not count.
  PublishStep(bus_, 5, 0, {{1.7, 0.0, 0.0}, {1.65, 0.0, 0.0}}, 0);
  PublishStep(bus_, 5, 1, {{1.7, 0.0, 0.0}, {1.65, 0.0, 0.0}}, 0, 1);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  ASSERT_EQ(frame_.violations.size(), 2u);
  for (const ViolationMark& mark : frame_.violations) EXPECT_EQ(mark.kind, ViolationMark::Kind::kBoundary);
}

TEST_F(BusFrameCollectorTest, KeepsABoundedNumberOfMarks) {
  for (int64_t step = 0; step < 200; ++step) {
    PublishStep(bus_, 5, step, {{0.0, 0.0, 0.0}, {0.05, 0.0, 0.0}}, step);  // colliding every step
  }
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.violations.size(), BusFrameCollector::kMaxMarks);
  EXPECT_EQ(frame_.violations.back().step, 198);  // the latest are kept
  EXPECT_EQ(frame_.violations_located, 199);
}

TEST_F(BusFrameCollectorTest, ANewRunAfterTheEndStartsOver) {
  PublishStep(bus_, 5, 0, {{0.0, 0.0, 0.0}, {0.05, 0.0, 0.0}}, 0);
  PublishStep(bus_, 5, 1, {{0.0, 0.0, 0.0}, {0.05, 0.0, 0.0}}, 1);
  Finish(5, 1, 1);
  now_ += std::chrono::seconds(1);
  PublishStep(bus_, 6, 0, {{0.5, 0.0, 0.0}}, 0);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.run_id, 6);
  EXPECT_EQ(frame_.x_m.size(), 1u);
  EXPECT_TRUE(frame_.violations.empty());
  EXPECT_EQ(frame_.violations_located, 0);
  EXPECT_EQ(frame_.status.collision_errors, 0);  // the new run's status, published before its poses
  EXPECT_FALSE(frame_.other_world.has_value());  // the run that ended is no second world
}

TEST_F(BusFrameCollectorTest, ANewRunAfterTheOneDrawnWentSilentStartsOver) {
  RunWithACollision();  // then killed: no FINISHED
  now_ += RunChoice::kSilence;
  PublishStep(bus_, 6, 0, {{0.5, 0.0, 0.0}}, 0, 0, run_status_t::WAITING_FOR_AGENTS);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.run_id, 6);
  EXPECT_TRUE(frame_.violations.empty());
}

TEST_F(BusFrameCollectorTest, TheSameRunFromItsStartAgainStartsOver) {
  // A run's log played on the bus a second time: the same run id, the steps from 0 again.
  PublishStep(bus_, 5, 7, {{0.0, 0.0, 0.0}, {0.05, 0.0, 0.0}}, 0);
  PublishStep(bus_, 5, 8, {{0.0, 0.0, 0.0}, {0.05, 0.0, 0.0}}, 1);
  PublishStep(bus_, 5, 7, {{0.0, 0.0, 0.0}, {0.05, 0.0, 0.0}}, 0);  // one step back: a late resend, not a restart
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.violations.size(), 1u);
  EXPECT_EQ(frame_.step, 8);
  PublishStep(bus_, 5, 0, {{0.5, 0.0, 0.0}, {1.0, 0.0, 0.0}}, 0);
  PublishStep(bus_, 5, 1, {{0.5, 0.0, 0.0}, {1.0, 0.0, 0.0}}, 0);  // the step after confirms the step back
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.step, 1);
  EXPECT_TRUE(frame_.violations.empty());
}

// Issue 34: one forged DREAM_POSES of a made-up run id made every view switch to it and wipe its violations.
TEST_F(BusFrameCollectorTest, AForgedPosesOfAnotherRunMidRunIsSaidNotDrawn) {
  RunWithACollision();
  PublishOne(bus_, "DREAM_POSES", Poses(0xbad, 0, {{1.0, 1.0, 0.0}}));
  PublishOne(bus_, "DREAM_POSES", Poses(0xbad, 3, {{1.0, 1.0, 0.0}}));
  PublishStep(bus_, 5, 3, {{0.0, 0.0, 0.0}, {0.1, 0.0, M_PI}}, 2);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.run_id, 5);
  EXPECT_EQ(frame_.step, 3);
  EXPECT_EQ(frame_.x_m.size(), 2u);
  EXPECT_EQ(frame_.violations.size(), 2u);  // step 1's and step 2's: none wiped
  EXPECT_EQ(frame_.violations_located, 2);
  ASSERT_TRUE(frame_.other_world.has_value());
  EXPECT_EQ(frame_.other_world->run_id, 0xbad);
  EXPECT_EQ(frame_.other_world->step, 3);
}

// Issue 34: sent after the run ended, the forged run replaced the finished one on screen.
TEST_F(BusFrameCollectorTest, AForgedPosesAfterTheEndLeavesTheFinishedRunDrawn) {
  RunWithACollision();
  Finish(5, 2, 1);
  for (const int64_t step : {0, 1, 500}) PublishOne(bus_, "DREAM_POSES", Poses(0xbad, step, {{1.0, 1.0, 0.0}}));
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.run_id, 5);
  EXPECT_EQ(frame_.step, 2);
  EXPECT_EQ(frame_.status.state, run_status_t::FINISHED);
  EXPECT_EQ(frame_.violations.size(), 1u);
  ASSERT_TRUE(frame_.other_world.has_value());
  EXPECT_EQ(frame_.other_world->run_id, 0xbad);
}

// Issue 34: a second dream sim waiting for agents made the views flip between the runs and end on its step 0.
TEST_F(BusFrameCollectorTest, ASecondWorldWaitingBesideTheRunIsSaidNotDrawn) {
  const std::vector<std::array<double, 3>> idle = {{-1.0, -0.5, 0.0}, {1.0, 0.5, 0.0}, {0.0, 0.0, 0.0}};
  // It was there first: drawn, until a run that moves comes.
  PublishStep(bus_, 9, 0, idle, 0, 0, run_status_t::WAITING_FOR_AGENTS);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.run_id, 9);
  for (int64_t step = 0; step < 3; ++step) {
    PublishStep(bus_, 5, step, {{0.0, 0.0, 0.0}, {step == 0 ? 1.0 : 0.1, 0.0, M_PI}}, step == 2 ? 1 : 0);
    PublishStep(bus_, 9, 0, idle, 0, 0, run_status_t::WAITING_FOR_AGENTS);  // its resends
  }
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.run_id, 5);
  EXPECT_EQ(frame_.step, 2);
  EXPECT_EQ(frame_.violations.size(), 1u);
  ASSERT_TRUE(frame_.other_world.has_value());
  EXPECT_EQ(frame_.other_world->run_id, 9);
  EXPECT_EQ(frame_.other_world->step, 0);
  EXPECT_EQ(frame_.other_world->state, run_status_t::WAITING_FOR_AGENTS);
  EXPECT_EQ(frame_.other_world->runs, 1);

  // The watched run ends; the idle world still waits: the finished run stays drawn.
  PublishOne(bus_, "DREAM_STATUS", Status(5, 2, 1, 0, run_status_t::FINISHED));
  for (int i = 0; i < 3; ++i) PublishStep(bus_, 9, 0, idle, 0, 0, run_status_t::WAITING_FOR_AGENTS);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.run_id, 5);
  EXPECT_EQ(frame_.status.state, run_status_t::FINISHED);
  EXPECT_EQ(frame_.violations.size(), 1u);

  // Its agents come and it runs: a run that starts after the end is drawn.
  PublishStep(bus_, 9, 1, idle, 0);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.run_id, 9);
  EXPECT_EQ(frame_.step, 1);
  EXPECT_EQ(frame_.x_m.size(), 3u);
  EXPECT_TRUE(frame_.violations.empty());
  EXPECT_FALSE(frame_.other_world.has_value());
}

TEST_F(BusFrameCollectorTest, TheUsersChoiceOfTheOtherWorldIsDrawnFromItsNextStep) {
  RunWithACollision();
  PublishStep(bus_, 9, 0, {{0.5, 0.5, 0.0}}, 0, 0, run_status_t::WAITING_FOR_AGENTS);
  EXPECT_FALSE(collector_.Follow(77));  // no such run heard
  EXPECT_TRUE(collector_.Follow(9));
  PublishStep(bus_, 9, 0, {{0.5, 0.5, 0.0}}, 0, 0, run_status_t::WAITING_FOR_AGENTS);  // its resend
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.run_id, 9);
  EXPECT_EQ(frame_.x_m.size(), 1u);
  EXPECT_EQ(frame_.status.state, run_status_t::WAITING_FOR_AGENTS);
  EXPECT_TRUE(frame_.violations.empty());
}

TEST_F(BusFrameCollectorTest, ASecondWorldGoneQuietIsNoLongerSaid) {
  RunWithACollision();
  Finish(5, 2, 1);
  PublishOne(bus_, "DREAM_POSES", Poses(0xbad, 0, {{1.0, 1.0, 0.0}}));
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  ASSERT_TRUE(frame_.other_world.has_value());
  EXPECT_FALSE(collector_.TakeFrame(&frame_, &version_));  // nothing new
  now_ += RunChoice::kOtherWorldShown + std::chrono::milliseconds(1);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_)) << "nothing else changed, but the page must be told";
  EXPECT_FALSE(frame_.other_world.has_value());
  EXPECT_EQ(frame_.run_id, 5);
  EXPECT_EQ(frame_.violations.size(), 1u);
}

TEST_F(BusFrameCollectorTest, AnotherWorldsStatusIsNotDrawnOverThisRun) {
  PublishStep(bus_, 5, 0, {{0.0, 0.0, 0.0}}, 0);
  lcm::Publish(bus_, "DREAM_STATUS", Status(99, 0, 1000));
  while (bus_.HandleSubscriptions(0) > 0) {
  }
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.status.collision_errors, 0);
}

TEST_F(BusFrameCollectorTest, ForgedMessagesAreCountedNotDrawn) {
  PublishStep(bus_, 5, 0, {{0.0, 0.0, 0.0}}, 0);
  const std::vector<uint8_t> junk(13, 0xff);
  bus_.Publish("DREAM_POSES", junk.data(), static_cast<int>(junk.size()));
  bus_.Publish("DREAM_STATUS", junk.data(), static_cast<int>(junk.size()));
  robot_poses_t lying = Poses(5, 1, {{0.0, 0.0, 0.0}});
  lying.num_robots = 1 << 28;  // a count that lies about the message's size: refused before allocating
  std::vector<uint8_t> bytes(static_cast<size_t>(Poses(5, 1, {{0.0, 0.0, 0.0}}).getEncodedSize()));
  Poses(5, 1, {{0.0, 0.0, 0.0}}).encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  bytes[8 + 8 + 8 + 8] = 0x10;  // num_robots' top byte (after the fingerprint, utime, step, run_id)
  bus_.Publish("DREAM_POSES", bytes.data(), static_cast<int>(bytes.size()));
  while (bus_.HandleSubscriptions(0) > 0) {
  }
  EXPECT_EQ(collector_.bad_messages(), 3);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.step, 0);
  EXPECT_EQ(frame_.x_m.size(), 1u);
}

TEST_F(BusFrameCollectorTest, RadioSendersAreThisRunsRobotsSinceTheLastFrame) {
  PublishStep(bus_, 5, 0, {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}, 0);
  radio_message_t radio{};
  lcm::Publish(bus_, "DREAM_RADIO_1", radio);
  lcm::Publish(bus_, "DREAM_RADIO_1", radio);
  lcm::Publish(bus_, "DREAM_RADIO_0", radio);
  lcm::Publish(bus_, "DREAM_RADIO_7", radio);  // no such robot in this run
  while (bus_.HandleSubscriptions(0) > 0) {
  }
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.radio_senders, (std::vector<int>{0, 1}));
  PublishStep(bus_, 5, 1, {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}, 0);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_TRUE(frame_.radio_senders.empty());  // said once, in the frame after they spoke
}

TEST_F(BusFrameCollectorTest, MeasuredPosesOfTheSameStepAreKept) {
  PublishStep(bus_, 5, 3, {{0.0, 0.0, 0.0}}, 0);
  lcm::Publish(bus_, "DREAM_MEASURED_POSES", Poses(5, 3, {{0.01, -0.01, 0.1}}));
  while (bus_.HandleSubscriptions(0) > 0) {
  }
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  ASSERT_EQ(frame_.measured_x_m.size(), 1u);
  EXPECT_DOUBLE_EQ(frame_.measured_x_m[0], 0.01);
  PublishStep(bus_, 5, 4, {{0.0, 0.0, 0.0}}, 0);  // a step without: the old ones are not drawn with it
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_TRUE(frame_.measured_x_m.empty());
}

}  // namespace
}  // namespace dream::view

namespace dream::view {
namespace {

// Issue 33: the page ends a run on the world's DREAM_VERDICT (summary.json's),
// taken by the agents' rule: the run drawn, once it is over.
TEST_F(BusFrameCollectorTest, TheVerdictOfTheRunDrawnIsTakenOnceItIsOver) {
  RunWithACollision();
  // While the run runs, a verdict (forged: the world judges only at the end) is refused.
  PublishOne(bus_, "DREAM_VERDICT", Verdict(5, 2, run_verdict_t::CLEAN));
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_FALSE(frame_.judged.has_value());
  Finish(5, 3, 1);
  // Another run's verdict is refused too, and an undecodable one is counted as bad.
  PublishOne(bus_, "DREAM_VERDICT", Verdict(6, 3, run_verdict_t::CLEAN));
  const uint8_t garbage[5] = {1, 2, 3, 4, 5};
  bus_.Publish("DREAM_VERDICT", garbage, 5);
  while (bus_.HandleSubscriptions(0) > 0) {
  }
  collector_.TakeFrame(&frame_, &version_);
  EXPECT_FALSE(frame_.judged.has_value());
  EXPECT_EQ(collector_.verdicts_refused(), 2);
  EXPECT_EQ(collector_.bad_messages(), 1);

  PublishOne(bus_, "DREAM_VERDICT", Verdict(5, 3, run_verdict_t::REJECTED));
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  ASSERT_TRUE(frame_.judged.has_value());
  EXPECT_EQ(frame_.judged->verdict, "rejected");
  EXPECT_EQ(frame_.judged->goal, "missed (1 of 2 robots arrived)");
  EXPECT_EQ(frame_.judged->exit_code, 3);
  EXPECT_EQ(frame_.judged->reasons, (std::vector<std::string>{"collision: robots 0 and 1 collided",
                                                              "goal: the go_to_goal experiment missed its goal"}));
  // A verdict value none of the four is refused, the one taken stays.
  PublishOne(bus_, "DREAM_VERDICT", Verdict(5, 3, 9));
  collector_.TakeFrame(&frame_, &version_);
  EXPECT_EQ(frame_.judged->verdict, "rejected");

  // The next run drawn is judged at its own end only.
  PublishStep(bus_, 6, 0, {{0.0, 0.0, 0.0}, {1.0, 0.0, M_PI}}, 0);
  PublishStep(bus_, 6, 1, {{0.0, 0.0, 0.0}, {1.0, 0.0, M_PI}}, 0);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.run_id, 6);
  EXPECT_EQ(frame_.step, 1);
  EXPECT_FALSE(frame_.judged.has_value());
}

}  // namespace
}  // namespace dream::view
