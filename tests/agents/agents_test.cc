#include <gtest/gtest.h>

#include <cmath>

#include "dream/agents/framework/actuator_limits.h"
#include "dream/go_to_goal/go_to_goal_robot.h"
#include "dream/agents/framework/robot.h"
#include "dream/agents/geometry/single_integrator_to_unicycle.h"

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

/// The smallest Robot: exposes the protected mapping and bad-message counter.
class BareRobot final : public Robot {
 public:
  explicit BareRobot(RobotParams params = {}) : Robot(0, params) {}
  UnicycleCommand Update(int64_t) override { return {}; }
  UnicycleCommand Drive(const Eigen::Vector2d& dxi_mps) const { return DxiToDxu(dxi_mps); }
  void Reject(const RadioMessage& message) { CountBadRadioMessage(message); }
  void RejectUnnamed() { CountBadRadioMessage(); }
};

RobotParams Gains(double vel_gain, double ang_gain) {
  RobotParams params;
  params.vel_gain = vel_gain;
  params.ang_gain = ang_gain;
  return params;
}

// Thesis Appendix A, Robot.dxi_to_dxu, with a = cos(theta), b = sin(theta):
//   v = vel_gain (a dx + b dy),  w = ang_gain atan2(-b dx + a dy, v) / (pi/2).
// Expectations below are worked out by hand from that formula.
TEST(RobotDxiToDxuTest, TurnsOnTheSpotTowardsASidewaysVelocity) {
  BareRobot robot;  // vel_gain 0.8, ang_gain 3.0
  See(robot, {0.0, 0.0, 0.0});
  // Heading +x, desired +y: v = 0.8 (1 * 0 + 0 * 0.1) = 0; w = 3 atan2(0.1, 0) / (pi/2) = 3.
  UnicycleCommand c = robot.Drive({0.0, 0.1});
  EXPECT_NEAR(c.v_mps, 0.0, 1e-15);
  EXPECT_NEAR(c.w_radps, 3.0, 1e-12);
  // Heading +y, desired +x (to its right): v = 0.8 (cos(pi/2) 0.1) ~ 0; w = 3 atan2(-0.1, ~0) / (pi/2) = -3.
  See(robot, {0.0, 0.0, M_PI / 2});
  c = robot.Drive({0.1, 0.0});
  EXPECT_NEAR(c.v_mps, 0.0, 1e-15);
  EXPECT_NEAR(c.w_radps, -3.0, 1e-12);
  // Heading +y, desired +y: straight on at 0.8 x 0.2 = 0.16 m/s, no turn.
  c = robot.Drive({0.0, 0.2});
  EXPECT_NEAR(c.v_mps, 0.16, 1e-12);
  EXPECT_NEAR(c.w_radps, 0.0, 1e-12);
}

TEST(RobotDxiToDxuTest, TheTurnUsesTheScaledSpeedAsTheThesisDoes) {
  // Heading pi/4, desired (0.1, 0): 45 degrees to the right.
  // v = 0.8 * 0.1 cos(pi/4) = 0.0565685; the atan2's other side is -0.1 sin(pi/4) = -0.0707107,
  // so w = 3 atan2(-0.0707107, 0.0565685) / (pi/2) = -3 atan(1 / 0.8) / (pi/2) = -1.7113397,
  // more than the -1.5 of a turn towards the true 45 degrees.
  BareRobot robot;
  See(robot, {0.3, -0.2, M_PI / 4});
  UnicycleCommand c = robot.Drive({0.1, 0.0});
  EXPECT_NEAR(c.v_mps, 0.0565685425, 1e-10);
  EXPECT_NEAR(c.w_radps, -1.7113397249, 1e-9);
  // vel_gain 1: the atan2 sees the true angle, w = 3 (-pi/4) / (pi/2) = -1.5.
  BareRobot unit_gain(Gains(1.0, 3.0));
  See(unit_gain, {0.0, 0.0, M_PI / 4});
  c = unit_gain.Drive({0.1, 0.0});
  EXPECT_NEAR(c.v_mps, 0.0707106781, 1e-10);
  EXPECT_NEAR(c.w_radps, -1.5, 1e-12);
  // ang_gain scales w alone: 1/3 of the first case.
  BareRobot slow_turn(Gains(0.8, 1.0));
  See(slow_turn, {0.0, 0.0, M_PI / 4});
  c = slow_turn.Drive({0.1, 0.0});
  EXPECT_NEAR(c.v_mps, 0.0565685425, 1e-10);
  EXPECT_NEAR(c.w_radps, -1.7113397249 / 3.0, 1e-9);
}

