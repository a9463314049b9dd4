#include "dream/lcm/command_batch.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "dream/robot_commands_t.hpp"
#include "dream/velocity_command_t.hpp"

namespace dream::lcm {

CommandBatch::CommandBatch(const robot_commands_t& commands, int num_robots)
    : commands_(commands), problem_(ProblemOf(commands, num_robots)) {
  if (!problem_) size_ = commands.robot_id.size();
}

std::optional<std::string> CommandBatch::ProblemOf(const robot_commands_t& commands, int num_robots) {
  const auto entries = static_cast<size_t>(std::max(commands.num_commands, 0));
  if (commands.robot_id.size() != entries || commands.v.size() != entries || commands.w.size() != entries ||
      commands.done.size() != entries) {
    return "its arrays do not hold num_commands = " + std::to_string(commands.num_commands) + " entries";
  }
  // lcm::Decode refuses a negative count; a message built in memory may still carry one.
  if (commands.num_commands < 0) return "num_commands = " + std::to_string(commands.num_commands) + " is negative";
  if (commands.num_commands > num_robots) {
    return std::to_string(commands.num_commands) + " commands, but this run has " + std::to_string(num_robots) +
           " robots";
  }
  // At most the run's robots from here: the copy is bounded.
  std::vector<int32_t> ids = commands.robot_id;
  std::sort(ids.begin(), ids.end());
  const auto twice = std::adjacent_find(ids.begin(), ids.end());
  if (twice != ids.end()) return "robot " + std::to_string(*twice) + " is listed twice";
  return std::nullopt;
}

velocity_command_t CommandBatch::Entry(size_t i) const {
  velocity_command_t command;
  command.utime = commands_.utime;
  command.step = commands_.step;
  command.run_id = commands_.run_id;
  command.agent_id = commands_.agent_id;
  command.robot_id = commands_.robot_id.at(i);
  command.v = commands_.v.at(i);
  command.w = commands_.w.at(i);
  command.done = commands_.done.at(i);
  return command;
}

}  // namespace dream::lcm
