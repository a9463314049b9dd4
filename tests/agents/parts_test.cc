// The thesis's parts with plain values: sensors see exactly what is in range
// and field of view, radios deliver exactly to neighbours, timers fire on the
// right steps.
#include <gtest/gtest.h>

#include <cmath>

#include "dream/agents/framework/byte_reader.h"
#include "dream/agents/framework/byte_writer.h"
#include "dream/agents/framework/graph_radio.h"
#include "dream/agents/framework/mailbox.h"
#include "dream/agents/framework/movement_sensor.h"
#include "dream/agents/framework/obstacle_sensor.h"
#include "dream/agents/framework/odometry_sensor.h"
#include "dream/agents/framework/range_radio.h"
#include "dream/agents/framework/robot.h"
#include "dream/agents/framework/robot_agent.h"
#include "dream/agents/framework/role_radio.h"
#include "dream/agents/framework/timer.h"

namespace dream::agents {
namespace {

/// Remembers what its accessories told it.
class RecordingRobot final : public Robot {
 public:
  explicit RecordingRobot(int id) : Robot(id, RobotParams{}) {}
  void OnOdometry(const OdometryReading& r) override {
    odometry.push_back(r);
    Robot::OnOdometry(r);
  }
  void OnMovement(const MovementReading& r) override { movement.push_back(r); }
  void OnObstacles(const ObstacleReading& r) override { obstacle_readings.push_back(r); }
  std::optional<std::vector<uint8_t>> OnRadio(const std::vector<RadioMessage>& heard) override {
    radio.push_back(heard);
    return ByteWriter().Int32(id()).Take();
  }
  UnicycleCommand Update(int64_t step) override {
    updates.push_back(step);
    return {0.01 * static_cast<double>(step), 0.0};
  }
  std::vector<OdometryReading> odometry;
  std::vector<MovementReading> movement;
  std::vector<ObstacleReading> obstacle_readings;
  std::vector<std::vector<RadioMessage>> radio;
  std::vector<int64_t> updates;
};

/// Robot 0 at the origin facing +x; others around it.
WorldSnapshot World(std::vector<Eigen::Vector3d> poses) {
  WorldSnapshot world;
  world.step = 5;
  world.poses = std::move(poses);
  world.velocities.assign(world.poses.size(), Eigen::Vector2d::Zero());
  return world;
}

TEST(OdometrySensorTest, ReportsOwnPoseExactlyWithoutNoiseAndRepeatablyWithIt) {
  RecordingRobot robot(1);
  const WorldSnapshot world = World({{0, 0, 0}, {0.5, -0.25, 1.0}});
  OdometrySensor(OdometrySensorParams{}, 1).Sense(world, robot);
  ASSERT_EQ(robot.odometry.size(), 1u);
  EXPECT_EQ(robot.odometry[0].pose, Eigen::Vector3d(0.5, -0.25, 1.0));
  EXPECT_EQ(robot.odometry[0].step, 5);
  OdometrySensor noisy_a({0.01}, 42);
  OdometrySensor noisy_b({0.01}, 42);
  RecordingRobot a(1);
  RecordingRobot b(1);
  noisy_a.Sense(world, a);
  noisy_b.Sense(world, b);
  EXPECT_EQ(a.odometry[0].pose, b.odometry[0].pose);  // same seed, same noise
  EXPECT_NE(a.odometry[0].pose, world.poses[1]);
  EXPECT_NEAR(a.odometry[0].pose.x(), 0.5, 0.05);
}

TEST(MovementSensorTest, SeesExactlyWhatIsInRangeAndFieldOfView) {
  // Robot 0 at the origin heading +x; sensor looks ahead with a 90-degree cone, range 1 m.
  const WorldSnapshot world = World({{0, 0, 0},
                                     {0.5, 0.0, 0},    // ahead, in range: seen
                                     {0.5, 0.45, 0},   // ~42 degrees left: seen
                                     {0.5, 0.55, 0},   // ~48 degrees left: outside the cone
                                     {-0.5, 0.0, 0},   // behind: not seen
                                     {1.2, 0.0, 0},    // ahead, out of range
                                     {1.0, 0.0, 0}});  // exactly at range: seen
  MovementSensorParams params;
  params.range_m = 1.0;
  params.field_of_view_rad = M_PI / 2;
  RecordingRobot robot(0);
  MovementSensor(params, 1).Sense(world, robot);
  ASSERT_EQ(robot.movement.size(), 1u);
  const auto& seen = robot.movement[0].neighbours;
  ASSERT_EQ(seen.size(), 3u);
  EXPECT_DOUBLE_EQ(seen[0].distance_m, 0.5);
  EXPECT_DOUBLE_EQ(seen[0].bearing_rad, 0.0);  // bearing points from us to the neighbour
  EXPECT_NEAR(seen[1].RelativePosition().y(), 0.45, 1e-12);
  EXPECT_DOUBLE_EQ(seen[2].distance_m, 1.0);
}

TEST(MovementSensorTest, FieldOfViewTurnsWithTheRobotAndItsDirection) {
  // Heading +y, sensor pointing backwards (direction pi): sees what is at -y.
  const WorldSnapshot world = World({{0, 0, M_PI / 2}, {0.0, -0.5, 0}, {0.0, 0.5, 0}});
  MovementSensorParams params;
  params.direction_rad = M_PI;
  params.field_of_view_rad = 0.5;
  RecordingRobot robot(0);
  MovementSensor(params, 1).Sense(world, robot);
  ASSERT_EQ(robot.movement[0].neighbours.size(), 1u);
  EXPECT_NEAR(robot.movement[0].neighbours[0].bearing_rad, -M_PI / 2, 1e-12);
}

TEST(MovementSensorTest, NeighbourVelocityIsThatOfThePointAhead) {
  WorldSnapshot world = World({{0, 0, 0}, {0.5, 0, M_PI / 2}});
  world.velocities[1] = {0.1, 2.0};  // heading +y at 0.1 m/s, turning at 2 rad/s
  RecordingRobot robot(0);
  MovementSensor(MovementSensorParams{}, 1).Sense(world, robot);
  const Eigen::Vector2d v = robot.movement[0].neighbours[0].velocity_mps;
  EXPECT_NEAR(v.x(), -0.05 * 2.0, 1e-12);  // the point 5 cm ahead swings left
  EXPECT_NEAR(v.y(), 0.1, 1e-12);
}

TEST(ObstacleSensorTest, ReportsClosestPointsOfObstaclesInRange) {
  WorldSnapshot world = World({{0, 0, 0}});
  world.obstacles = {{0, {1.0, 0.0}, {0.4, 0.4}, {0, 0}},     // closest point (0.8, 0): in range
                     {1, {0.0, 2.0}, {1.0, 0.2}, {0, 0}},     // closest (0, 1.9): out of range
                     {2, {-0.5, -0.5}, {0.2, 0.2}, {0, 0}}};  // closest corner (-0.4, -0.4)
  RecordingRobot robot(0);
  ObstacleSensor({1.0, 0.0}, 1).Sense(world, robot);
  const auto& points = robot.obstacle_readings[0].closest_points_m;
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0], Eigen::Vector2d(0.8, 0.0));
  EXPECT_EQ(points[1], Eigen::Vector2d(-0.4, -0.4));
}