TEST(RobotDxiToDxuTest, AVelocityBehindReversesAndTurnsPastNinetyDegrees) {
  // Heading +x, desired (-0.1, 0.05): v = 0.8 * -0.1 = -0.08;
  // w = 3 atan2(0.05, -0.08) / (pi/2) = 3 (pi - atan(0.625)) / (pi/2) = 4.9331539 (then LimitActuators caps it).
  BareRobot robot;
  See(robot, {0.0, 0.0, 0.0});
  const UnicycleCommand c = robot.Drive({-0.1, 0.05});
  EXPECT_NEAR(c.v_mps, -0.08, 1e-12);
  EXPECT_NEAR(c.w_radps, 4.9331538931, 1e-9);
}

TEST(RobotDxiToDxuTest, TheStaticMappingIsTheRobotsOwn) {
  // Harnesses without a Robot (hrvo_swap_harness) use the static form; it must be the same function.
  const RobotParams params = Gains(0.7, 2.5);
  BareRobot robot(params);
  for (const double theta : {-2.9, -1.0, 0.0, 0.4, 1.9, 3.1}) {
    See(robot, {0.1, 0.2, theta});
    for (const Eigen::Vector2d& dxi :
         {Eigen::Vector2d(0.1, 0.0), Eigen::Vector2d(-0.05, 0.12), Eigen::Vector2d(0.0, -0.2)}) {
      const UnicycleCommand member = robot.Drive(dxi);
      const UnicycleCommand free = Robot::DxiToDxu(dxi, theta, params);
      EXPECT_EQ(member.v_mps, free.v_mps);
      EXPECT_EQ(member.w_radps, free.w_radps);
    }
  }
}

TEST(RobotTest, BadRadioMessagesAreCountedPerSender) {
  BareRobot robot;
  robot.Reject(RadioMessage{4, 10, {1}});
  robot.Reject(RadioMessage{4, 11, {1}});
  robot.Reject(RadioMessage{2, 11, {}});
  robot.RejectUnnamed();
  EXPECT_EQ(robot.bad_radio_messages(), 4);
  const std::map<int, long> expected{{Robot::kUnknownSender, 1}, {2, 1}, {4, 2}};
  EXPECT_EQ(robot.bad_radio_messages_by_sender(), expected);
}

TEST(GoToGoalRobotTest, DrivesTowardTheGoalAndReportsDoneWithinTolerance) {
  go_to_goal::GoToGoalParams params;
  params.goal_m = {1.0, 0.0};
  go_to_goal::GoToGoalRobot robot(0, RobotParams{}, params);
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
  go_to_goal::GoToGoalParams params;
  params.goal_m = {-0.4, 0.3};
  go_to_goal::GoToGoalRobot robot(0, RobotParams{}, params);
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
  go_to_goal::GoToGoalParams params;
  params.max_speed_mps = 0.5;
  std::string error;
  EXPECT_FALSE(params.IsValid(&error));
  EXPECT_NE(error.find("max_speed_mps must be in (0, 0.2]"), std::string::npos) << error;
  params = go_to_goal::GoToGoalParams{};
  params.tolerance_m = 0;
  EXPECT_FALSE(params.IsValid(&error));
  EXPECT_NE(error.find("tolerance_m"), std::string::npos);
  EXPECT_THROW(go_to_goal::GoToGoalRobot(0, RobotParams{}, params), std::invalid_argument);
}

}  // namespace
}  // namespace dream::agents
