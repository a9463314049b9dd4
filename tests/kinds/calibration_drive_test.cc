// Kind calibration_drive: the open-loop program step by step, the robot that
// drives it and says done at its end, the start poses, and the goal (the
// program ran to its end with no boundary or collision error).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dream/calibration_drive/calibration_drive.h"
#include "dream/calibration_drive/calibration_drive_metrics.h"
#include "dream/calibration_drive/calibration_drive_robot.h"
#include "dream/robotarium/robotarium_constants.h"

namespace dream::agents {
namespace {

using robotarium::RobotariumConstants;

void ExpectCommand(int64_t step, double v, double w) {
  const UnicycleCommand command = calibration_drive::CalibrationDrive::CommandAt(step);
  EXPECT_EQ(command.v_mps, v) << "step " << step;
  EXPECT_EQ(command.w_radps, w) << "step " << step;
}

// Segments of round(seconds / 0.033) steps: rest 2 s (61 steps), 0.05 m/s
// 3 s (91), rest 1.5 s (45), back 3 s (91), rest (45), 0.1 m/s 2 s (61), ...
TEST(CalibrationDriveTest, CommandsEachStepOfTheProgram) {
  EXPECT_EQ(calibration_drive::CalibrationDrive::Steps(), 1480);
  ExpectCommand(-1, 0.0, 0.0);
  ExpectCommand(0, 0.0, 0.0);
  ExpectCommand(60, 0.0, 0.0);
  ExpectCommand(61, 0.05, 0.0);
  ExpectCommand(151, 0.05, 0.0);
  ExpectCommand(152, 0.0, 0.0);
  ExpectCommand(196, 0.0, 0.0);
  ExpectCommand(197, -0.05, 0.0);
  ExpectCommand(287, -0.05, 0.0);
  ExpectCommand(288, 0.0, 0.0);
  ExpectCommand(333, 0.1, 0.0);
  ExpectCommand(calibration_drive::CalibrationDrive::Steps() - 1, 0.0, 0.0);
  ExpectCommand(calibration_drive::CalibrationDrive::Steps(), 0.0, 0.0);
  ExpectCommand(int64_t{1} << 40, 0.0, 0.0);
}

// What calibrate needs: every speed and turn rate, both ways, from rest; and
// within the wheels' limit (0.19, not 0.2 m/s).
TEST(CalibrationDriveTest, ExcitesEverySpeedAndTurnBothWaysWithinTheWheelLimit) {
  std::vector<std::pair<double, double>> starts;
  UnicycleCommand before;
  for (int64_t k = 0; k < calibration_drive::CalibrationDrive::Steps(); ++k) {
    const UnicycleCommand command = calibration_drive::CalibrationDrive::CommandAt(k);
    const double wheel_radps =
        (std::abs(command.v_mps) + std::abs(command.w_radps) * RobotariumConstants::kBaseLengthMeters / 2) /
        RobotariumConstants::kWheelRadiusMeters;
    EXPECT_LT(wheel_radps, RobotariumConstants::kMaxWheelVelocityRadps) << "step " << k;
    if (before.v_mps == 0.0 && before.w_radps == 0.0 && (command.v_mps != 0.0 || command.w_radps != 0.0)) {
      starts.emplace_back(command.v_mps, command.w_radps);
    }
    before = command;
  }
  const std::vector<std::pair<double, double>> expected = {{0.05, 0.0}, {-0.05, 0.0}, {0.1, 0.0}, {-0.1, 0.0},
                                                           {0.19, 0.0}, {-0.19, 0.0}, {0.0, 1.0}, {0.0, -1.0},
                                                           {0.0, 2.0},  {0.0, -2.0},  {0.1, 0.5}, {-0.1, -0.5}};
  EXPECT_EQ(starts, expected);
}

// Driven with the official (Euler) unicycle step, each robot comes back to
// within 5 mm of its start (the arc back is not the arc's exact inverse),
// and never leaves a box that fits beside its neighbours.
TEST(CalibrationDriveTest, EndsWhereItStartedAndStaysNearItsStart) {
  double x = 0, y = 0, theta = 0, max_dx = 0, min_dx = 0, max_dy = 0, min_dy = 0;
  for (int64_t k = 0; k < calibration_drive::CalibrationDrive::Steps(); ++k) {
    const UnicycleCommand command = calibration_drive::CalibrationDrive::CommandAt(k);
    x += command.v_mps * std::cos(theta) * RobotariumConstants::kTimeStepSeconds;
    y += command.v_mps * std::sin(theta) * RobotariumConstants::kTimeStepSeconds;
    theta += command.w_radps * RobotariumConstants::kTimeStepSeconds;
    max_dx = std::max(max_dx, x);
    min_dx = std::min(min_dx, x);
    max_dy = std::max(max_dy, y);
    min_dy = std::min(min_dy, y);
  }
  EXPECT_NEAR(x, 0.0, 0.005);
  EXPECT_NEAR(y, 0.0, 0.005);
  EXPECT_NEAR(theta, 0.0, 1e-9);
  EXPECT_LE(max_dx, 0.31);
  EXPECT_GE(min_dx, -0.01);
  EXPECT_LE(max_dy, 0.1);
  EXPECT_GE(min_dy, -0.01);
}

TEST(CalibrationDriveTest, StartPosesFitTheArenaAndAreSpacedForTheProgram) {
  for (int robots = 1; robots <= calibration_drive::CalibrationDrive::kMaxRobots; ++robots) {
    const std::vector<Eigen::Vector3d> poses = calibration_drive::CalibrationDrive::StartPoses(robots);
    ASSERT_EQ(poses.size(), static_cast<size_t>(robots));
    for (const Eigen::Vector3d& pose : poses) {
      // The robot drives up to 0.3 m ahead and swings 0.1 m to its left.
      EXPECT_GE(pose.x() - 0.1, RobotariumConstants::kArenaXMinMeters);
      EXPECT_LE(pose.x() + 0.3 + 0.1, RobotariumConstants::kArenaXMaxMeters);
      EXPECT_GE(pose.y() - 0.1, RobotariumConstants::kArenaYMinMeters);
      EXPECT_LE(pose.y() + 0.1 + 0.1, RobotariumConstants::kArenaYMaxMeters);
      EXPECT_EQ(pose.z(), 0.0);
    }
    for (size_t i = 0; i < poses.size(); ++i) {
      for (size_t j = i + 1; j < poses.size(); ++j) {
        EXPECT_GE((poses[i] - poses[j]).head<2>().norm(), 0.4 - 1e-9) << robots << " robots: " << i << ", " << j;
      }
    }
  }
  EXPECT_THROW(calibration_drive::CalibrationDrive::StartPoses(0), std::invalid_argument);
  EXPECT_THROW(calibration_drive::CalibrationDrive::StartPoses(calibration_drive::CalibrationDrive::kMaxRobots + 1),
               std::invalid_argument);
}

TEST(CalibrationDriveRobotTest, DrivesTheProgramOpenLoopAndIsDoneAtItsEnd) {
  calibration_drive::CalibrationDriveRobot robot(3, RobotParams{});
  for (int64_t k = 0; k < calibration_drive::CalibrationDrive::Steps() - 1; ++k) {
    const UnicycleCommand command = robot.Update(k);
    EXPECT_EQ(command.v_mps, calibration_drive::CalibrationDrive::CommandAt(k).v_mps) << "step " << k;
    EXPECT_EQ(command.w_radps, calibration_drive::CalibrationDrive::CommandAt(k).w_radps) << "step " << k;
    ASSERT_FALSE(robot.done()) << "step " << k;
  }
  robot.Update(calibration_drive::CalibrationDrive::Steps() - 1);
  EXPECT_TRUE(robot.done());
  const UnicycleCommand after = robot.Update(calibration_drive::CalibrationDrive::Steps() + 5);
  EXPECT_EQ(after.v_mps, 0.0);
  EXPECT_EQ(after.w_radps, 0.0);
  EXPECT_TRUE(robot.done());
}

// The goal over `steps` snapshots of two robots; `move` places them per step.
template <typename Move>
GoalJudgement JudgeRun(int64_t steps, Move move) {
  calibration_drive::CalibrationDriveMetrics metrics;
  for (int64_t k = 0; k <= steps; ++k) {
    WorldSnapshot world;
    world.step = k;
    world.poses = {Eigen::Vector3d(-0.5, 0.0, 0.0), Eigen::Vector3d(0.5, 0.0, 0.0)};
    move(k, &world.poses);
    metrics.Observe(world);
  }
  MetricsReport report;
  metrics.Write(&report);
  return *metrics.JudgeGoal(report);
}

TEST(CalibrationDriveMetricsTest, MetWhenTheProgramRanToItsEndClean) {
  const GoalJudgement goal = JudgeRun(calibration_drive::CalibrationDrive::Steps(), [](int64_t, auto*) {});
  EXPECT_TRUE(goal.met) << goal.detail;
  EXPECT_EQ(goal.completion_step, calibration_drive::CalibrationDrive::Steps());
  EXPECT_EQ(goal.detail, "the program ran clean");
}

TEST(CalibrationDriveMetricsTest, MissedWhenCutShortOutsideTheArenaOrColliding) {
  const GoalJudgement cut = JudgeRun(100, [](int64_t, auto*) {});
  EXPECT_FALSE(cut.met);
  EXPECT_EQ(cut.completion_step, -1);
  EXPECT_EQ(cut.detail, "cut short at step 100 of 1480");

  // Robot 1 just past the right wall at steps 200-202.
  const GoalJudgement outside = JudgeRun(calibration_drive::CalibrationDrive::Steps(), [](int64_t k, auto* poses) {
    if (k >= 200 && k <= 202) (*poses)[1].x() = RobotariumConstants::kArenaXMaxMeters + 1e-6;
  });
  EXPECT_FALSE(outside.met);
  EXPECT_EQ(outside.detail, "3 steps outside the arena (first 200), 0 with a collision (first -1)");

  // Facing each other 0.185 m apart: their points 0.025 m ahead are 0.135 m
  // apart, a collision by the Robotarium's rule; facing away, none.
  const GoalJudgement facing = JudgeRun(calibration_drive::CalibrationDrive::Steps(), [](int64_t k, auto* poses) {
    if (k != 700) return;
    (*poses)[0] = Eigen::Vector3d(0.0, 0.0, 0.0);
    (*poses)[1] = Eigen::Vector3d(0.185, 0.0, M_PI);
  });
  EXPECT_FALSE(facing.met);
  EXPECT_EQ(facing.detail, "0 steps outside the arena (first -1), 1 with a collision (first 700)");
  const GoalJudgement away = JudgeRun(calibration_drive::CalibrationDrive::Steps(), [](int64_t k, auto* poses) {
    if (k != 700) return;
    (*poses)[0] = Eigen::Vector3d(0.0, 0.0, M_PI);
    (*poses)[1] = Eigen::Vector3d(0.185, 0.0, 0.0);
  });
  EXPECT_TRUE(away.met) << away.detail;
}

}  // namespace
}  // namespace dream::agents