TEST(SensorParamsTest, InvalidParamsAreRefusedWithTheFieldName) {
  EXPECT_THROW(OdometrySensor({-0.1}, 1), std::invalid_argument);
  MovementSensorParams movement;
  movement.field_of_view_rad = 7.0;
  std::string error;
  EXPECT_FALSE(movement.IsValid(&error));
  EXPECT_NE(error.find("field_of_view_rad"), std::string::npos);
  movement.field_of_view_rad = 6.2832;  // 2 pi as written in a config: a full circle
  EXPECT_TRUE(movement.IsValid(&error)) << error;
  movement.field_of_view_rad = 6.2833;
  EXPECT_FALSE(movement.IsValid(&error));
  EXPECT_THROW(ObstacleSensor({0.0, 0.0}, 1), std::invalid_argument);
}

TEST(RadioTest, RangeRadioHearsExactlyTheRobotsInRange) {
  const WorldSnapshot world = World({{0, 0, 0}, {0.9, 0, 0}, {1.1, 0, 0}, {0, -1.0, 0}});
  const RangeRadio radio(1.0);
  EXPECT_TRUE(radio.CanHear(0, 1, world));
  EXPECT_FALSE(radio.CanHear(0, 2, world));
  EXPECT_TRUE(radio.CanHear(0, 3, world));   // exactly at range
  EXPECT_FALSE(radio.CanHear(0, 0, world));  // not itself
  EXPECT_FALSE(radio.CanHear(0, 9, world));  // unknown sender
  EXPECT_THROW(RangeRadio(0.0), std::invalid_argument);
}

