#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "dream/agents/framework/mailbox.h"
#include "dream/agents/framework/movement_sensor.h"
#include "dream/agents/framework/obstacle_sensor.h"
#include "dream/agents/framework/odometry_sensor.h"
#include "dream/agents/framework/robot_agent.h"
#include "dream/agents/framework/robot_params.h"
#include "dream/config/config_node.h"

namespace dream::kind_api {

/// One `sensors:` entry of a controller section.
struct SensorConfig {
  enum class Kind { kOdometry, kMovement, kObstacle };
  Kind kind = Kind::kOdometry;
  std::vector<int> period_steps;  ///< per robot
  agents::OdometrySensorParams odometry;
  agents::MovementSensorParams movement;
  agents::ObstacleSensorParams obstacle;

  /// A sensor of `kind`, default params, that each of `num_robots` robots reads every `period_steps` steps.
  static SensorConfig Every(Kind kind, int num_robots, int period_steps);
};

/// The `radio:` entry of a controller section.
struct RadioConfig {
  enum class Kind { kNone, kRange, kGraph, kRole };
  Kind kind = Kind::kNone;
  std::vector<int> period_steps;  ///< per robot
  double range_m = 1.0;           ///< kRange
  Eigen::MatrixXd graph;          ///< kGraph, kRole: adjacency or weights
  std::vector<int> leaders;       ///< kRole: leader ids; every other robot follows
  agents::RadioLinkParams link;

  /// A radio of `kind`, default params, that each of `num_robots` robots runs every `period_steps` steps.
  static RadioConfig Every(Kind kind, int num_robots, int period_steps);
};

/// The parts every robot of an experiment is built from, read from the
/// common keys of a `controller:` section:
///
///     robot:   {period_steps: 4, start_delay_steps: 20, vel_gain: 0.8, ang_gain: 3.0}
///     sensors: [{kind: odometry, period_steps: 2, noise_std: 0.0},
///               {kind: movement, period_steps: 3, range_m: 1.0, direction_rad: 0.0,
///                field_of_view_rad: 6.2832, noise_std: 0.0},
///               {kind: obstacle, period_steps: 3, range_m: 1.0, noise_std: 0.0}]
///     radio:   {kind: range | graph | role, period_steps: 30, range_m: 1.0,
///               graph: [[...]], leaders: [0, 1, 2], loss_probability: 0.0, delay_steps: 0}
///
/// `period_steps` and `start_delay_steps` take one number or a list with one
/// per robot. Experiments supply defaults; the config overrides them.
struct AgentPartsConfig {
  agents::RobotParams robot;
  std::vector<int> robot_period_steps;
  std::vector<int> start_delay_steps;
  std::vector<SensorConfig> sensors;
  RadioConfig radio;

  /// Defaults for `num_robots`: robot period 1, no delay, odometry every step, no radio.
  static AgentPartsConfig Defaults(int num_robots);

  /// The thesis's HRVO robots (Appendix B): odometry and movement sensor,
  /// periods of 2, 3 and 4 steps for odometry, movement and control (one more
  /// on odd ids), start delay 20 + id; no radio yet.
  static AgentPartsConfig ThesisHrvoParts(int num_robots);

  /// Reads the common keys of `section` over `defaults`.
  /// @param graph_must_connect graph radios must form a connected, symmetric graph.
  /// @throws config::ConfigError naming file, line, key and value.
  static AgentPartsConfig Read(const config::ConfigNode& section, int num_robots, AgentPartsConfig defaults,
                               bool graph_must_connect);

  /// The spec of robot `control->id()` around its control law `control`,
  /// sensors and radio seeded from `run_seed`.
  agents::RobotAgentSpec MakeSpec(std::unique_ptr<agents::Robot> control, uint64_t run_seed) const;
};

}  // namespace dream::kind_api
