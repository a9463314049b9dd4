// Known answers for the V2 unicycle <-> wheel conversions and saturation,
// worked out by hand from r = 0.016 m, L = 0.11 m, max wheel 12.5 rad/s.
#include "dream/world/unicycle_kinematics.h"

#include <gtest/gtest.h>

#include "dream/robotarium/robotarium_constants.h"

namespace dream::world {
namespace {

constexpr double kR = robotarium::RobotariumConstants::kWheelRadiusMeters;
constexpr double kL = robotarium::RobotariumConstants::kBaseLengthMeters;
constexpr double kMax = robotarium::RobotariumConstants::kMaxWheelVelocityRadps;

TEST(RobotariumConstantsTest, DerivedValuesMatchTheOfficialFormulas) {
  EXPECT_EQ(kMax, 12.5);
  EXPECT_NEAR(robotarium::RobotariumConstants::kMaxAngularVelocityRadps, 3.6363636363636362, 1e-15);
  EXPECT_EQ(robotarium::RobotariumConstants::kMaxRobotsInSimulation, 50);
  EXPECT_EQ(robotarium::RobotariumConstants::kMaxRobotsOnHardware, 20);
}

TEST(UnicycleKinematicsTest, StraightAndTurnInPlaceToWheels) {
  // 2v / 2r = 0.1 / 0.016 = 6.25 rad/s on both wheels.
  const WheelSpeeds straight = UnicycleToWheelSpeeds({0.1, 0.0}, kR, kL);
  EXPECT_DOUBLE_EQ(straight.left_radps, 6.25);
  EXPECT_DOUBLE_EQ(straight.right_radps, 6.25);
  // L w / 2r = 0.11 / 0.032 = 3.4375 rad/s, left backwards.
  const WheelSpeeds spin = UnicycleToWheelSpeeds({0.0, 1.0}, kR, kL);
  EXPECT_DOUBLE_EQ(spin.left_radps, -3.4375);
  EXPECT_DOUBLE_EQ(spin.right_radps, 3.4375);
}

TEST(UnicycleKinematicsTest, WheelsBackToUnicycle) {
  const UnicycleCommand command = WheelSpeedsToUnicycle({2.5, 12.5}, kR, kL);
  // v = 0.008 * 15 = 0.12; w = (0.016 / 0.11) * 10 = 1.4545...
  EXPECT_DOUBLE_EQ(command.v_mps, 0.12);
  EXPECT_DOUBLE_EQ(command.w_radps, 0.16 / 0.11);
}

TEST(UnicycleKinematicsTest, PureForwardOverTheLimitClipsToMaxSpeed) {
  // 0.3 m/s needs 18.75 rad/s per wheel; both clip to 12.5 -> 0.2 m/s.
  EXPECT_TRUE(ExceedsWheelSpeedLimit(UnicycleToWheelSpeeds({0.3, 0.0}, kR, kL), kMax));
  const UnicycleCommand saturated = SaturateUnicycleCommand({0.3, 0.0}, kR, kL, kMax);
  EXPECT_EQ(saturated.v_mps, 0.2);
  EXPECT_EQ(saturated.w_radps, 0.0);
}

TEST(UnicycleKinematicsTest, PureRotationOverTheLimitClipsToMaxTurnRate) {
  // 6 rad/s needs -+20.625 rad/s; clipped to -+12.5 -> w = 25 r / L = 3.636 rad/s.
  const UnicycleCommand saturated = SaturateUnicycleCommand({0.0, 6.0}, kR, kL, kMax);
  EXPECT_EQ(saturated.v_mps, 0.0);
  EXPECT_DOUBLE_EQ(saturated.w_radps, robotarium::RobotariumConstants::kMaxAngularVelocityRadps);
}

TEST(UnicycleKinematicsTest, MixedCommandSaturatesOnlyOneWheelAndBends) {
  // (0.15, 2): left 2.5, right 16.25 -> 12.5. v drops to 0.12, w to 1.4545.
  const UnicycleCommand forward = SaturateUnicycleCommand({0.15, 2.0}, kR, kL, kMax);
  EXPECT_DOUBLE_EQ(forward.v_mps, 0.12);
  EXPECT_DOUBLE_EQ(forward.w_radps, 0.16 / 0.11);
  // Reversing mirrors the left wheel: -16.25 -> -12.5, right -2.5.
  const UnicycleCommand backward = SaturateUnicycleCommand({-0.15, 2.0}, kR, kL, kMax);
  EXPECT_DOUBLE_EQ(backward.v_mps, -0.12);
  EXPECT_DOUBLE_EQ(backward.w_radps, 0.16 / 0.11);
}

TEST(UnicycleKinematicsTest, ExactlyAtTheLimitIsNotAnError) {
  // 0.2 m/s straight is exactly 12.5 rad/s per wheel: allowed (strict >).
  EXPECT_FALSE(ExceedsWheelSpeedLimit(UnicycleToWheelSpeeds({0.2, 0.0}, kR, kL), kMax));
  EXPECT_TRUE(ExceedsWheelSpeedLimit(UnicycleToWheelSpeeds({0.2000001, 0.0}, kR, kL), kMax));
}

TEST(UnicycleKinematicsTest, InLimitRoundTripIsTheOfficialArithmetic) {
  // (0.1, 1): left = 31.25 * (0.2 - 0.11) = 2.8125000000000004 in doubles;
  // the round trip still lands on (0.1, 1.0) exactly, as in numpy.
  const UnicycleCommand round_trip = SaturateUnicycleCommand({0.1, 1.0}, kR, kL, kMax);
  EXPECT_EQ(round_trip.v_mps, 0.1);
  EXPECT_EQ(round_trip.w_radps, 1.0);
}

}  // namespace
}  // namespace dream::world