TEST(RadioTest, GraphRadioHearsExactlyItsNeighbours) {
  Eigen::MatrixXd adjacency(3, 3);
  adjacency << 0, 1, 0, 1, 0, 1, 0, 1, 0;
  const GraphRadio radio(CommunicationGraph(adjacency, 3, true, true));
  const WorldSnapshot world = World({{0, 0, 0}, {5, 0, 0}, {0.1, 0, 0}});
  EXPECT_TRUE(radio.CanHear(0, 1, world));   // far away but linked
  EXPECT_FALSE(radio.CanHear(0, 2, world));  // close but not linked
  EXPECT_TRUE(radio.CanHear(2, 1, world));
}

TEST(RadioTest, RoleRadioLeadersOnlyPublish) {
  Eigen::MatrixXd weights(3, 3);
  weights << 0, 0.5, 0.5, 0.5, 0, 0, 0.5, 0, 0;
  const RoleRadio leader(RoleRadio::Role::kLeader, CommunicationGraph(weights, 3, false, false));
  const RoleRadio follower(RoleRadio::Role::kFollower, CommunicationGraph(weights, 3, false, false));
  const WorldSnapshot world = World({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
  EXPECT_FALSE(leader.receives());
  EXPECT_TRUE(leader.publishes());
  EXPECT_FALSE(leader.CanHear(1, 0, world));
  EXPECT_TRUE(follower.CanHear(1, 0, world));
  EXPECT_FALSE(follower.CanHear(1, 2, world));
}

TEST(CommunicationGraphTest, BadMatricesAreClearErrors) {
  auto error_of = [](Eigen::MatrixXd m, int n, bool symmetric, bool connected) {
    try {
      CommunicationGraph(std::move(m), n, symmetric, connected);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error_of(Eigen::MatrixXd::Zero(2, 3), 2, false, false).find("must be 2x2"), std::string::npos);
  Eigen::MatrixXd asymmetric(2, 2);
  asymmetric << 0, 1, 0, 0;
  EXPECT_NE(error_of(asymmetric, 2, true, false).find("must be symmetric"), std::string::npos);
  Eigen::MatrixXd split(3, 3);
  split << 0, 1, 0, 1, 0, 0, 0, 0, 0;
  EXPECT_NE(error_of(split, 3, true, true).find("robot 2 cannot be reached"), std::string::npos);
  Eigen::MatrixXd self_loop = Eigen::MatrixXd::Zero(2, 2);
  self_loop(1, 1) = 1;
  EXPECT_NE(error_of(self_loop, 2, false, false).find("diagonal"), std::string::npos);
}

TEST(MailboxTest, KeepsTheLatestAudibleMessagePerSenderWithDelay) {
  RadioLinkParams link;
  link.delay_steps = 2;
  Mailbox mailbox(link, 1);
  const RangeRadio radio(10.0);
  for (int64_t step = 1; step <= 6; ++step) {
    mailbox.Post({1, step, ByteWriter().Int32(static_cast<int32_t>(step)).Take()});
  }
  WorldSnapshot world = World({{0, 0, 0}, {1, 0, 0}});
  world.step = 6;  // sent at step k, heard from k + 1 + 2: newest audible was sent at step 3
  auto heard = mailbox.Heard(radio, 0, world);
  ASSERT_EQ(heard.size(), 1u);
  EXPECT_EQ(heard[0].sent_step, 3);
  world.step = 3;  // nothing sent at step 0
  EXPECT_TRUE(mailbox.Heard(radio, 0, world).empty());
}

TEST(MailboxTest, LossIsSeededAndIndependentOfArrivalOrder) {
  RadioLinkParams link;
  link.loss_probability = 0.5;
  Mailbox forward(link, 9);
  Mailbox backward(link, 9);
  for (int64_t step = 0; step < 200; ++step) forward.Post({1, step, {}});
  for (int64_t step = 199; step >= 0; --step) backward.Post({1, step, {}});
  EXPECT_EQ(forward.lost_messages(), backward.lost_messages());
  EXPECT_GT(forward.lost_messages(), 60);
  EXPECT_LT(forward.lost_messages(), 140);
  EXPECT_THROW(Mailbox({1.0, 0}, 1), std::invalid_argument);
  EXPECT_THROW(Mailbox({0.0, -1}, 1), std::invalid_argument);
}

TEST(TimerTest, FiresAfterTheStartDelayEveryPeriod) {
  // Thesis semantics: nothing while step <= delay; then a component fires when
  // step - last_fire >= period, counting the first last_fire as step 0.
  Timer timer(3, {1, 4});
  std::vector<int64_t> every_step;
  std::vector<int64_t> every_fourth;
  for (int64_t step = 0; step <= 14; ++step) {
    const std::vector<bool>& due = timer.Tick(step);
    if (due[0]) every_step.push_back(step);
    if (due[1]) every_fourth.push_back(step);
  }
  EXPECT_EQ(every_step, (std::vector<int64_t>{4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14}));
  EXPECT_EQ(every_fourth, (std::vector<int64_t>{4, 8, 12}));
  EXPECT_THROW(Timer(0, {0}), std::invalid_argument);
  EXPECT_THROW(Timer(-1, {1}), std::invalid_argument);
}

TEST(RobotAgentTest, RunsPartsInOrderOnTheirStepsAndRepeatsTheLastCommand) {
  RobotAgentSpec spec;
  auto robot = std::make_unique<RecordingRobot>(0);
  RecordingRobot* seen = robot.get();
  spec.robot = std::move(robot);
  spec.sensors.push_back({std::make_unique<OdometrySensor>(OdometrySensorParams{}, 1), 2});
  spec.radio = std::make_unique<RangeRadio>(1.0);
  spec.radio_period_steps = 3;
  spec.robot_period_steps = 2;
  spec.start_delay_steps = 1;
  RobotAgent agent(std::move(spec), 1);
  std::vector<double> commands;
  int broadcasts = 0;
  for (int64_t step = 0; step <= 7; ++step) {
    WorldSnapshot world = World({{0.1 * static_cast<double>(step), 0, 0}, {0.5, 0, 0}});
    world.step = step;
    if (step == 4) agent.Receive({1, 3, ByteWriter().Int32(1).Take()});
    const RobotAgent::Output out = agent.Step(world);
    commands.push_back(out.command.v_mps);
    broadcasts += out.broadcast ? 1 : 0;
  }
  EXPECT_EQ(seen->updates, (std::vector<int64_t>{2, 4, 6}));
  EXPECT_EQ(seen->odometry.size(), 3u);  // steps 2, 4, 6: sensing before Update
  EXPECT_DOUBLE_EQ(seen->odometry[0].pose.x(), 0.2);
  EXPECT_EQ(commands, (std::vector<double>{0, 0, 0.02, 0.02, 0.04, 0.04, 0.06, 0.06}));
  ASSERT_EQ(seen->radio.size(), 2u);  // steps 3 and 6
  EXPECT_TRUE(seen->radio[0].empty());
  ASSERT_EQ(seen->radio[1].size(), 1u);  // robot 1's message of step 3, within range
  EXPECT_EQ(broadcasts, 2);
}

TEST(ByteReaderTest, MalformedPayloadsNeverReadPastTheEnd) {
  const std::vector<uint8_t> bytes = ByteWriter().Int32(7).Double(0.5).Take();
  ByteReader good(bytes);
  EXPECT_EQ(good.Int32(), 7);
  EXPECT_EQ(good.Double(), 0.5);
  EXPECT_TRUE(good.done());
  const std::vector<uint8_t> short_bytes(bytes.begin(), bytes.begin() + 6);
  ByteReader truncated(short_bytes);
  truncated.Int32();
  truncated.Double();
  EXPECT_FALSE(truncated.ok());
  const std::vector<uint8_t> nan_bytes = ByteWriter().Double(std::nan("")).Take();
  ByteReader nan_reader(nan_bytes);
  nan_reader.Double();
  EXPECT_FALSE(nan_reader.ok());
}

TEST(ByteReaderTest, Vector2IsXThenYAndFailsOnAHalfVector) {
  const std::vector<uint8_t> bytes = ByteWriter().Vector2({1.5, -2.0}).Take();
  EXPECT_EQ(bytes, ByteWriter().Double(1.5).Double(-2.0).Take());
  ByteReader good(bytes);
  EXPECT_EQ(good.Vector2(), Eigen::Vector2d(1.5, -2.0));
  EXPECT_TRUE(good.done());
  const std::vector<uint8_t> half = ByteWriter().Double(1.5).Take();
  ByteReader short_reader(half);
  short_reader.Vector2();
  EXPECT_FALSE(short_reader.ok());
}

}  // namespace
}  // namespace dream::agents
