// RealisticWorld (world.realism): each model on its own against the true
// world, determinism from the seed, and that ideal params through the
// decorator step exactly like the official UnicycleWorld.
#include "dream/world/realistic_world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "dream/world/realism_params.h"
#include "dream/robotarium/robotarium_constants.h"
#include "dream/world/unicycle_world.h"

namespace dream::world {
namespace {

constexpr double kDt = robotarium::RobotariumConstants::kTimeStepSeconds;
constexpr double kWheelRadius = robotarium::RobotariumConstants::kWheelRadiusMeters;

std::vector<Pose2> ThreeRobots() { return {{-0.5, 0.0, 0.0}, {0.5, 0.0, 3.14159}, {0.0, 0.6, -1.0}}; }

// Commands that turn, some over the wheel limit, and bring robots 0 and 1 into
// collision, so every violation count moves.
UnicycleCommand CommandFor(int robot, int64_t step) {
  const double phase = 0.05 * static_cast<double>(step) + robot;
  return {0.15 + 0.1 * std::sin(phase), (robot == 2 ? 4.0 : 0.5) * std::cos(phase)};
}

TEST(RealisticWorldTest, IdealParamsStepExactlyLikeTheOfficialWorld) {
  UnicycleWorld official(WorldParams{}, ThreeRobots());
  RealisticWorld realistic(WorldParams{}, RealismParams::Ideal(), 7, ThreeRobots());
  for (int64_t step = 0; step < 300; ++step) {
    for (int robot = 0; robot < 3; ++robot) {
      official.SetCommand(robot, CommandFor(robot, step));
      realistic.SetCommand(robot, CommandFor(robot, step));
    }
    official.Step();
    realistic.Step();
    for (size_t i = 0; i < 3; ++i) {
      ASSERT_EQ(realistic.poses()[i].x_m, official.poses()[i].x_m) << "step " << step;
      ASSERT_EQ(realistic.poses()[i].y_m, official.poses()[i].y_m) << "step " << step;
      ASSERT_EQ(realistic.poses()[i].theta_rad, official.poses()[i].theta_rad) << "step " << step;
      ASSERT_EQ(realistic.velocities()[i].v_mps, official.velocities()[i].v_mps);
    }
  }
  EXPECT_EQ(realistic.violations(), official.violations());
  EXPECT_GT(official.violations().actuator_errors, 0);
  EXPECT_GT(official.violations().collision_errors + official.violations().boundary_errors, 0);
}

TEST(RealisticWorldTest, SameSeedGivesTheSamePosesAndAnotherSeedOthers) {
  auto run = [](uint64_t seed) {
    RealisticWorld world(WorldParams{}, RealismParams::Lab(), seed, ThreeRobots());
    std::vector<double> trace;
    for (int64_t step = 0; step < 200; ++step) {
      for (int robot = 0; robot < 3; ++robot) world.SetCommand(robot, CommandFor(robot, step));
      world.Step();
      for (const Pose2& pose : world.poses()) trace.insert(trace.end(), {pose.x_m, pose.y_m, pose.theta_rad});
      for (const Pose2& pose : world.true_poses()) trace.insert(trace.end(), {pose.x_m, pose.y_m, pose.theta_rad});
    }
    return trace;
  };
  EXPECT_EQ(run(11), run(11));
  EXPECT_NE(run(11), run(12));
}

// Robots that never move: every measurement is truth + noise.
TEST(RealisticWorldTest, PoseNoiseHasTheConfiguredMeanAndDeviation) {
  RealismParams realism;
  realism.pose_noise_m = 0.01;
  realism.pose_noise_rad = 0.02;
  RealisticWorld world(WorldParams{}, realism, 5, ThreeRobots());
  double sum_x = 0, sum_xx = 0, sum_t = 0, sum_tt = 0;
  int n = 0;
  for (int step = 0; step < 4000; ++step) {
    world.Step();
    for (size_t i = 0; i < 3; ++i) {
      const double ex = world.poses()[i].x_m - world.true_poses()[i].x_m;
      const double et = std::remainder(world.poses()[i].theta_rad - world.true_poses()[i].theta_rad, 2 * M_PI);
      sum_x += ex;
      sum_xx += ex * ex;
      sum_t += et;
      sum_tt += et * et;
      ++n;
    }
  }
  const double mean_x = sum_x / n, mean_t = sum_t / n;
  EXPECT_LT(std::abs(mean_x), 4 * 0.01 / std::sqrt(n));
  EXPECT_LT(std::abs(mean_t), 4 * 0.02 / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(sum_xx / n - mean_x * mean_x), 0.01, 0.0005);
  EXPECT_NEAR(std::sqrt(sum_tt / n - mean_t * mean_t), 0.02, 0.001);
  // The truth is untouched by the measurement.
  EXPECT_EQ(world.true_poses()[0].x_m, -0.5);
}

TEST(RealisticWorldTest, QuantisationRoundsMeasuredPoses) {
  RealismParams realism;
  realism.pose_quantum_m = 0.01;
  realism.pose_quantum_rad = 0.05;
  RealisticWorld world(WorldParams{}, realism, 1, {{0.123456, -0.3333, 0.777}});
  for (int step = 0; step < 50; ++step) {
    world.SetCommand(0, {0.1, 0.3});
    world.Step();
    const Pose2& measured = world.poses()[0];
    const Pose2& truth = world.true_poses()[0];
    EXPECT_NEAR(measured.x_m / 0.01, std::round(measured.x_m / 0.01), 1e-9);
    EXPECT_NEAR(measured.y_m / 0.01, std::round(measured.y_m / 0.01), 1e-9);
    EXPECT_NEAR(measured.theta_rad / 0.05, std::round(measured.theta_rad / 0.05), 1e-9);
    EXPECT_LE(std::abs(measured.x_m - truth.x_m), 0.005 + 1e-12);
    EXPECT_LE(std::abs(measured.theta_rad - truth.theta_rad), 0.025 + 1e-12);
  }
}

// The lab's tracker wraps a heading to [-pi, pi) and then rounds it: every
// heading lies on the 1 mrad grid, also near +-pi (rounding first and then
// wrapping gave values such as 3.155 - 2 pi, off the grid).
TEST(RealisticWorldTest, HeadingsAreWrappedThenRoundedSoAllStayOnTheGrid) {
  RealismParams realism = RealismParams::Lab();
  realism.tracking_dropout_probability = 0.0;
  RealisticWorld world(WorldParams{}, realism, 3, {{0.0, 0.0, 3.14}, {0.5, 0.0, -3.14}});
  int near_pi = 0;
  for (int step = 0; step < 6000; ++step) {
    world.SetCommand(0, {0.0, 2.0});
    world.SetCommand(1, {0.0, -2.0});
    world.Step();
    for (const Pose2& measured : world.poses()) {
      const double units = measured.theta_rad / 0.001;
      ASSERT_NEAR(units, std::round(units), 1e-6) << measured.theta_rad << " at step " << step;
      ASSERT_GE(measured.theta_rad, -M_PI) << "step " << step;
      ASSERT_LT(measured.theta_rad, M_PI) << "step " << step;
      near_pi += std::abs(measured.theta_rad) > 3.13;
    }
  }
  EXPECT_GT(near_pi, 20) << "the robots must pass +-pi often for this to test anything";
}

TEST(RealisticWorldTest, PoseDelaySendsThePosesOfEarlierSteps) {
  RealismParams realism;
  realism.pose_delay_steps = 3;
  RealisticWorld world(WorldParams{}, realism, 1, {{0.0, 0.0, 0.0}});
  std::vector<Pose2> truth{world.true_poses()[0]};
  for (int64_t step = 1; step <= 30; ++step) {
    world.SetCommand(0, {0.1, 0.2});
    world.Step();
    truth.push_back(world.true_poses()[0]);
    const Pose2& expected = truth[static_cast<size_t>(std::max<int64_t>(0, step - 3))];
    EXPECT_EQ(world.poses()[0].x_m, expected.x_m) << "step " << step;
    EXPECT_EQ(world.poses()[0].theta_rad, expected.theta_rad) << "step " << step;
  }
  EXPECT_NE(world.poses()[0].x_m, world.true_poses()[0].x_m);
}

TEST(RealisticWorldTest, TrackingDropoutsRepeatTheLastMeasurement) {
  RealismParams never_seen;
  never_seen.tracking_dropout_probability = 1.0;
  RealisticWorld frozen(WorldParams{}, never_seen, 1, {{0.0, 0.0, 0.0}});
  for (int step = 0; step < 20; ++step) {
    frozen.SetCommand(0, {0.1, 0.0});
    frozen.Step();
  }
  EXPECT_EQ(frozen.poses()[0].x_m, 0.0);  // step 0 is always measured
  EXPECT_GT(frozen.true_poses()[0].x_m, 0.05);

  RealismParams some;
  some.tracking_dropout_probability = 0.3;
  RealisticWorld world(WorldParams{}, some, 9, {{-1.0, 0.0, 0.0}});
  int repeated = 0;
  const int steps = 3000;
  for (int step = 0; step < steps; ++step) {
    const double before = world.poses()[0].x_m;
    world.SetCommand(0, {0.1, 0.0});  // 0.0033 m a step: every fresh measurement differs
    world.Step();
    if (world.poses()[0].x_m == before) {
      ++repeated;
    } else {
      EXPECT_EQ(world.poses()[0].x_m, world.true_poses()[0].x_m);
    }
  }
  EXPECT_NEAR(static_cast<double>(repeated) / steps, 0.3, 0.03);
}

// Drives every robot straight at 0.1 m/s for `steps` steps; returns, per step
// and robot, whether the measured pose is the one sent the step before.
std::vector<std::vector<bool>> RepeatedMeasurements(RealisticWorld& world, int steps) {
  std::vector<std::vector<bool>> repeated;
  for (int step = 0; step < steps; ++step) {
    const std::vector<Pose2> before = world.poses();
    for (int robot = 0; robot < world.num_robots(); ++robot) world.SetCommand(robot, {0.1, 0.0});
    world.Step();
    std::vector<bool> row;
    for (size_t i = 0; i < before.size(); ++i) row.push_back(world.poses()[i].x_m == before[i].x_m);
    repeated.push_back(row);
  }
  return repeated;
}

TEST(RealisticWorldTest, TrackerDropsARobotWithoutAPoseForLongerThanTrackerDropS) {
  RealismParams realism;
  realism.tracking_dropout_probability = 1.0;  // nothing after step 0
  realism.tracker_drop_s = 0.2;                // 6 steps of 0.033 s are 0.198 s: the 7th missing one drops it
  RealisticWorld world(WorldParams{}, realism, 1, {{0.0, 0.0, 0.0}, {0.0, 0.5, 0.0}});
  RepeatedMeasurements(world, 200);
  ASSERT_EQ(world.tracker_losses().size(), 2u);
  EXPECT_EQ(world.tracker_losses()[0].robot_id, 0);
  EXPECT_EQ(world.tracker_losses()[0].step, 7);
  EXPECT_EQ(world.tracker_losses()[1].robot_id, 1);
  EXPECT_EQ(world.tracker_losses()[1].step, 7);
  // What the agents see of a lost robot: its last measurement, as in a dropout; the robot still drives.
  EXPECT_EQ(world.poses()[0].x_m, 0.0);
  EXPECT_EQ(world.poses()[1].y_m, 0.5);
  EXPECT_NEAR(world.true_poses()[0].x_m, 200 * 0.1 * kDt, 1e-9);
  EXPECT_EQ(world.dropped_measurements(), 2 * 7);  // not counted after the loss

  const std::optional<VerdictReason> reason = world.TrackerLossReason();
  ASSERT_TRUE(reason.has_value());
  EXPECT_EQ(reason->rule, "tracker_lost");
  EXPECT_EQ(reason->verdict, RunVerdict::kWarning);
  EXPECT_NE(reason->problem.find("robots 0 (from step 7), 1 (from step 7) lost to the tracker"), std::string::npos)
      << reason->problem;
  EXPECT_NE(reason->problem.find("over 0.2 s"), std::string::npos) << reason->problem;
}

TEST(RealisticWorldTest, TrackerDropOffOrShortDropoutsLoseNoRobot) {
  RealismParams off;
  off.tracking_dropout_probability = 1.0;
  off.tracker_drop_s = 0.0;  // never
  RealisticWorld blind(WorldParams{}, off, 1, {{0.0, 0.0, 0.0}});
  RepeatedMeasurements(blind, 400);  // 13 s without a pose
  EXPECT_TRUE(blind.tracker_losses().empty());
  EXPECT_FALSE(blind.TrackerLossReason().has_value());
  EXPECT_EQ(blind.dropped_measurements(), 400);

  // Dropouts that end in time reset the count: a robot measured again within
  // 0.5 s (15 steps) is never lost, however many dropouts it has.
  RealismParams some;
  some.tracking_dropout_probability = 0.5;
  some.tracker_drop_s = 0.5;
  RealisticWorld world(WorldParams{}, some, 4, {{0.0, 0.0, 0.0}});
  const std::vector<std::vector<bool>> repeated = RepeatedMeasurements(world, 2000);
  int longest = 0;
  int run = 0;
  for (const std::vector<bool>& row : repeated) {
    run = row[0] ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  EXPECT_TRUE(world.tracker_losses().empty());
  EXPECT_GE(longest, 5);
  EXPECT_LE(longest, 15);
  EXPECT_GT(world.dropped_measurements(), 800);
}

TEST(RealisticWorldTest, DropoutBurstsLastTheConfiguredMeanSteps) {
  RealismParams bursts;
  bursts.tracking_dropout_probability = 0.02;
  bursts.tracking_dropout_mean_steps = 10.0;
  RealisticWorld world(WorldParams{}, bursts, 5, {{-1.0, 0.0, 0.0}});
  int count = 0;
  int total = 0;
  bool in_burst = false;
  for (const std::vector<bool>& row : RepeatedMeasurements(world, 30000)) {
    if (row[0]) {
      ++total;
      if (!in_burst) ++count;
    }
    in_burst = row[0];
  }
  ASSERT_GT(count, 200);
  // Geometric bursts: 10 steps on average, a little more as a new dropout may start when one ends.
  const double mean = static_cast<double>(total) / count;
  EXPECT_NEAR(mean, 10.0 / (1.0 - 0.02), 1.5) << count << " bursts";

  // Without bursts the same probability gives dropouts of about one step.
  RealismParams single = bursts;
  single.tracking_dropout_mean_steps = 1.0;
  RealisticWorld independent(WorldParams{}, single, 5, {{-1.0, 0.0, 0.0}});
  int single_total = 0;
  for (const std::vector<bool>& row : RepeatedMeasurements(independent, 30000)) single_total += row[0] ? 1 : 0;
  EXPECT_NEAR(static_cast<double>(single_total) / 30000, 0.02, 0.005);
}

TEST(RealisticWorldTest, TrackerLossesRepeatForASeed) {
  RealismParams realism = RealismParams::Lab();
  realism.tracking_dropout_probability = 0.05;
  realism.tracking_dropout_mean_steps = 40.0;
  realism.tracker_drop_s = 1.0;
  auto run = [&realism](uint64_t seed) {
    RealisticWorld world(WorldParams{}, realism, seed, ThreeRobots());
    std::vector<double> trace;
    for (int64_t step = 0; step < 400; ++step) {
      for (int robot = 0; robot < 3; ++robot) world.SetCommand(robot, CommandFor(robot, step));
      world.Step();
      for (const Pose2& pose : world.poses()) trace.insert(trace.end(), {pose.x_m, pose.y_m, pose.theta_rad});
    }
    for (const RealisticWorld::TrackerLoss& loss : world.tracker_losses()) {
      trace.insert(trace.end(), {static_cast<double>(loss.robot_id), static_cast<double>(loss.step)});
    }
    return std::make_pair(trace, world.tracker_losses().size());
  };
  const auto first = run(11);
  EXPECT_GT(first.second, 0u);
  EXPECT_EQ(run(11), first);
  EXPECT_NE(run(12).first, first.first);
}

// The lab preset's 5 s tracker drop changes nothing while no dropout lasts
// that long: the other models' draws are the same.
TEST(RealisticWorldTest, TrackerDropLeavesOtherDrawsAlone) {
  RealismParams without = RealismParams::Lab();
  without.tracker_drop_s = 0.0;
  RealisticWorld lab(WorldParams{}, RealismParams::Lab(), 3, ThreeRobots());
  RealisticWorld reference(WorldParams{}, without, 3, ThreeRobots());
  for (int64_t step = 0; step < 300; ++step) {
    for (int robot = 0; robot < 3; ++robot) {
      lab.SetCommand(robot, CommandFor(robot, step));
      reference.SetCommand(robot, CommandFor(robot, step));
    }
    lab.Step();
    reference.Step();
    for (size_t i = 0; i < 3; ++i) {
      ASSERT_EQ(lab.poses()[i].x_m, reference.poses()[i].x_m) << "step " << step;
      ASSERT_EQ(lab.poses()[i].theta_rad, reference.poses()[i].theta_rad) << "step " << step;
    }
  }
  EXPECT_TRUE(lab.tracker_losses().empty());
  EXPECT_GT(lab.dropped_measurements(), 0);
}

TEST(RealisticWorldTest, CommandLatencyDelaysWhenACommandActs) {
  RealismParams realism;
  realism.command_latency_steps = 2;
  RealisticWorld world(WorldParams{}, realism, 1, {{0.0, 0.0, 0.0}});
  world.SetCommand(0, {0.1, 0.0});  // answers step 0: acts from step 2
  world.Step();
  world.Step();
  EXPECT_EQ(world.true_poses()[0].x_m, 0.0);
  world.Step();
  EXPECT_DOUBLE_EQ(world.true_poses()[0].x_m, 0.1 * kDt);
}

TEST(RealisticWorldTest, StopRobotDropsQueuedCommands) {
  RealismParams realism;
  realism.command_latency_steps = 1;
  RealisticWorld world(WorldParams{}, realism, 1, {{0.0, 0.0, 0.0}});
  world.SetCommand(0, {0.1, 0.0});
  world.StopRobot(0);
  for (int step = 0; step < 5; ++step) world.Step();
  EXPECT_EQ(world.true_poses()[0].x_m, 0.0);
}

// One command, then silence: the firmware brakes 0.5 s after the command
// reached the robot (15 steps of 0.033 s still drive, the 16th does not).
TEST(RealisticWorldTest, BrakeStopsARobotWhoseCommandIsOlderThanTheLimit) {
  for (int latency : {0, 1}) {
    RealismParams realism;
    realism.command_latency_steps = latency;
    RealisticWorld world(WorldParams{}, realism, 1, {{0.0, 0.0, 0.0}});
    world.SetCommand(0, {0.1, 0.0});
    std::vector<double> v;
    for (int step = 0; step < 25; ++step) {
      world.Step();
      v.push_back(world.true_velocities()[0].v_mps);
    }
    // v[s] is the velocity driven in the step from s to s + 1.
    for (int s = 0; s < 25; ++s) {
      const bool driving = s >= latency && s <= latency + 15;
      EXPECT_EQ(v[static_cast<size_t>(s)] != 0.0, driving) << "latency " << latency << " step " << s;
    }
  }
  RealismParams never;
  never.command_brake_s = 0.0;
  RealisticWorld world(WorldParams{}, never, 1, {{0.0, 0.0, 0.0}});
  world.SetCommand(0, {0.1, 0.0});
  for (int step = 0; step < 100; ++step) world.Step();
  EXPECT_NEAR(world.true_velocities()[0].v_mps, 0.1, 1e-12);
}

TEST(RealisticWorldTest, DeadZoneCoastsOnlyWhenBothSpeedsAreSmall) {
  RealismParams realism;
  realism.dead_zone_v_mps = 1e-4;
  realism.dead_zone_w_radps = 0.01;
  RealisticWorld world(WorldParams{}, realism, 1, {{0.0, 0.0, 0.0}, {0.5, 0.0, 0.0}, {-0.5, 0.0, 0.0}});
  world.SetCommand(0, {5e-5, 0.005});  // both inside: coasts
  world.SetCommand(1, {5e-5, 0.02});   // turning fast enough: follows
  world.SetCommand(2, {2e-4, 0.0});    // moving fast enough: follows
  world.Step();
  EXPECT_EQ(world.true_velocities()[0].v_mps, 0.0);
  EXPECT_EQ(world.true_velocities()[0].w_radps, 0.0);
  EXPECT_DOUBLE_EQ(world.true_velocities()[1].w_radps, 0.02);
  EXPECT_DOUBLE_EQ(world.true_velocities()[2].v_mps, 2e-4);
}

TEST(RealisticWorldTest, WheelAccelerationLimitRampsTheWheels) {
  RealismParams realism;
  realism.wheel_accel_limit_radps2 = 100.0;  // 3.3 rad/s per step
  RealisticWorld world(WorldParams{}, realism, 1, {{0.0, 0.0, 0.0}});
  const double per_step_mps = 100.0 * kDt * kWheelRadius;
  std::vector<double> v;
  for (int step = 0; step < 6; ++step) {
    world.SetCommand(0, {0.2, 0.0});  // both wheels at the 12.5 rad/s limit
    world.Step();
    v.push_back(world.true_velocities()[0].v_mps);
  }
  EXPECT_NEAR(v[0], per_step_mps, 1e-12);
  EXPECT_NEAR(v[1], 2 * per_step_mps, 1e-12);
  EXPECT_NEAR(v[2], 3 * per_step_mps, 1e-12);
  EXPECT_NEAR(v[3], 0.2, 1e-12);  // 4 * 3.3 > 12.5: reached
  EXPECT_NEAR(v[5], 0.2, 1e-12);
  // Stopping ramps down too.
  world.SetCommand(0, {0.0, 0.0});
  world.Step();
  EXPECT_NEAR(world.true_velocities()[0].v_mps, 0.2 - per_step_mps, 1e-12);
}

// v = 0.1, w = 1.9: the outer wheel turns 12.48 rad/s on a 0.105 m axle (under
// the 12.5 limit) but 12.78 rad/s on the simulator's 0.11 m one.
TEST(RealisticWorldTest, AxleLengthSetsTheWheelSaturationButNotTheActuatorCheck) {
  RealismParams lab_axle;
  lab_axle.axle_length_m = 0.105;
  RealisticWorld lab(WorldParams{}, lab_axle, 1, {{0.0, 0.0, 0.0}});
  UnicycleWorld official(WorldParams{}, {{0.0, 0.0, 0.0}});
  lab.SetCommand(0, {0.1, 1.9});
  official.SetCommand(0, {0.1, 1.9});
  lab.Step();
  official.Step();
  EXPECT_DOUBLE_EQ(lab.true_velocities()[0].w_radps, 1.9);
  EXPECT_LT(official.velocities()[0].w_radps, 1.9);
  // The Robotarium judges the command with its own 0.11 m: over the limit in both.
  EXPECT_EQ(lab.violations().actuator_errors, 1);
  EXPECT_EQ(official.violations().actuator_errors, 1);
}

TEST(RealisticWorldTest, LabPresetIsValidAndNotIdeal) {
  std::string error;
  EXPECT_TRUE(RealismParams::Lab().IsValid(&error)) << error;
  EXPECT_FALSE(RealismParams::Lab().IsIdeal());
  EXPECT_TRUE(RealismParams::Ideal().IsIdeal());
  RealismParams preset;
  EXPECT_TRUE(RealismParams::FromPreset("lab", &preset));
  EXPECT_EQ(preset, RealismParams::Lab());
  EXPECT_FALSE(RealismParams::FromPreset("Lab", &preset));
}

TEST(RealisticWorldTest, InvalidParamsAndCommandsThrow) {
  RealismParams bad;
  bad.tracking_dropout_probability = 1.5;
  EXPECT_THROW(RealisticWorld(WorldParams{}, bad, 1, {{0.0, 0.0, 0.0}}), std::invalid_argument);
  bad = RealismParams{};
  bad.pose_noise_m = -0.1;
  std::string error;
  EXPECT_FALSE(bad.IsValid(&error));
  EXPECT_NE(error.find("pose_noise_m"), std::string::npos) << error;
  bad = RealismParams{};
  bad.tracking_dropout_mean_steps = 0.5;
  EXPECT_FALSE(bad.IsValid(&error));
  EXPECT_NE(error.find("tracking_dropout_mean_steps = 0.5"), std::string::npos) << error;
  bad = RealismParams{};
  bad.tracker_drop_s = -1.0;
  EXPECT_FALSE(bad.IsValid(&error));
  EXPECT_NE(error.find("tracker_drop_s = -1"), std::string::npos) << error;
  EXPECT_THROW(RealisticWorld(WorldParams{}, bad, 1, {{0.0, 0.0, 0.0}}), std::invalid_argument);
  RealisticWorld world(WorldParams{}, RealismParams::Lab(), 1, {{0.0, 0.0, 0.0}});
  EXPECT_THROW(world.SetCommand(1, {0.1, 0.0}), std::out_of_range);
  EXPECT_THROW(world.SetCommand(0, {NAN, 0.0}), std::invalid_argument);
  EXPECT_THROW(world.StopRobot(-1), std::out_of_range);
}

// IsValid goes through Fields(): every field has a rule, a NaN (or a step
// count past kMaxDelaySteps) fails naming it, and the lab's value passes.
TEST(RealisticWorldTest, EveryRealismFieldIsCheckedByItsRule) {
  for (const RealismParams::Field& field : RealismParams::Fields()) {
    SCOPED_TRACE(field.key);
    RealismParams bad = RealismParams::Lab();
    if (field.steps != nullptr) {
      bad.*field.steps = RealismParams::kMaxDelaySteps + 1;
    } else {
      ASSERT_NE(field.allows, nullptr);
      ASSERT_NE(field.allowed, nullptr);
      EXPECT_TRUE(field.allows(RealismParams::Lab().*field.number));
      bad.*field.number = NAN;
    }
    std::string error;
    EXPECT_FALSE(bad.IsValid(&error));
    EXPECT_EQ(error.rfind(std::string(field.key) + " = ", 0), 0u) << error;
  }
  RealismParams negative_delay;
  negative_delay.command_latency_steps = -1;
  std::string error;
  EXPECT_FALSE(negative_delay.IsValid(&error));
  EXPECT_EQ(error, "command_latency_steps = -1 is out of range; allowed: 0..300 steps");
  RealismParams flat_axle;
  flat_axle.axle_length_m = 0.0;
  EXPECT_FALSE(flat_axle.IsValid(&error));
  EXPECT_EQ(error, "axle_length_m = 0 is out of range; allowed: > 0 m, finite");
}

}  // namespace
}  // namespace dream::world
