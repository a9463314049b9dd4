#include <gtest/gtest.h>

#include <cmath>

#include "dream/agents/framework/byte_writer.h"
#include "dream/agent_host/controller_factory.h"
#include "dream/line_deployment/line_consensus.h"
#include "dream/line_deployment/line_deployment_builder.h"
#include "dream/line_deployment/line_deployment_robot.h"
#include "dream/line_deployment/line_formation_metrics.h"
#include "dream/agents/framework/position_message.h"
#include "dream/config/config_error.h"

namespace dream::agents {
namespace {

TEST(LineConsensusTest, Eq37OnAHandComputedExample) {
  // Robot 2 hears robots 0, 1 and 3; d = 0.4.
  //   x: (0.1 + (0-2) 0.4) = -0.7,  (0.5 + (1-2) 0.4) = 0.1,  (-0.3 + (3-2) 0.4) = 0.1  -> mean -0.5/3
  //   y: (0.2 - 0.1 + 0.4) / 3 = 0.5/3
  const std::optional<Eigen::Vector2d> target =
      line_deployment::LineConsensusTarget(2, {{0, {0.1, 0.2}}, {1, {0.5, -0.1}}, {3, {-0.3, 0.4}}}, 0.4);
  ASSERT_TRUE(target.has_value());
  EXPECT_NEAR(target->x(), -0.5 / 3.0, 1e-15);
  EXPECT_NEAR(target->y(), 0.5 / 3.0, 1e-15);
  // One neighbour: stand d from it on its line; eq. 3.7's sign puts the
  // higher id on the left.
  const std::optional<Eigen::Vector2d> single = line_deployment::LineConsensusTarget(0, {{1, {0.2, -0.3}}}, 0.4);
  ASSERT_TRUE(single.has_value());
  EXPECT_NEAR(single->x(), 0.6, 1e-15);
  EXPECT_NEAR(single->y(), -0.3, 1e-15);
  EXPECT_FALSE(line_deployment::LineConsensusTarget(0, {}, 0.4).has_value());
}

TEST(LineConsensusTest, ALineOrderedByDescendingIdIsAFixedPoint) {
  // x_i = 0.5 - 0.4 i, y = 0.1: every robot's target is where it stands.
  const Eigen::MatrixXd graph = line_deployment::LineDeploymentBuilder::ThesisAdjacency();
  for (int i = 0; i < 6; ++i) {
    std::vector<line_deployment::NeighbourPosition> neighbours;
    for (int j = 0; j < 6; ++j) {
      if (graph(i, j) != 0.0) neighbours.push_back({j, {0.5 - 0.4 * j, 0.1}});
    }
    const std::optional<Eigen::Vector2d> target = line_deployment::LineConsensusTarget(i, neighbours, 0.4);
    ASSERT_TRUE(target.has_value());
    EXPECT_NEAR(target->x(), 0.5 - 0.4 * i, 1e-12) << "robot " << i;
    EXPECT_NEAR(target->y(), 0.1, 1e-12) << "robot " << i;
  }
}

TEST(LineDeploymentRobotTest, KeepsGoodNeighbourPositionsAndDropsMalformedPayloads) {
  line_deployment::LineDeploymentRobot robot(2, RobotParams{}, HrvoRobotParams{},
                                             line_deployment::LineDeploymentParams{});
  // Before odometry it knows no position to advertise.
  EXPECT_FALSE(robot.OnRadio({}).has_value());
  robot.OnOdometry({0, Eigen::Vector3d(0.3, -0.2, 0.0)});
  std::vector<uint8_t> truncated = PositionMessage{3, {0.0, 0.0}}.Encode();
  truncated.pop_back();
  const std::vector<uint8_t> not_finite = ByteWriter().Int32(3).Double(NAN).Double(0.0).Take();
  const std::optional<std::vector<uint8_t>> sent =
      robot.OnRadio({{0, 5, PositionMessage{0, {0.1, 0.2}}.Encode()},
                     {1, 5, PositionMessage{4, {9.0, 9.0}}.Encode()},  // claims another robot's id
                     {3, 5, truncated},
                     {4, 5, not_finite}});
  EXPECT_EQ(robot.bad_radio_messages(), 3);
  ASSERT_EQ(robot.neighbour_positions().size(), 1u);
  EXPECT_EQ(robot.neighbour_positions().at(0), Eigen::Vector2d(0.1, 0.2));
  ASSERT_TRUE(sent.has_value());
  const std::optional<PositionMessage> own = PositionMessage::Decode(*sent, 2);
  ASSERT_TRUE(own.has_value());
  EXPECT_EQ(own->id, 2);
  EXPECT_EQ(own->position_m, Eigen::Vector2d(0.3, -0.2));
  // A later bad message from robot 0 keeps its last good position.
  robot.OnRadio({{0, 6, {1, 2, 3}}});
  EXPECT_EQ(robot.neighbour_positions().at(0), Eigen::Vector2d(0.1, 0.2));
  // Target: 0.1 + (0 - 2) 0.4 = -0.7, y 0.2.
  ASSERT_TRUE(robot.Target().has_value());
  EXPECT_NEAR(robot.Target()->x(), -0.7, 1e-15);
  EXPECT_NEAR(robot.Target()->y(), 0.2, 1e-15);
}

TEST(LineDeploymentRobotTest, TargetsAreClampedInsideTheArenaAndSettledRobotsReportDone) {
  line_deployment::LineDeploymentParams params;
  params.settle_updates = 2;
  line_deployment::LineDeploymentRobot robot(0, RobotParams{}, HrvoRobotParams{}, params);
  robot.OnOdometry({0, Eigen::Vector3d(1.0, 0.0, 0.0)});
  // Robot 1 at x = 1.4 puts robot 0's eq. 3.7 target at 1.8, past the wall.
  robot.OnRadio({{1, 0, PositionMessage{1, {1.4, 0.95}}.Encode()}});
  ASSERT_TRUE(robot.Target().has_value());
  EXPECT_NEAR(robot.Target()->x(), 1.6 - 0.15, 1e-15);
  EXPECT_NEAR(robot.Target()->y(), 1.0 - 0.15, 1e-15);
  const UnicycleCommand go = robot.Update(1);
  EXPECT_GT(go.v_mps, 0.0);
  EXPECT_FALSE(robot.done());
  robot.OnOdometry({0, Eigen::Vector3d(1.4495, 0.8495, 0.0)});
  robot.Update(2);
  EXPECT_FALSE(robot.done());
  robot.Update(3);
  EXPECT_TRUE(robot.done());
  robot.OnOdometry({0, Eigen::Vector3d(1.3, 0.8495, 0.0)});  // pushed away: no longer settled
  robot.Update(4);
  EXPECT_FALSE(robot.done());
}

TEST(LineDeploymentRobotTest, AStillRobotDodgesOnlyNeighboursWithinHoldAvoidRange) {
  line_deployment::LineDeploymentRobot robot(0, RobotParams{}, HrvoRobotParams{},
                                             line_deployment::LineDeploymentParams{});
  robot.OnOdometry({0, Eigen::Vector3d(0.0, 0.0, 0.0)});
  // Robot 1 at (-0.4, 0): robot 0's target is exactly where it stands.
  robot.OnRadio({{1, 0, PositionMessage{1, {-0.4, 0.0}}.Encode()}});
  UnicycleCommand command = robot.Update(1);
  EXPECT_EQ(command.v_mps, 0.0);
  EXPECT_EQ(command.w_radps, 0.0);
  // A neighbour 0.4 m west whose point ahead moves at us (it is turning on
  // the spot): a still robot ignores it...
  NeighbourDetection far;
  far.distance_m = 0.4;
  far.bearing_rad = M_PI;
  far.velocity_mps = {0.18, 0.0};
  robot.OnMovement({2, {far}});
  command = robot.Update(2);
  EXPECT_EQ(command.v_mps, 0.0);
  EXPECT_EQ(command.w_radps, 0.0);
  // ...but one within 0.3 m makes it step aside.
  NeighbourDetection near = far;
  near.distance_m = 0.25;
  robot.OnMovement({3, {near}});
  command = robot.Update(3);
  EXPECT_NE(std::abs(command.v_mps) + std::abs(command.w_radps), 0.0);
}

TEST(LineDeploymentParamsTest, InvalidParamsNameTheField) {
  std::string error;
  EXPECT_TRUE(line_deployment::LineDeploymentParams{}.IsValid(&error));
  line_deployment::LineDeploymentParams p;
  p.spacing_m = 0.0;
  EXPECT_FALSE(p.IsValid(&error));
  EXPECT_NE(error.find("spacing_m"), std::string::npos);
  p = {};
  p.settle_updates = 0;
  EXPECT_FALSE(p.IsValid(&error));
  EXPECT_NE(error.find("settle_updates"), std::string::npos);
  p = {};
  p.resume_m = 0.001;  // below tolerance_m
  EXPECT_FALSE(p.IsValid(&error));
  EXPECT_NE(error.find("resume_m"), std::string::npos);
  p = {};
  p.hold_avoid_range_m = -1.0;
  EXPECT_FALSE(p.IsValid(&error));
  EXPECT_NE(error.find("hold_avoid_range_m"), std::string::npos);
  p = {};
  p.arena_margin_m = 1.0;  // leaves no room in y
  EXPECT_FALSE(p.IsValid(&error));
  EXPECT_NE(error.find("arena_margin_m"), std::string::npos);
  EXPECT_THROW(line_deployment::LineDeploymentRobot(0, RobotParams{}, HrvoRobotParams{}, p), std::invalid_argument);
}

WorldSnapshot At(int64_t step, std::vector<Eigen::Vector3d> poses) {
  WorldSnapshot world;
  world.step = step;
  world.poses = std::move(poses);
  return world;
}

TEST(LineFormationMetricsTest, StraightnessSpacingAndConvergenceOnPlainPoses) {
  // ids descend along x by 0.4 (step -0.4), as eq. 3.7 arranges them.
  const WorldSnapshot bent = At(0, {{0.4, 0.0, 0}, {0.0, 0.03, 0}, {-0.45, 0.0, 0}});
  EXPECT_NEAR(line_deployment::LineFormationMetrics::StraightnessError(bent), 0.02, 1e-15);  // mean y 0.01
  EXPECT_NEAR(line_deployment::LineFormationMetrics::SpacingError(bent, -0.4), 0.05, 1e-15);
  line_deployment::LineFormationMetrics metrics(-0.4, 0.02, 10);
  metrics.Observe(bent);
  metrics.Observe(At(5, {{0.4, 0.0, 0}, {0.0, 0.01, 0}, {-0.41, 0.0, 0}}));   // within 2 cm
  metrics.Observe(At(10, {{0.4, 0.0, 0}, {0.0, 0.04, 0}, {-0.41, 0.0, 0}}));  // out again
  metrics.Observe(At(15, {{0.4, 0.0, 0}, {0.0, 0.0, 0}, {-0.4, 0.0, 0}}));
  metrics.Observe(At(17, {{0.4, 0.0, 0}, {0.0, 0.0, 0}, {-0.4, 0.0, 0}}));
  MetricsReport report;
  metrics.Write(&report);
  EXPECT_EQ(report.values["converged_step"], 15.0);
  EXPECT_EQ(report.values["final_line_straightness_error_m"], 0.0);
  EXPECT_NEAR(report.values["final_spacing_error_m"], 0.0, 1e-15);
  // Series every 10 steps, plus the last step.
  const auto& series = report.series["line_straightness_error_m"];
  ASSERT_EQ(series.size(), 3u);
  EXPECT_EQ(series[0].first, 0);
  EXPECT_EQ(series[1].first, 10);
  EXPECT_NEAR(series[1].second, 0.04 * 2.0 / 3.0, 1e-15);
  EXPECT_EQ(series[2].first, 17);
  EXPECT_EQ(report.series["spacing_error_m"].size(), 3u);
  // The convergence threshold is the line the view's plots draw on each error.
  for (const char* name : {"final_line_straightness_error_m", "spacing_error_m"}) {
    ASSERT_TRUE(report.thresholds.count(name)) << name;
    EXPECT_EQ(report.thresholds.at(name).value, 0.02) << name;
    EXPECT_EQ(report.thresholds.at(name).label, "converged: within 0.02 m") << name;
  }
}

std::string FactoryError(const std::string& yaml, int robots) {
  try {
    agent_host::ControllerFactory(config::ConfigNode::LoadString(yaml, "line.yaml").Required("controller"), robots, 1);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(LineDeploymentConfigTest, AdjacencyMustBeSquareSymmetricAndConnectedAndErrorsNameTheKey) {
  const std::string head = "controller:\n  kind: line_deployment\n  radio:\n    kind: graph\n    graph:\n";
  const std::string thesis =
      "      - [0, 1, 1, 0, 0, 0]\n      - [1, 0, 1, 0, 1, 0]\n      - [1, 1, 0, 1, 0, 0]\n"
      "      - [0, 0, 1, 0, 1, 1]\n      - [0, 1, 0, 1, 0, 1]\n      - [0, 0, 0, 1, 1, 0]\n";
  EXPECT_EQ(FactoryError(head + thesis, 6), "");
  // No radio section: the thesis's matrix is the default for six robots.
  EXPECT_EQ(FactoryError("controller: {kind: line_deployment}\n", 6), "");

  // (0, 3) set but (3, 0) not.
  const std::string asymmetric =
      "      - [0, 1, 1, 1, 0, 0]\n      - [1, 0, 1, 0, 1, 0]\n      - [1, 1, 0, 1, 0, 0]\n"
      "      - [0, 0, 1, 0, 1, 1]\n      - [0, 1, 0, 1, 0, 1]\n      - [0, 0, 0, 1, 1, 0]\n";
  std::string error = FactoryError(head + asymmetric, 6);
  EXPECT_NE(error.find("line.yaml:"), std::string::npos) << error;
  EXPECT_NE(error.find("graph"), std::string::npos) << error;
  EXPECT_NE(error.find("must be symmetric"), std::string::npos) << error;
  EXPECT_NE(error.find("(0, 3)"), std::string::npos) << error;

  // {0, 1, 2} and {3, 4, 5} never talk.
  const std::string split =
      "      - [0, 1, 1, 0, 0, 0]\n      - [1, 0, 1, 0, 0, 0]\n      - [1, 1, 0, 0, 0, 0]\n"
      "      - [0, 0, 0, 0, 1, 1]\n      - [0, 0, 0, 1, 0, 1]\n      - [0, 0, 0, 1, 1, 0]\n";
  error = FactoryError(head + split, 6);
  EXPECT_NE(error.find("graph"), std::string::npos) << error;
  EXPECT_NE(error.find("not connected"), std::string::npos) << error;
  EXPECT_NE(error.find("robot 3"), std::string::npos) << error;

  // A 6x6 matrix for 5 robots, and a ragged one.
  error = FactoryError(head + thesis, 5);
  EXPECT_NE(error.find("graph"), std::string::npos) << error;
  EXPECT_NE(error.find("must be 5x5"), std::string::npos) << error;
  error = FactoryError(head + "      - [0, 1]\n      - [1, 0, 0]\n", 2);
  EXPECT_NE(error.find("graph[1]"), std::string::npos) << error;
  EXPECT_NE(error.find("the matrix must be 2x2"), std::string::npos) << error;

  // Own keys are checked too.
  error = FactoryError("controller:\n  kind: line_deployment\n  gain: 1\n  spacing_m: -0.4\n", 6);
  EXPECT_EQ(error, "line.yaml:4: controller.spacing_m: must be > 0, got -0.4");
  error = FactoryError("controller: {kind: line_deployment, spacing: 0.4}\n", 6);
  EXPECT_NE(error.find("unknown key for kind line_deployment"), std::string::npos) << error;
  error = FactoryError("controller: {kind: line_deployment, hrvo: {variant: magic}}\n", 6);
  EXPECT_NE(error.find("unknown HRVO variant 'magic'"), std::string::npos) << error;
}

}  // namespace
}  // namespace dream::agents
