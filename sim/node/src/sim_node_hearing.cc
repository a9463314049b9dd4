// SimNode's hearing: every message heard, dispatched by channel to its
// intake, then recorded (used) or kept apart (refused).
#include <spdlog/spdlog.h>

#include <optional>
#include <string>

#include "decode_or_report.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/run_id.h"
#include "dream/node/refused_record.h"
#include "dream/node/sim_node.h"
#include "dream/radio_message_t.hpp"
#include "dream/robot_busy_t.hpp"
#include "dream/robot_commands_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/velocity_command_t.hpp"

namespace dream::node {

void SimNode::OnMessage(const std::string& channel, const void* data, int size) {
  // The world's own channels are recorded once, when published (another
  // world's show on its status); udpm's start-up self test is transport
  // noise, not part of the run.
  if (channel == lcm::kPosesChannel || channel == lcm::kObstaclesChannel || channel == "LCM_SELF_TEST") return;
  if (channel == lcm::kStatusChannel) {
    // Our own statuses come back too (memq, udpm loopback); another run id is a second world.
    run_status_t status;
    if (DecodeOrReport(bad_messages_, channel, data, size, &status)) OnStatus(channel, status);
    return;
  }
  if (channel == lcm::kCommandsChannel) {
    HearCommands(channel, data, size);
    return;
  }
  Keep(channel, Hear(channel, data, size), data, size);
}

void SimNode::Keep(const std::string& channel, Heard heard, const void* data, int size) {
  switch (heard) {
    case Heard::kUsed:
      Record(channel, data, size);
      break;
    case Heard::kRefused:
      if (refused_ != nullptr) refused_->Add(channel, world_.step(), SimUtime(), data, size);
      break;
    case Heard::kRepeat:
      break;
  }
}

void SimNode::HearCommands(const std::string& channel, const void* data, int size) {
  robot_commands_t commands;
  // Each entry is kept as the DREAM_CMD_<id> message it stands for, so the
  // run's log is the same whichever way its commands were sent.
  const auto keep_entry = [this](const std::string& entry_channel, const velocity_command_t& command, Heard heard) {
    if (heard == Heard::kRepeat) return;
    const int entry_size = command.getEncodedSize();
    entry_encoded_.resize(static_cast<size_t>(entry_size));
    command.encode(entry_encoded_.data(), 0, entry_size);
    Keep(entry_channel, heard, entry_encoded_.data(), entry_size);
  };
  if (!DecodeOrReport(bad_messages_, channel, data, size, &commands) ||
      commands_.TakeAll(channel, commands, keep_entry) == Heard::kRefused) {
    Keep(channel, Heard::kRefused, data, size);
  }
}

Heard SimNode::Hear(const std::string& channel, const void* data, int size) {
  if (channel.rfind(lcm::kCommandChannelPrefix, 0) == 0) {
    velocity_command_t command;
    if (!DecodeOrReport(bad_messages_, channel, data, size, &command)) return Heard::kRefused;
    return commands_.Take(channel, command);
  }
  if (channel.rfind(lcm::kFaultChannelPrefix, 0) == 0) {
    robot_fault_t fault;
    if (!DecodeOrReport(bad_messages_, channel, data, size, &fault)) return Heard::kRefused;
    return OnFault(channel, fault);
  }
  if (channel.rfind(lcm::kBusyChannelPrefix, 0) == 0) {
    robot_busy_t busy;
    if (!DecodeOrReport(bad_messages_, channel, data, size, &busy)) return Heard::kRefused;
    return busy_.Take(channel, busy);
  }
  if (channel.rfind(lcm::kRadioChannelPrefix, 0) == 0) {
    radio_message_t radio;
    if (!DecodeOrReport(bad_messages_, channel, data, size, &radio)) return Heard::kRefused;
    return radio_.Take(channel, radio, data, size);
  }
  if (channel.rfind(lcm::kDrawChannelPrefix, 0) == 0) return drawings_.Take(channel, data, size);
  // DREAM_APPLIED and DREAM_MEASURED_POSES are the world's own records, never
  // sent: one heard is forged; any other name is not part of a run.
  bad_messages_.Report(channel,
                       "not a channel agents send on (DREAM_CMD_<id>, DREAM_CMDS, DREAM_RADIO_<id>, DREAM_FAULT_<id>, "
                       "DREAM_DRAW_<id>, DREAM_BUSY_<id>): refused, kept out of the run log");
  return Heard::kRefused;
}

void SimNode::NoteOtherWorld(int64_t run_id, const std::string& seen_on) {
  // 0 is "no run" (a message made without one), not a world.
  if (run_id == 0 || run_id == run_id_ || other_worlds_.size() >= kMaxOtherWorlds ||
      !other_worlds_.insert(run_id).second)
    return;
  spdlog::error(
      "another world (run {}) is on this LCM URL ({}; seen on {}) beside this one (run {}): two simulators "
      "share the URL and agents may answer either. Stop one, or give each run its own URL",
      lcm::RunIdText(run_id), lcm_.url(), seen_on, lcm::RunIdText(run_id_));
}

void SimNode::OnStatus(const std::string& /*channel*/, const run_status_t& status) {
  if (status.run_id != run_id_) NoteOtherWorld(status.run_id, lcm::kStatusChannel);
}

Heard SimNode::OnFault(const std::string& channel, const robot_fault_t& fault) {
  if (fault.run_id != run_id_) {
    NoteOtherWorld(fault.run_id, channel);
    bad_messages_.Report(channel, "robot fault of another run " + lcm::RunIdText(fault.run_id), fault.agent_id);
    return Heard::kRefused;
  }
  const std::optional<int> id = lcm::RobotIdFromChannel(channel, lcm::kFaultChannelPrefix);
  if (!id || *id != fault.robot_id || *id >= world_.num_robots()) {
    bad_messages_.Report(
        channel,
        "robot fault for robot " + std::to_string(fault.robot_id) + " does not match its channel or this run's robots",
        fault.agent_id);
    return Heard::kRefused;
  }
  RobotSlot& robot = robots_[static_cast<size_t>(*id)];
  // Only the agent driving the robot may give it up.
  if (robot.owned && robot.owner_agent_id != fault.agent_id) {
    bad_messages_.Report(channel,
                         "robot fault from agent " + std::to_string(fault.agent_id) + ", which does not drive robot " +
                             std::to_string(*id),
                         fault.agent_id);
    return Heard::kRefused;
  }
  if (robot_faults_.count(*id) != 0) return Heard::kRepeat;  // said once is enough
  const std::string& detail = fault.detail;  // at most MessageLimits::kDetailBytes, checked by lcm::Decode
  robot_faults_[*id] = "step " + std::to_string(world_.step()) + ": " + detail;
  robot.lost = true;
  robots_ever_lost_.insert(*id);
  world_.StopRobot(*id);
  spdlog::error("robot {} lost at step {}: its controller failed: {}; it stops, the run goes on", *id, world_.step(),
                detail);
  return Heard::kUsed;
}

}  // namespace dream::node
