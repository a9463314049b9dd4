#include "dream/run_log/message_difference.h"

#include <gtest/gtest.h>

#include <vector>

#include "dream/robot_poses_t.hpp"
#include "dream/velocity_command_t.hpp"
#include "../support/encoded_message.h"

namespace dream::run_log {
namespace {

using dream::testing::Encoded;

robot_poses_t ThreeRobots() {
  robot_poses_t poses;
  poses.utime = 33000;
  poses.step = 12;
  poses.run_id = 0;
  poses.num_robots = 3;
  poses.x = {0.5, -0.25, 0.0};
  poses.y = {0.1, 0.2, 0.3};
  poses.theta = {3.0, -1.5, 0.0};
  poses.v = {0.1, 0.0, 0.0};
  poses.w = {0.0, 0.5, 0.0};
  return poses;
}

TEST(MessageDifference, NamesTheStepRobotAndFieldOfAPoseThatDiffers) {
  robot_poses_t other = ThreeRobots();
  other.y[2] = 0.31;
  other.theta[0] = 1.0;  // a later field: the first difference in field order wins
  EXPECT_EQ(FirstDifference(Encoded(ThreeRobots()), Encoded(other)), "step 12, robot 2: y 0.3 vs 0.31");
}

TEST(MessageDifference, NamesTheRobotOfACommand) {
  velocity_command_t a{};
  a.step = 7;
  a.robot_id = 4;
  a.v = 0.1;
  velocity_command_t b = a;
  b.v = 0.2;
  EXPECT_EQ(FirstDifference(Encoded(a), Encoded(b)), "step 7, robot 4: v 0.1 vs 0.2");
}

TEST(MessageDifference, UndecodableBytesAreComparedByteByByte) {
  EXPECT_EQ(FirstDifference({1, 2, 3}, {1, 9, 3}), "byte 1 differs (2 vs 9)");
  EXPECT_EQ(FirstDifference({1, 2}, {1, 2, 3}), "2 bytes vs 3");
}

}  // namespace
}  // namespace dream::run_log
