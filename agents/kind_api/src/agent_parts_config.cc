#include "dream/kind_api/agent_parts_config.h"

#include <algorithm>
#include <stdexcept>

#include "dream/agents/framework/graph_radio.h"
#include "dream/agents/framework/noise_source.h"
#include "dream/agents/framework/number_text.h"
#include "dream/agents/framework/range_radio.h"
#include "dream/agents/framework/role_radio.h"
#include "dream/config/name_suggestion.h"

namespace dream::kind_api {
namespace {

using config::ConfigNode;

// A whole number of steps in [minimum, INT_MAX].
int ReadSteps(const ConfigNode& node, int minimum) {
  const int value = node.AsInt32();
  if (value < minimum) node.Fail("must be >= " + std::to_string(minimum) + ", got " + std::to_string(value));
  return value;
}

// One value for every robot, or a list with one per robot.
std::vector<int> ReadPerRobot(const ConfigNode& node, int num_robots, int minimum) {
  std::vector<int> values;
  if (node.IsSequence()) {
    if (node.size() != static_cast<size_t>(num_robots)) {
      node.Fail("expected one number, or a list with one per robot (" + std::to_string(num_robots) + "), got " +
                std::to_string(node.size()));
    }
    for (size_t i = 0; i < node.size(); ++i) values.push_back(ReadSteps(node[i], minimum));
  } else {
    values.assign(static_cast<size_t>(num_robots), ReadSteps(node, minimum));
  }
  return values;
}

template <typename Params>
void Validate(const ConfigNode& node, const Params& params) {
  std::string error;
  if (!params.IsValid(&error)) node.FailAtField(error);
}

Eigen::MatrixXd ReadMatrix(const ConfigNode& node) {
  if (!node.IsSequence() || node.size() == 0) node.Fail("expected a square matrix as a list of rows");
  const size_t rows = node.size();
  Eigen::MatrixXd matrix(rows, rows);
  for (size_t i = 0; i < rows; ++i) {
    const std::vector<double> row = node[i].AsDoubles();
    if (row.size() != rows) {
      node[i].Fail("row " + std::to_string(i) + " has " + std::to_string(row.size()) + " entries; the matrix must be " +
                   std::to_string(rows) + "x" + std::to_string(rows));
    }
    for (size_t j = 0; j < rows; ++j) matrix(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = row[j];
  }
  return matrix;
}

SensorConfig ReadSensor(const ConfigNode& node, int num_robots) {
  SensorConfig sensor;
  const std::string kind = node.Required("kind").AsString();
  if (node.Has("period_steps")) {
    sensor.period_steps = ReadPerRobot(node.Required("period_steps"), num_robots, 1);
  } else {
    sensor.period_steps.assign(static_cast<size_t>(num_robots), 1);
  }
  if (kind == "odometry") {
    node.RejectUnknownKeys({"kind", "period_steps", "noise_std"});
    sensor.kind = SensorConfig::Kind::kOdometry;
    sensor.odometry.noise_std = node.GetDouble("noise_std", 0.0);
    Validate(node, sensor.odometry);
  } else if (kind == "movement") {
    node.RejectUnknownKeys({"kind", "period_steps", "noise_std", "range_m", "direction_rad", "field_of_view_rad"});
    sensor.kind = SensorConfig::Kind::kMovement;
    agents::MovementSensorParams& p = sensor.movement;
    p.noise_std = node.GetDouble("noise_std", p.noise_std);
    p.range_m = node.GetDouble("range_m", p.range_m);
    p.direction_rad = node.GetDouble("direction_rad", p.direction_rad);
    p.field_of_view_rad = node.GetDouble("field_of_view_rad", p.field_of_view_rad);
    Validate(node, p);
  } else if (kind == "obstacle") {
    node.RejectUnknownKeys({"kind", "period_steps", "noise_std", "range_m"});
    sensor.kind = SensorConfig::Kind::kObstacle;
    sensor.obstacle.noise_std = node.GetDouble("noise_std", 0.0);
    sensor.obstacle.range_m = node.GetDouble("range_m", sensor.obstacle.range_m);
    Validate(node, sensor.obstacle);
  } else {
    node.Required("kind").Fail("unknown sensor kind '" + kind + "'" +
                               config::DidYouMean(kind, {"odometry", "movement", "obstacle"}) +
                               "; known kinds: odometry, movement, obstacle");
  }
  return sensor;
}

// The keys of a `radio:` entry of `kind` (none for an unknown kind): those of
// every radio with the kind's own (range_m; graph; graph and leaders) in between.
std::vector<std::string> RadioKeys(const std::string& kind) {
  std::vector<std::string> own;
  if (kind == "range") {
    own = {"range_m"};
  } else if (kind == "graph") {
    own = {"graph"};
  } else if (kind == "role") {
    own = {"graph", "leaders"};
  } else if (kind != "none") {
    return {};
  }
  std::vector<std::string> keys = {"kind", "period_steps"};
  keys.insert(keys.end(), own.begin(), own.end());
  keys.insert(keys.end(), {"loss_probability", "delay_steps"});
  return keys;
}

// A key of another radio kind (a range radio's `graph`) would be silently
// ignored: an error at `kind`, since either the kind or the key is the mistake.
void RejectKeysOfOtherKinds(const ConfigNode& node, const std::string& kind) {
  const std::vector<std::string> keys = RadioKeys(kind);
  if (keys.empty()) return;  // an unknown kind: ReadRadio names the known ones
  for (const std::string& key : node.Keys()) {
    if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
    std::string allowed;
    for (const std::string& k : keys) allowed += (allowed.empty() ? "" : ", ") + k;
    node.Required("kind").Fail("a radio of kind " + kind + " has no `" + key + "`; its keys: " + allowed);
  }
}

void ReadRadio(const ConfigNode& node, int num_robots, bool graph_must_connect, RadioConfig* radio) {
  node.RejectUnknownKeys({"kind", "period_steps", "range_m", "graph", "leaders", "loss_probability", "delay_steps"});
  const std::string kind = node.Required("kind").AsString();
  RejectKeysOfOtherKinds(node, kind);
  if (node.Has("period_steps")) radio->period_steps = ReadPerRobot(node.Required("period_steps"), num_robots, 1);
  radio->link.loss_probability = node.GetDouble("loss_probability", radio->link.loss_probability);
  if (node.Has("delay_steps")) radio->link.delay_steps = ReadSteps(node.Required("delay_steps"), 0);
  Validate(node, radio->link);
  if (kind == "none") {
    radio->kind = RadioConfig::Kind::kNone;
  } else if (kind == "range") {
    radio->kind = RadioConfig::Kind::kRange;
    radio->range_m = node.GetDouble("range_m", radio->range_m);
    if (!(radio->range_m > 0.0))
      node.Required("range_m").Fail("must be > 0, got " + agents::NumberText(radio->range_m));
  } else if (kind == "graph" || kind == "role") {
    radio->kind = kind == "graph" ? RadioConfig::Kind::kGraph : RadioConfig::Kind::kRole;
    if (node.Has("graph")) radio->graph = ReadMatrix(node.Required("graph"));
    if (radio->graph.size() == 0) node.Required("graph").Fail("a graph radio needs its adjacency matrix");
    try {
      // Consensus needs symmetric links reaching everyone; role radios carry
      // directed stress weights, which need not be symmetric in general.
      agents::CommunicationGraph(radio->graph, num_robots, graph_must_connect && kind == "graph", graph_must_connect);
    } catch (const std::invalid_argument& e) {
      node.FailAt("graph", e.what());
    }
    if (kind == "role") {
      if (node.Has("leaders")) {
        radio->leaders.clear();
        const ConfigNode leaders = node.Required("leaders");
        for (double id : leaders.AsDoubles()) {
          if (id < 0 || id >= num_robots || id != static_cast<int>(id)) {
            leaders.Fail("leader ids must be robot ids 0.." + std::to_string(num_robots - 1));
          }
          radio->leaders.push_back(static_cast<int>(id));
        }
      }
      if (radio->leaders.empty()) node.Required("leaders").Fail("a role radio needs at least one leader id");
    }
  } else {
    node.Required("kind").Fail("unknown radio kind '" + kind + "'" +
                               config::DidYouMean(kind, {"none", "range", "graph", "role"}) +
                               "; known kinds: none, range, graph, role");
  }
}

}  // namespace

SensorConfig SensorConfig::Every(Kind kind, int num_robots, int period_steps) {
  SensorConfig sensor;
  sensor.kind = kind;
  sensor.period_steps.assign(static_cast<size_t>(num_robots), period_steps);
  return sensor;
}

RadioConfig RadioConfig::Every(Kind kind, int num_robots, int period_steps) {
  RadioConfig radio;
  radio.kind = kind;
  radio.period_steps.assign(static_cast<size_t>(num_robots), period_steps);
  return radio;
}

AgentPartsConfig AgentPartsConfig::Defaults(int num_robots) {
  AgentPartsConfig parts;
  const auto n = static_cast<size_t>(num_robots);
  parts.robot_period_steps.assign(n, 1);
  parts.start_delay_steps.assign(n, 0);
  parts.sensors.push_back(SensorConfig::Every(SensorConfig::Kind::kOdometry, num_robots, 1));
  parts.radio = RadioConfig::Every(RadioConfig::Kind::kNone, num_robots, 1);
  return parts;
}

AgentPartsConfig AgentPartsConfig::ThesisHrvoParts(int num_robots) {
  AgentPartsConfig parts = Defaults(num_robots);
  SensorConfig odometry;
  odometry.kind = SensorConfig::Kind::kOdometry;
  SensorConfig movement;
  movement.kind = SensorConfig::Kind::kMovement;
  for (size_t i = 0; i < static_cast<size_t>(num_robots); ++i) {
    const int odd = static_cast<int>(i % 2);
    parts.robot_period_steps[i] = 4 + odd;
    parts.start_delay_steps[i] = 20 + static_cast<int>(i);
    odometry.period_steps.push_back(2 + odd);
    movement.period_steps.push_back(3 + odd);
  }
  parts.sensors = {odometry, movement};
  return parts;
}

AgentPartsConfig AgentPartsConfig::Read(const ConfigNode& section, int num_robots, AgentPartsConfig defaults,
                                        bool graph_must_connect) {
  AgentPartsConfig parts = std::move(defaults);
  const ConfigNode robot_node = section.Optional("robot");
  if (robot_node.IsDefined()) {
    robot_node.RejectUnknownKeys({"period_steps", "start_delay_steps", "vel_gain", "ang_gain"});
    if (robot_node.Has("period_steps"))
      parts.robot_period_steps = ReadPerRobot(robot_node.Required("period_steps"), num_robots, 1);
    if (robot_node.Has("start_delay_steps")) {
      parts.start_delay_steps = ReadPerRobot(robot_node.Required("start_delay_steps"), num_robots, 0);
    }
    parts.robot.vel_gain = robot_node.GetDouble("vel_gain", parts.robot.vel_gain);
    parts.robot.ang_gain = robot_node.GetDouble("ang_gain", parts.robot.ang_gain);
    Validate(robot_node, parts.robot);
  }
  const ConfigNode sensors_node = section.Optional("sensors");
  if (sensors_node.IsDefined()) {
    if (!sensors_node.IsSequence()) sensors_node.Fail("expected a list of sensors, each with kind:");
    parts.sensors.clear();
    for (size_t i = 0; i < sensors_node.size(); ++i) parts.sensors.push_back(ReadSensor(sensors_node[i], num_robots));
  }
  const ConfigNode radio_node = section.Optional("radio");
  if (radio_node.IsDefined()) ReadRadio(radio_node, num_robots, graph_must_connect, &parts.radio);
  return parts;
}

agents::RobotAgentSpec AgentPartsConfig::MakeSpec(std::unique_ptr<agents::Robot> control, uint64_t run_seed) const {
  const int id = control->id();
  const auto i = static_cast<size_t>(id);
  agents::RobotAgentSpec spec;
  spec.robot_period_steps = robot_period_steps.at(i);
  spec.start_delay_steps = start_delay_steps.at(i);
  for (size_t s = 0; s < sensors.size(); ++s) {
    const uint64_t seed = agents::NoiseSource::MixSeed(run_seed, i, s + 1);
    agents::SensorSlot slot;
    slot.period_steps = sensors[s].period_steps.at(i);
    switch (sensors[s].kind) {
      case SensorConfig::Kind::kOdometry:
        slot.sensor = std::make_unique<agents::OdometrySensor>(sensors[s].odometry, seed);
        break;
      case SensorConfig::Kind::kMovement:
        slot.sensor = std::make_unique<agents::MovementSensor>(sensors[s].movement, seed);
        break;
      case SensorConfig::Kind::kObstacle:
        slot.sensor = std::make_unique<agents::ObstacleSensor>(sensors[s].obstacle, seed);
        break;
    }
    spec.sensors.push_back(std::move(slot));
  }
  const int n = static_cast<int>(robot_period_steps.size());
  switch (radio.kind) {
    case RadioConfig::Kind::kNone:
      break;
    case RadioConfig::Kind::kRange:
      spec.radio = std::make_unique<agents::RangeRadio>(radio.range_m);
      break;
    case RadioConfig::Kind::kGraph:
      spec.radio = std::make_unique<agents::GraphRadio>(agents::CommunicationGraph(radio.graph, n, false, false));
      break;
    case RadioConfig::Kind::kRole: {
      const bool leader = std::find(radio.leaders.begin(), radio.leaders.end(), id) != radio.leaders.end();
      spec.radio = std::make_unique<agents::RoleRadio>(
          leader ? agents::RoleRadio::Role::kLeader : agents::RoleRadio::Role::kFollower,
          agents::CommunicationGraph(radio.graph, n, false, false));
      break;
    }
  }
  spec.radio_period_steps = radio.period_steps.at(i);
  spec.link = radio.link;
  spec.robot = std::move(control);
  return spec;
}

}  // namespace dream::kind_api
