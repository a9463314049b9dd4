#include "dream/python/python_controller_spec.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "dream/kind_api/agent_parts_config.h"
#include "dream/python/python_controller_builder.h"

namespace dream::python {
namespace {

using Json = nlohmann::ordered_json;

// A YAML value as JSON. A plain scalar becomes the number or boolean it
// spells (YAML 1.2 core schema), a quoted one stays a string; the Python side
// checks types, so nothing here guesses beyond that.
Json YamlToJson(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Sequence: {
      Json list = Json::array();
      for (const YAML::Node& item : node) list.push_back(YamlToJson(item));
      return list;
    }
    case YAML::NodeType::Map: {
      Json map = Json::object();
      for (const auto& entry : node) map[entry.first.Scalar()] = YamlToJson(entry.second);
      return map;
    }
    case YAML::NodeType::Scalar: {
      const std::string& text = node.Scalar();
      if (node.Tag() == "!") return text;  // quoted
      if (text == "true" || text == "True" || text == "TRUE") return true;
      if (text == "false" || text == "False" || text == "FALSE") return false;
      long long integer = 0;
      if (YAML::convert<long long>::decode(node, integer)) return integer;
      double number = 0.0;
      if (YAML::convert<double>::decode(node, number) && std::isfinite(number)) return number;
      return text;
    }
    default:
      return nullptr;
  }
}

Json PerRobot(const std::vector<int>& values) { return Json(values); }

Json PartsJson(const kind_api::AgentPartsConfig& parts) {
  Json robot = {{"period_steps", PerRobot(parts.robot_period_steps)},
                {"start_delay_steps", PerRobot(parts.start_delay_steps)},
                {"vel_gain", parts.robot.vel_gain},
                {"ang_gain", parts.robot.ang_gain}};
  Json sensors = Json::array();
  static const char* const kSensorKinds[] = {"odometry", "movement", "obstacle"};
  for (const kind_api::SensorConfig& sensor : parts.sensors) {
    // What every sensor has, then its own params.
    Json entry = {{"kind", kSensorKinds[static_cast<int>(sensor.kind)]},
                  {"period_steps", PerRobot(sensor.period_steps)}};
    switch (sensor.kind) {
      case kind_api::SensorConfig::Kind::kOdometry:
        entry["noise_std"] = sensor.odometry.noise_std;
        break;
      case kind_api::SensorConfig::Kind::kMovement:
        entry["range_m"] = sensor.movement.range_m;
        entry["direction_rad"] = sensor.movement.direction_rad;
        entry["field_of_view_rad"] = sensor.movement.field_of_view_rad;
        entry["noise_std"] = sensor.movement.noise_std;
        break;
      case kind_api::SensorConfig::Kind::kObstacle:
        entry["range_m"] = sensor.obstacle.range_m;
        entry["noise_std"] = sensor.obstacle.noise_std;
        break;
    }
    sensors.push_back(entry);
  }
  const kind_api::RadioConfig& radio = parts.radio;
  static const char* const kRadioKinds[] = {"none", "range", "graph", "role"};
  Json graph = Json::array();
  for (Eigen::Index i = 0; i < radio.graph.rows(); ++i) {
    Json row = Json::array();
    for (Eigen::Index j = 0; j < radio.graph.cols(); ++j) row.push_back(radio.graph(i, j));
    graph.push_back(row);
  }
  Json radio_json = {{"kind", kRadioKinds[static_cast<int>(radio.kind)]},
                     {"period_steps", PerRobot(radio.period_steps)},
                     {"range_m", radio.range_m},
                     {"graph", graph},
                     {"leaders", radio.leaders},
                     {"loss_probability", radio.link.loss_probability},
                     {"delay_steps", radio.link.delay_steps}};
  return {{"robot", robot}, {"sensors", sensors}, {"radio", radio_json}};
}

}  // namespace

std::string PythonControllerSpecJson(const config::ControllerConfig& config) {
  const config::ConfigNode& section = config.controller;
  if (section.Required("kind").AsString() != PythonControllerBuilder::kKind) {
    section.Required("kind").Fail("expected kind python for a Python controller spec");
  }
  // The parts and the builder as the factory reads them for this kind (its
  // default parts, no graph rule), so the spec holds what the factory checked.
  const kind_api::AgentPartsConfig parts = kind_api::AgentPartsConfig::Read(
      section, config.num_robots, kind_api::AgentPartsConfig::Defaults(config.num_robots), false);
  const PythonControllerBuilder builder(section, config.num_robots);
  Json params = Json::object();
  static const std::vector<std::string> kNotOwn = {"kind", "module", "class", "robot", "sensors", "radio"};
  for (const std::string& key : section.Keys()) {
    if (std::find(kNotOwn.begin(), kNotOwn.end(), key) != kNotOwn.end()) continue;
    const config::ConfigNode value = section.Optional(key);
    params[key] = {{"value", YamlToJson(value.yaml())}, {"line", value.line()}};
  }
  const Json spec = {{"format", 1},
                     {"name", config.name},
                     {"config_file", config.source},
                     {"robots", config.num_robots},
                     {"seed", config.seed},
                     {"module", builder.module_path()},
                     {"class", builder.class_name()},
                     {"section_line", section.line()},
                     {"module_line", section.Required("module").line()},
                     {"class_line", section.Required("class").line()},
                     {"params", params},
                     {"parts", PartsJson(parts)}};
  return spec.dump();
}

}  // namespace dream::python
