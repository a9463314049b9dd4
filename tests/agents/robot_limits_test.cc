// agents/ may not use the world library, so RobotLimits writes the
// Robotarium's numbers again; this keeps the two copies equal.
#include "dream/agents/framework/robot_limits.h"

#include <gtest/gtest.h>

#include "dream/world/robotarium_constants.h"

namespace dream::agents {
namespace {

using sim::RobotariumConstants;

TEST(RobotLimitsTest, DefaultsAreTheRobotariumConstants) {
  const RobotLimits limits;
  EXPECT_EQ(limits.max_linear_speed_mps, RobotariumConstants::kMaxLinearVelocityMps);
  EXPECT_EQ(limits.wheel_radius_m, RobotariumConstants::kWheelRadiusMeters);
  EXPECT_EQ(limits.base_length_m, RobotariumConstants::kBaseLengthMeters);
  EXPECT_EQ(limits.max_wheel_speed_radps, RobotariumConstants::kMaxWheelVelocityRadps);
  EXPECT_EQ(limits.max_angular_speed_radps, RobotariumConstants::kMaxAngularVelocityRadps);
}

}  // namespace
}  // namespace dream::agents
