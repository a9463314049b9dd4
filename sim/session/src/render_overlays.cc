#include "dream/session/render_overlays.h"

#include <memory>
#include <vector>

#include "dream/agent_host/agent_parts_config.h"
#include "dream/agent_host/controller_factory.h"
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

std::vector<sim::SensorReach> SensorReachesOf(const agents::AgentPartsConfig& parts) {
  std::vector<sim::SensorReach> reaches;
  for (const agents::SensorConfig& sensor : parts.sensors) {
    if (sensor.kind == agents::SensorConfig::Kind::kMovement) {
      reaches.push_back({sensor.movement.range_m, sensor.movement.direction_rad, sensor.movement.field_of_view_rad});
    } else if (sensor.kind == agents::SensorConfig::Kind::kObstacle) {
      reaches.push_back({sensor.obstacle.range_m});
    }
  }
  return reaches;
}

sim::ArenaOverlays::RadioHearing HearingOf(const agents::AgentPartsConfig& parts, int num_robots, uint64_t seed) {
  if (parts.radio.kind == agents::RadioConfig::Kind::kNone) return {};
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
    if (world->step != poses.step || world->num_robots() != poses.num_robots) agents::TakePoses(poses, world.get());
    return (*radios)[static_cast<size_t>(receiver)]->CanHear(receiver, sender, *world);
  };
}

}  // namespace

sim::ArenaOverlays ArenaOverlaysFromConfig(const config::RunConfig& config) {
  // The factory loads the config's plugins, checks the kind and reads the parts.
  return ArenaOverlaysFromConfig(config, agents::ControllerFactory(config));
}

sim::ArenaOverlays ArenaOverlaysFromConfig(const config::RunConfig& config, const agents::ControllerFactory& factory) {
  const agents::AgentPartsConfig& parts = factory.parts();
  sim::ArenaOverlays overlays;
  for (const std::vector<Eigen::Vector2d>& points : factory.GoalsToDraw()) {
    Points goals;
    for (const Eigen::Vector2d& point : points) goals.push_back({point.x(), point.y()});
    overlays.goals_m.push_back(goals);
  }
  overlays.sensor_reaches = SensorReachesOf(parts);
  overlays.hears = HearingOf(parts, config.num_robots, config.seed);
  return overlays;
}

}  // namespace dream::session
