#include "dream/agent_host/log_metrics.h"

#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/log_reader.h"
#include "dream/obstacles_t.hpp"
#include "dream/robot_poses_t.hpp"

namespace dream::agents {

MetricsReport MetricsFromLog(const ControllerFactory& factory, const std::string& log_path,
                             std::optional<GoalJudgement>* goal) {
  std::vector<std::unique_ptr<ExperimentMetrics>> metrics = factory.MakeMetrics();
  WorldSnapshot world;
  lcm::LogReader reader(log_path);
  lcm::LogRecord record;
  while (reader.Next(&record)) {
    const int size = static_cast<int>(record.data.size());
    if (record.channel == lcm::kObstaclesChannel) {
      obstacles_t obstacles{};
      if (!lcm::Decode(record.data.data(), size, &obstacles)) continue;
      world.obstacles.clear();
      for (const rectangle_obstacle_t& o : obstacles.obstacles) {
        world.obstacles.push_back({o.id, {o.center_x, o.center_y}, {o.width, o.height}, {o.vx, o.vy}});
      }
    } else if (record.channel == lcm::kPosesChannel) {
      robot_poses_t poses{};
      if (!lcm::Decode(record.data.data(), size, &poses)) continue;
      world.step = poses.step;
      world.poses.resize(poses.x.size());
      world.velocities.resize(poses.x.size());
      for (size_t i = 0; i < poses.x.size(); ++i) {
        world.poses[i] = {poses.x[i], poses.y[i], poses.theta[i]};
        world.velocities[i] = {poses.v[i], poses.w[i]};
      }
      for (auto& m : metrics) m->Observe(world);
    }
  }
  MetricsReport report;
  for (const auto& m : metrics) m->Write(&report);
  if (goal != nullptr) {
    goal->reset();
    for (const auto& m : metrics) {
      if (!*goal) *goal = m->JudgeGoal(report);
    }
  }
  return report;
}

}  // namespace dream::agents
