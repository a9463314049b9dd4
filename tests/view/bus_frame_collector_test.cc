#include "dream/view/bus_frame_collector.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include <cstdint>
#include <string>
#include <vector>

#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/radio_message_t.hpp"

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

run_status_t Status(int64_t run_id, int64_t step, int64_t collisions, int64_t boundary = 0) {
  run_status_t status{};
  status.run_id = run_id;
  status.step = step;
  status.state = run_status_t::RUNNING;
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
                 int64_t collisions, int64_t boundary = 0) {
  lcm::Publish(bus, "DREAM_OBSTACLES", NoObstacles(run_id, step));
  lcm::Publish(bus, "DREAM_STATUS", Status(run_id, step, collisions, boundary));
  lcm::Publish(bus, "DREAM_POSES", Poses(run_id, step, robots));
  while (bus.HandleSubscriptions(0) > 0) {
  }
}

class BusFrameCollectorTest : public ::testing::Test {
 protected:
  lcm::LcmBus bus_{"memq://"};
  BusFrameCollector collector_{bus_, world::WorldParams()};
  uint64_t version_ = 0;
  ViewFrame frame_;
};

TEST_F(BusFrameCollectorTest, KeepsOnlyTheNewestStep) {
  for (int64_t step = 0; step < 5; ++step) PublishStep(bus_, 77, step, {{0.1 * static_cast<double>(step), 0.0, 0.0}, {1.0, 0.5, 1.0}}, 0);
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

TEST_F(BusFrameCollectorTest, ANewRunStartsOver) {
  PublishStep(bus_, 5, 0, {{0.0, 0.0, 0.0}, {0.05, 0.0, 0.0}}, 0);
  PublishStep(bus_, 5, 1, {{0.0, 0.0, 0.0}, {0.05, 0.0, 0.0}}, 1);
  PublishStep(bus_, 6, 0, {{0.5, 0.0, 0.0}}, 0);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.run_id, 6);
  EXPECT_EQ(frame_.x_m.size(), 1u);
  EXPECT_TRUE(frame_.violations.empty());
  EXPECT_EQ(frame_.violations_located, 0);
}

TEST_F(BusFrameCollectorTest, TheSameRunFromItsStartAgainStartsOver) {
  // A run's log played on the bus a second time: the same run id, the steps from 0 again.
  PublishStep(bus_, 5, 7, {{0.0, 0.0, 0.0}, {0.05, 0.0, 0.0}}, 0);
  PublishStep(bus_, 5, 8, {{0.0, 0.0, 0.0}, {0.05, 0.0, 0.0}}, 1);
  PublishStep(bus_, 5, 7, {{0.0, 0.0, 0.0}, {0.05, 0.0, 0.0}}, 0);  // one step back: a resend, not a restart
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.violations.size(), 1u);
  PublishStep(bus_, 5, 0, {{0.5, 0.0, 0.0}, {1.0, 0.0, 0.0}}, 0);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.step, 0);
  EXPECT_TRUE(frame_.violations.empty());
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
