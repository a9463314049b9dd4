#include "dream/node/radio_intake.h"

#include <functional>
#include <optional>
#include <string_view>

#include "dream/lcm/channels.h"
#include "dream/lcm/run_id.h"
#include "dream/radio_message_t.hpp"

namespace dream::node {

RadioIntake::RadioIntake(const world::World& world, int64_t run_id, lcm::BadMessageLog& bad_messages)
    : world_(world), run_id_(run_id), bad_messages_(bad_messages), robots_(static_cast<size_t>(world.num_robots())) {}

std::string RadioIntake::Problem(const std::string& channel, const radio_message_t& radio) const {
  const std::optional<int> id = lcm::RobotIdFromChannel(channel, lcm::kRadioChannelPrefix);
  if (radio.run_id != run_id_) return "radio of another run " + lcm::RunIdText(radio.run_id);
  if (!id || *id != radio.sender_id || *id >= world_.num_robots()) {
    return "radio from robot " + std::to_string(radio.sender_id) + " does not match its channel or this run's " +
           std::to_string(world_.num_robots()) + " robots";
  }
  if (radio.step < 0 || radio.step > world_.step()) {
    return "radio sent at step " + std::to_string(radio.step) + " but the world is at step " +
           std::to_string(world_.step());
  }
  return "";
}

Heard RadioIntake::Take(const std::string& channel, const radio_message_t& radio, const void* data, int size) {
  std::string problem = Problem(channel, radio);
  if (problem.empty()) {
    // Problem() checked that sender_id is the channel's robot, and one of this run's.
    const int id = radio.sender_id;
    RobotRadio& robot = robots_[static_cast<size_t>(id)];
    const size_t hash = std::hash<std::string_view>{}(std::string_view(static_cast<const char*>(data), size));
    if (robot.world_step != world_.step()) {
      robot.world_step = world_.step();
      robot.messages = 0;
    } else if (hash == robot.hash) {
      return Heard::kRepeat;  // the agent's resend with the world's resent step
    }
    if (robot.messages < kMaxPerRobotPerStep) {
      ++robot.messages;
      robot.hash = hash;
      return Heard::kUsed;
    }
    problem = "more than " + std::to_string(kMaxPerRobotPerStep) + " different radio messages from robot " +
              std::to_string(id) + " at step " + std::to_string(world_.step()) + " (a flood)";
  }
  bad_messages_.Report(channel, problem, radio.agent_id);
  return Heard::kRefused;
}

}  // namespace dream::node
