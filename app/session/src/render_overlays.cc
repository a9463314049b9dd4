#include "dream/session/render_overlays.h"

#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "dream/kind_api/agent_parts_config.h"
#include "dream/agent_host/controller_factory.h"
#include "dream/agent_host/controller_registry.h"
#include "dream/files/file_text.h"
#include "dream/node/run_summary.h"
#include "dream/agent_host/snapshot_from_messages.h"
#include "dream/agents/framework/world_snapshot.h"

namespace dream::session {
namespace {

using Points = std::vector<std::array<double, 2>>;

// A robot with no control law: only there so the parts' own MakeSpec builds
// its radio, exactly as in a run.
class RadioHolder final : public agents::Robot {
 public:
  using agents::Robot::Robot;
  agents::UnicycleCommand Update(int64_t) override { return {}; }
};

std::vector<render::SensorReach> SensorReachesOf(const kind_api::AgentPartsConfig& parts) {
  std::vector<render::SensorReach> reaches;
  for (const kind_api::SensorConfig& sensor : parts.sensors) {
    if (sensor.kind == kind_api::SensorConfig::Kind::kMovement) {
      reaches.push_back({sensor.movement.range_m, sensor.movement.direction_rad, sensor.movement.field_of_view_rad});
    } else if (sensor.kind == kind_api::SensorConfig::Kind::kObstacle) {
      reaches.push_back({sensor.obstacle.range_m});
    }
  }
  return reaches;
}

render::ArenaOverlays::RadioHearing HearingOf(const kind_api::AgentPartsConfig& parts, int num_robots, uint64_t seed) {
  if (parts.radio.kind == kind_api::RadioConfig::Kind::kNone) return {};
  auto radios = std::make_shared<std::vector<std::unique_ptr<agents::Radio>>>();
  for (int id = 0; id < num_robots; ++id) {
    radios->push_back(parts.MakeSpec(std::make_unique<RadioHolder>(id, parts.robot), seed).radio);
  }
  // Radios judge a WorldSnapshot; build it once per step, not once per pair.
  auto world = std::make_shared<agents::WorldSnapshot>();
  world->step = -1;
  return [radios, world](int receiver, int sender, const robot_poses_t& poses) {
    if (receiver < 0 || receiver >= static_cast<int>(radios->size()) || !(*radios)[static_cast<size_t>(receiver)]) {
      return false;
    }
    if (world->step != poses.step || world->num_robots() != poses.num_robots) agent_host::TakePoses(poses, world.get());
    return (*radios)[static_cast<size_t>(receiver)]->CanHear(receiver, sender, *world);
  };
}

}  // namespace

render::ArenaOverlays ArenaOverlaysFromConfig(const run_config::RunConfig& config) {
  // The factory loads the config's plugins, checks the kind and reads the parts.
  return ArenaOverlaysFromConfig(config, agent_host::ControllerFactory(config));
}

render::ArenaOverlays ArenaOverlaysFromConfig(const run_config::RunConfig& config,
                                              const agent_host::ControllerFactory& factory) {
  const kind_api::AgentPartsConfig& parts = factory.parts();
  render::ArenaOverlays overlays;
  for (const std::vector<Eigen::Vector2d>& points : factory.GoalsToDraw()) {
    Points goals;
    for (const Eigen::Vector2d& point : points) goals.push_back({point.x(), point.y()});
    overlays.goals_m.push_back(goals);
  }
  overlays.sensor_reaches = SensorReachesOf(parts);
  overlays.hears = HearingOf(parts, config.num_robots, config.seed);
  return overlays;
}

void AddDeclaredGoals(const nlohmann::json& metrics, render::ArenaOverlays* overlays) {
  if (!overlays->goals_m.empty() || !metrics.is_object() || !metrics.contains("goal_points")) return;
  const nlohmann::json& robots = metrics["goal_points"];
  if (!robots.is_array()) return;
  for (const nlohmann::json& points : robots) {
    if (overlays->goals_m.size() >= kMaxGoalRobots) break;
    Points goals;
    if (points.is_array()) {
      for (const nlohmann::json& point : points) {
        if (goals.size() >= kMaxGoalPointsPerRobot) break;
        if (point.is_array() && point.size() == 2 && point[0].is_number() && point[1].is_number()) {
          goals.push_back({point[0].get<double>(), point[1].get<double>()});
        }
      }
    }
    overlays->goals_m.push_back(goals);
  }
}

bool AddDeclaredGoalsOfRun(const std::string& summary_path, render::ArenaOverlays* overlays) {
  node::RunSummary summary;
  try {
    summary = node::RunSummary::Read(summary_path);
  } catch (const std::exception&) {
    return false;  // goals are a nicety: a missing, odd or huge summary.json goes without
  }
  if (!summary.metrics.is_object()) return false;
  const size_t before = overlays->goals_m.size();
  AddDeclaredGoals(summary.metrics, overlays);
  return overlays->goals_m.size() > before;
}

void AddKindGoals(const run_config::RunConfig& config, const std::string& runtime_dir,
                  render::ArenaOverlays* overlays) {
  if (!overlays->goals_m.empty() || runtime_dir.empty()) return;
  const std::shared_ptr<const kind_api::ControllerKind> kind = agent_host::ControllerRegistry::KindOf(config);
  if (!kind || !kind->goals_before_run) return;
  for (const std::vector<Eigen::Vector2d>& robot : kind->goals_before_run(config, runtime_dir)) {
    if (overlays->goals_m.size() >= kMaxGoalRobots) break;
    Points goals;
    for (const Eigen::Vector2d& point : robot) {
      if (goals.size() >= kMaxGoalPointsPerRobot) break;
      goals.push_back({point.x(), point.y()});
    }
    overlays->goals_m.push_back(goals);
  }
}

}  // namespace dream::session
