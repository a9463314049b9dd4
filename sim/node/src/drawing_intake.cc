#include "dream/node/drawing_intake.h"

#include <functional>
#include <optional>
#include <string_view>

#include "dream/drawing_t.hpp"
#include "dream/lcm/channels.h"
#include "dream/lcm/drawing_shapes.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/wire_layout_of.h"
#include "dream/lcm/run_id.h"

namespace dream::node {

DrawingIntake::DrawingIntake(const world::World& world, int64_t run_id, lcm::BadMessageLog& bad_messages)
    : world_(world), run_id_(run_id), bad_messages_(bad_messages), robots_(static_cast<size_t>(world.num_robots())) {}

std::string DrawingIntake::Problem(const std::string& channel, const drawing_t& drawing) const {
  const std::optional<int> id = lcm::RobotIdFromChannel(channel, lcm::kDrawChannelPrefix);
  if (drawing.run_id != run_id_) return "drawing of another run " + lcm::RunIdText(drawing.run_id);
  if (!id || *id != drawing.robot_id || *id >= world_.num_robots()) {
    return "drawing of robot " + std::to_string(drawing.robot_id) + " does not match its channel or this run's " +
           std::to_string(world_.num_robots()) + " robots";
  }
  if (drawing.step < 0 || drawing.step > world_.step()) {
    return "drawing of step " + std::to_string(drawing.step) + " but the world is at step " +
           std::to_string(world_.step());
  }
  if (std::string problem = lcm::DrawingShapes::Problem(drawing); !problem.empty()) return "drawing: " + problem;
  return "";
}

Heard DrawingIntake::Take(const std::string& channel, const void* data, int size) {
  drawing_t drawing;
  if (std::optional<std::string> wrong = lcm::DecodeProblem(data, size, &drawing)) {
    bad_messages_.Report(channel, "cannot decode " + std::to_string(size) + " bytes as drawing_t: " + *wrong,
                         lcm::WireLayoutOf<drawing_t>().AgentIdOf(data, size));
    return Heard::kRefused;
  }
  std::string problem = Problem(channel, drawing);
  if (problem.empty()) {
    RobotDrawings& robot = robots_[static_cast<size_t>(drawing.robot_id)];  // Problem() checked the id
    const size_t hash = std::hash<std::string_view>{}(std::string_view(static_cast<const char*>(data), size));
    if (robot.world_step != world_.step()) {
      robot.world_step = world_.step();
      robot.drawings = 0;
    } else if (hash == robot.hash) {
      return Heard::kRepeat;  // the agent's resend with the world's resent step
    }
    if (robot.drawings < kMaxPerRobotPerStep) {
      ++robot.drawings;
      robot.hash = hash;
      return Heard::kUsed;
    }
    problem = "more than " + std::to_string(kMaxPerRobotPerStep) + " different drawings from robot " +
              std::to_string(drawing.robot_id) + " at step " + std::to_string(world_.step()) + " (a flood)";
  }
  bad_messages_.Report(channel, problem, drawing.agent_id);
  return Heard::kRefused;
}

}  // namespace dream::node
