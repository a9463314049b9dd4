#include "dream/view/frame_json.h"

#include <cmath>
#include <string_view>

#include "dream/robotarium/robotarium_constants.h"
#include "drawing_json.h"
#include "json_parts.h"
#include "json_writer.h"

namespace dream::view {
namespace {

constexpr int kMetres = 4;   // 0.1 mm
constexpr int kRadians = 4;  // 1e-4 rad
constexpr int kMetricDigits = 7;

void NumberArray(JsonWriter& json, std::string_view key, const std::vector<double>& values, int decimals) {
  json.Key(key).BeginArray();
  for (const double value : values) json.Number(value, decimals);
  json.EndArray();
}

}  // namespace

ViewFrame::Status ViewFrame::Status::Of(const run_status_t& message) {
  Status status;
  status.seen = true;
  status.state = message.state;
  status.boundary_errors = message.boundary_errors;
  status.collision_errors = message.collision_errors;
  status.actuator_errors = message.actuator_errors;
  status.obstacle_collisions = message.obstacle_collisions;
  status.rejected_commands = message.rejected_commands;
  status.command_conflicts = message.command_conflicts;
  status.lost_robot_ids = message.lost_robot_ids;
  status.detail = message.detail.substr(0, kMaxDetailChars);
  return status;
}

void WriteStatusJson(JsonWriter& json, std::string_view key, const ViewFrame::Status& status) {
  json.Key(key);
  if (!status.seen) {
    json.Null();
    return;
  }
  json.BeginObject();
  json.Key("state").Integer(status.state);
  json.Key("boundary").Integer(status.boundary_errors);
  json.Key("collision").Integer(status.collision_errors);
  json.Key("actuator").Integer(status.actuator_errors);
  json.Key("obstacle").Integer(status.obstacle_collisions);
  json.Key("rejected").Integer(status.rejected_commands);
  json.Key("conflicts").Integer(status.command_conflicts);
  json.Key("lost").BeginArray();
  for (const int id : status.lost_robot_ids) json.Integer(id);
  json.EndArray();
  json.Key("detail").String(status.detail);
  json.EndObject();
}

void AppendViolation(JsonWriter& json, const ViolationMark& mark) {
  json.BeginObject();
  json.Key("kind").String(ViolationKindName(mark.kind));
  json.Key("step").Integer(mark.step);
  json.Key("robot").Integer(mark.robot);
  json.Key("other").Integer(mark.other);
  json.Key("x").Number(mark.x_m, kMetres);
  json.Key("y").Number(mark.y_m, kMetres);
  if (std::isfinite(mark.worst_m)) json.Key("worst").Number(mark.worst_m, kMetres);
  json.EndObject();
}

namespace {

// As the setup's "judged" (summary.json's), less the metrics the bus does not carry.
void WriteJudgedJson(JsonWriter& json, const std::optional<ViewFrame::Judged>& judged) {
  json.Key("judged");
  if (!judged) {
    json.Null();
    return;
  }
  json.BeginObject();
  json.Key("verdict").String(judged->verdict);
  json.Key("reasons").BeginArray();
  for (const std::string& reason : judged->reasons) json.String(reason);
  json.EndArray();
  json.Key("goal").String(judged->goal);
  json.Key("exit_code").Integer(judged->exit_code);
  json.Key("metrics").BeginArray().EndArray();
  json.EndObject();
}

}  // namespace

std::string FrameJson(const ViewFrame& frame) {
  std::string out;
  out.reserve(256 + frame.x_m.size() * 60 + frame.obstacles.size() * 60);
  JsonWriter json(&out);
  json.BeginObject();
  json.Key("type").String("frame");
  // As a string: a 64-bit id does not fit a JavaScript number.
  json.Key("run").String(std::to_string(frame.run_id));
  json.Key("step").Integer(frame.step);
  json.Key("t").Number(static_cast<double>(frame.utime) / 1e6, 3);
  NumberArray(json, "x", frame.x_m, kMetres);
  NumberArray(json, "y", frame.y_m, kMetres);
  NumberArray(json, "th", frame.theta_rad, kRadians);
  NumberArray(json, "v", frame.v_mps, kMetres);
  NumberArray(json, "w", frame.w_radps, kRadians);
  if (!frame.command_v_mps.empty()) {
    NumberArray(json, "cv", frame.command_v_mps, kMetres);
    NumberArray(json, "cw", frame.command_w_radps, kRadians);
  }
  if (!frame.measured_x_m.empty()) {
    NumberArray(json, "mx", frame.measured_x_m, kMetres);
    NumberArray(json, "my", frame.measured_y_m, kMetres);
    NumberArray(json, "mth", frame.measured_theta_rad, kRadians);
  }
  json.Key("obstacles").BeginArray();
  for (const ViewFrame::Obstacle& o : frame.obstacles) {
    json.BeginArray().Integer(o.id).Number(o.center_x_m, kMetres).Number(o.center_y_m, kMetres);
    json.Number(o.width_m, kMetres).Number(o.height_m, kMetres).Number(o.vx_mps, kMetres).Number(o.vy_mps, kMetres);
    json.EndArray();
  }
  json.EndArray();
  WriteStatusJson(json, "status", frame.status);
  json.Key("radio").BeginArray();
  for (const int id : frame.radio_senders) json.Integer(id);
  json.EndArray();
  json.Key("links").BeginArray();
  for (const auto& [sender, receiver] : frame.radio_links)
    json.BeginArray().Integer(sender).Integer(receiver).EndArray();
  json.EndArray();
  json.Key("drawings").BeginArray();
  for (const ViewFrame::Drawn& drawn : frame.drawings) {
    json.BeginArray().Integer(drawn.step).Integer(drawn.robot_id).Integer(drawn.clipped);
    AppendShapes(json, drawn.shapes);
    json.EndArray();
  }
  json.EndArray();
  json.Key("violations").BeginArray();
  for (const ViolationMark& mark : frame.violations) AppendViolation(json, mark);
  json.EndArray();
  json.Key("located").Integer(frame.violations_located);
  json.Key("metrics").BeginArray();
  for (const MetricReading& m : frame.metrics) {
    json.BeginObject().Key("name").String(m.name).Key("value").Significant(m.value, kMetricDigits);
    if (m.step >= 0) json.Key("step").Integer(m.step);  // a figure of an earlier step than the frame's
    if (m.threshold)
      json.Key("threshold").Significant(*m.threshold, kMetricDigits).Key("label").String(m.threshold_label);
    json.EndObject();
  }
  json.EndArray();
  json.Key("other_world");
  if (frame.other_world) {
    const ViewFrame::OtherWorld& other = *frame.other_world;
    json.BeginObject();
    json.Key("run").String(std::to_string(other.run_id));
    json.Key("step").Integer(other.step);
    json.Key("state");
    if (other.state >= 0) {
      json.Integer(other.state);
    } else {
      json.Null();
    }
    json.Key("runs").Integer(other.runs);
    json.EndObject();
  } else {
    json.Null();
  }
  WriteJudgedJson(json, frame.judged);
  json.EndObject();
  return out;
}

void AppendSetupFields(JsonWriter& json, const ViewSetup& setup) {
  json.Key("mode").String(setup.mode == ViewSetup::Mode::kLive ? "live" : "replay");
  json.Key("source").String(setup.source);
  json.Key("run_name").String(setup.overlays.run_name);
  const world::Arena& arena = setup.world.arena;
  json.Key("arena").BeginArray().Number(arena.x_min_m, kMetres).Number(arena.x_max_m, kMetres);
  json.Number(arena.y_min_m, kMetres).Number(arena.y_max_m, kMetres).EndArray();
  json.Key("robot_diameter").Number(robotarium::RobotariumConstants::kRobotDiameterMeters, kMetres);
  json.Key("collision_diameter").Number(setup.world.collision_diameter_m, kMetres);
  json.Key("time_step").Number(setup.world.time_step_s, 6);
  json.Key("fps").Integer(setup.frame_rates.real_time);
  json.Key("goals").BeginArray();
  for (const auto& goals : setup.overlays.goals_m) {
    json.BeginArray();
    for (const auto& goal : goals) json.BeginArray().Number(goal[0], kMetres).Number(goal[1], kMetres).EndArray();
    json.EndArray();
  }
  json.EndArray();
  json.Key("sensors").BeginArray();
  for (const render::SensorReach& reach : setup.overlays.sensor_reaches) {
    json.BeginArray().Number(reach.range_m, kMetres).Number(reach.direction_rad, kRadians);
    json.Number(reach.field_of_view_rad, kRadians).EndArray();
  }
  json.EndArray();
  json.Key("hears_known").Bool(static_cast<bool>(setup.overlays.hears));
  if (setup.judged) {
    json.Key("judged").BeginObject();
    json.Key("verdict").String(setup.judged->verdict);
    json.Key("reasons").BeginArray();
    for (const std::string& reason : setup.judged->reasons) json.String(reason);
    json.EndArray();
    json.Key("goal").String(setup.judged->goal);
    json.Key("metrics").BeginArray();
    for (const auto& [name, value] : setup.judged->metrics) {
      json.BeginArray().String(name).String(value).EndArray();
    }
    json.EndArray();
    json.EndObject();
  }
}

std::string SetupJson(const ViewSetup& setup) {
  std::string out;
  JsonWriter json(&out);
  json.BeginObject();
  json.Key("type").String("setup");
  AppendSetupFields(json, setup);
  json.EndObject();
  return out;
}

}  // namespace dream::view
