#include <gtest/gtest.h>

#include <cmath>

#include "dream/agents/actuator_limits.h"
#include "dream/agents/go_to_goal_robot.h"
#include "dream/agents/single_integrator_to_unicycle.h"

namespace dream::agents {
namespace {

double FastestWheel(const UnicycleCommand& c, const RobotLimits& l = {}) {
  return (std::abs(c.v_mps) + l.base_length_m / 2.0 * std::abs(c.w_radps)) / l.wheel_radius_m;
}

TEST(ActuatorLimitsTest, FeasibleCommandsPassUnchanged) {
  const ActuatorLimits limits;
  const UnicycleCommand out = limits.Apply({0.1, 1.0});
  EXPECT_DOUBLE_EQ(out.v_mps, 0.1);
  EXPECT_DOUBLE_EQ(out.w_radps, 1.0);
}

TEST(ActuatorLimitsTest, ClipsThenShrinksSpeedKeepingTurnRate) {
  const ActuatorLimits limits;
  // v clipped to 0.2; w = 2 needs 0.11 m of wheel travel per rad: v shrinks to
  // (12.5 - 0.11 / 0.032 * 2) * 0.016 = 0.09.
  const UnicycleCommand out = limits.Apply({0.5, 2.0});
  EXPECT_DOUBLE_EQ(out.w_radps, 2.0);
  EXPECT_NEAR(out.v_mps, 0.09, 1e-9);
  EXPECT_NEAR(FastestWheel(out), 12.5, 1e-7);
  EXPECT_LT(FastestWheel(out), 12.5);  // strictly inside, so the world never sees it one ulp over
  const UnicycleCommand backwards = limits.Apply({-0.5, -2.0});
  EXPECT_NEAR(backwards.v_mps, -0.09, 1e-9);
  // Spinning at the angular limit leaves no room for forward speed.
  const UnicycleCommand spin = limits.Apply({0.2, 100.0});
  EXPECT_NEAR(spin.w_radps, 0.2 / 0.055, 1e-12);
  EXPECT_NEAR(spin.v_mps, 0.0, 1e-12);
  EXPECT_LE(FastestWheel(spin), 12.5 + 1e-9);
}

TEST(ActuatorLimitsTest, NonFiniteBecomesStop) {
  const UnicycleCommand out = ActuatorLimits().Apply({std::nan(""), 1.0});
  EXPECT_EQ(out.v_mps, 0.0);
  EXPECT_EQ(out.w_radps, 0.0);
}

TEST(SingleIntegratorToUnicycleTest, MatchesTheRobotariumMapping) {
  const SingleIntegratorToUnicycle map;  // gain 1, angular limit pi
  // Heading +x, desired +x: straight ahead.
  UnicycleCommand c = map.Map({0.1, 0.0}, 0.0);
  EXPECT_DOUBLE_EQ(c.v_mps, 0.1);
  EXPECT_DOUBLE_EQ(c.w_radps, 0.0);
  // Desired velocity 90 degrees to the left: no forward speed, turn at pi.
  c = map.Map({0.0, 0.1}, 0.0);
  EXPECT_NEAR(c.v_mps, 0.0, 1e-15);
  EXPECT_NEAR(c.w_radps, M_PI, 1e-12);
  // 45 degrees to the right while heading +y.
  c = map.Map({0.1, 0.1}, M_PI / 2);
  EXPECT_NEAR(c.v_mps, 0.1, 1e-12);
  EXPECT_NEAR(c.w_radps, -M_PI / 2, 1e-12);
  EXPECT_THROW(SingleIntegratorToUnicycle(0.0), std::invalid_argument);
  EXPECT_THROW(SingleIntegratorToUnicycle(1.0, -1.0), std::invalid_argument);
}

/// Feeds a robot its exact pose as odometry.
void See(Robot& robot, const Eigen::Vector3d& pose) { robot.OnOdometry({0, pose}); }

TEST(GoToGoalRobotTest, DrivesTowardTheGoalAndReportsDoneWithinTolerance) {
  GoToGoalParams params;
  params.goal_m = {1.0, 0.0};
  GoToGoalRobot robot(0, RobotParams{}, params);
  // Before any odometry it does not know where it is, so it holds still.
  UnicycleCommand command = robot.Update(0);
  EXPECT_EQ(command.v_mps, 0.0);
  See(robot, {0.0, 0.0, 0.0});
  command = robot.Update(1);
  EXPECT_FALSE(robot.done());
  EXPECT_NEAR(command.v_mps, 0.15, 1e-12);  // capped at max_speed
  EXPECT_NEAR(command.w_radps, 0.0, 1e-12);
  See(robot, {0.99, 0.0, 2.0});
  command = robot.Update(2);
  EXPECT_TRUE(robot.done());
  EXPECT_EQ(command.v_mps, 0.0);
}

TEST(GoToGoalRobotTest, ReachesItsGoalUnderUnicycleKinematics) {
  GoToGoalParams params;
  params.goal_m = {-0.4, 0.3};
  GoToGoalRobot robot(0, RobotParams{}, params);
  Eigen::Vector3d pose(0.5, -0.2, 2.5);
  for (int step = 0; step < 2000 && !robot.done(); ++step) {
    See(robot, pose);
    const UnicycleCommand command = robot.Update(step);
    EXPECT_LE(FastestWheel(command), 12.5 + 1e-9);
    pose.x() += 0.033 * command.v_mps * std::cos(pose.z());
    pose.y() += 0.033 * command.v_mps * std::sin(pose.z());
    pose.z() += 0.033 * command.w_radps;
  }
  EXPECT_TRUE(robot.done());
  EXPECT_LE((pose.head<2>() - params.goal_m).norm(), params.tolerance_m);
}

TEST(GoToGoalParamsTest, InvalidParamsNameTheField) {
  GoToGoalParams params;
  params.max_speed_mps = 0.5;
  std::string error;
  EXPECT_FALSE(params.IsValid(&error));
  EXPECT_NE(error.find("max_speed_mps must be in (0, 0.2]"), std::string::npos) << error;
  params = GoToGoalParams{};
  params.tolerance_m = 0;
  EXPECT_FALSE(params.IsValid(&error));
  EXPECT_NE(error.find("tolerance_m"), std::string::npos);
  EXPECT_THROW(GoToGoalRobot(0, RobotParams{}, params), std::invalid_argument);
}

}  // namespace
}  // namespace dream::agents
